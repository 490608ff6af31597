// `subdiv evaluate`: the written points are the library's, bad rows are refused with their
// row number, and no output file is left behind on an error.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme_registry.h"
#include "support/cli_runner.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::vector<std::vector<double>> read_csv(const fs::path& p, std::string& header) {
  std::ifstream in(p);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, ',');) row.push_back(std::stod(f));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST_CASE("subdiv evaluate writes the limit points and derivatives of the library") {
  const fs::path dir = test::fresh_dir("evaluate-cli");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  write(dir / "points.csv", "face,u,v\n0,0.3,0.2\n4,0.5,0.125\n5,1e-300,0.5\n");
  const auto r = test::run_subdiv("evaluate " + mesh + " --at " + (dir / "points.csv").string() + " -o " +
                                  (dir / "out.csv").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  std::string header;
  const auto rows = read_csv(dir / "out.csv", header);
  CHECK(header == "face,u,v,x,y,z,du_x,du_y,du_z,dv_x,dv_y,dv_z");
  REQUIRE(rows.size() == 3);
  const MeshData m = read_mesh(mesh);
  const LimitSurface s(load_scheme("catmull-clark"), level_from_mesh(m, mesh));
  for (const auto& row : rows) {
    const LimitSample p = s.evaluate(Index(row[0]), row[1], row[2], m.positions, 3);
    for (int c = 0; c < 3; ++c) {
      CHECK(row[size_t(3 + c)] == p.position[size_t(c)]);  // written in the shortest exact form
      CHECK(row[size_t(6 + c)] == p.du[size_t(c)]);
      CHECK(row[size_t(9 + c)] == p.dv[size_t(c)]);
    }
  }
}

TEST_CASE("subdiv evaluate --derivatives 2 adds the second derivatives, nan at an extraordinary vertex") {
  const fs::path dir = test::fresh_dir("evaluate-cli-second");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  write(dir / "points.csv", "face,u,v\n0,0.3,0.2\n2,0.01,0.004\n0,0,0\n");
  const auto r = test::run_subdiv("evaluate " + mesh + " --at " + (dir / "points.csv").string() +
                                  " --derivatives 2 -o " + (dir / "out.csv").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  std::string header;
  const auto rows = read_csv(dir / "out.csv", header);
  CHECK(header == "face,u,v,x,y,z,du_x,du_y,du_z,dv_x,dv_y,dv_z,duu_x,duu_y,duu_z,duv_x,duv_y,duv_z,dvv_x,dvv_y,dvv_z");
  REQUIRE(rows.size() == 3);
  const MeshData m = read_mesh(mesh);
  const LimitSurface s(load_scheme("catmull-clark"), level_from_mesh(m, mesh));
  for (const auto& row : rows) {
    REQUIRE(row.size() == 21);
    const LimitSample p = s.evaluate(Index(row[0]), row[1], row[2], m.positions, 3, 2);
    for (int c = 0; c < 3; ++c) {
      if (!p.has_second_derivatives) {
        CHECK(std::isnan(row[size_t(12 + c)]));
        continue;
      }
      CHECK(row[size_t(12 + c)] == p.duu[size_t(c)]);
      CHECK(row[size_t(15 + c)] == p.duv[size_t(c)]);
      CHECK(row[size_t(18 + c)] == p.dvv[size_t(c)]);
    }
  }
  CHECK(std::isnan(rows[2][12]));  // (0, 0) of face 0 is a valence-3 vertex
  CHECK(!std::isnan(rows[1][12]));
}

TEST_CASE("subdiv evaluate -s mid-edge --derivatives 2: the library's numbers, nan on a knot line and at an "
          "extraordinary point") {
  const fs::path dir = test::fresh_dir("evaluate-cli-mid-edge-second");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  write(dir / "points.csv", "face,u,v\n0,0.3,0.15\n3,0.8125,0.40625\n1,0.5,0.5\n0,0.3,0.2\n2,0,0\n");
  const auto r = test::run_subdiv("evaluate " + mesh + " -s mid-edge --at " + (dir / "points.csv").string() +
                                  " --derivatives 2 -o " + (dir / "out.csv").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  std::string header;
  const auto rows = read_csv(dir / "out.csv", header);
  REQUIRE(rows.size() == 5);
  const MeshData m = read_mesh(mesh);
  const LimitSurface s(load_scheme("mid-edge"), level_from_mesh(m, mesh));
  for (size_t k = 0; k < 2; ++k) {  // inside the box spline's pieces
    REQUIRE(rows[k].size() == 21);
    const LimitSample p = s.evaluate(Index(rows[k][0]), rows[k][1], rows[k][2], m.positions, 3, 2);
    REQUIRE(p.has_second_derivatives);
    for (int c = 0; c < 3; ++c) {
      CHECK(rows[k][size_t(12 + c)] == p.duu[size_t(c)]);
      CHECK(rows[k][size_t(15 + c)] == p.duv[size_t(c)]);
      CHECK(rows[k][size_t(18 + c)] == p.dvv[size_t(c)]);
    }
  }
  // A quad's centre, where knot lines cross, and u + v = 1/2 (0.3 + 0.2 is 0.5 exactly), a knot
  // line of the halved grid where the descent ends next to the valence-3 corners: first
  // derivatives, no second; a valence-3 vertex: neither.
  for (size_t k = 2; k < 4; ++k) {
    CHECK(std::isfinite(rows[k][6]));
    CHECK(std::isnan(rows[k][12]));
  }
  CHECK(std::isnan(rows[4][6]));
  CHECK(std::isnan(rows[4][12]));
}

TEST_CASE("subdiv evaluate --adaptive writes a closed mesh with fewer faces than uniform refinement") {
  const fs::path dir = test::fresh_dir("evaluate-cli-adaptive");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  const auto r = test::run_subdiv("evaluate " + mesh + " --adaptive 4 --limit -o " + (dir / "adaptive.vtp").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const MeshData m = read_mesh((dir / "adaptive.vtp").string());
  const Level L = level_from_mesh(m, "adaptive.vtp");
  int open = 0;
  for (Index e = 0; e < L.edge_count(); ++e) open += L.edge_face_count(e) != 2;
  CHECK(open == 0);
  CHECK(L.face_count() < 6 * 256);
  const auto named = [&](const char* name) {
    for (const DataArray& a : m.cell_data)
      if (a.name == name) return true;
    return false;
  };
  CHECK(named("face_level"));
  const auto bad = test::run_subdiv("evaluate " + mesh + " --adaptive 2 --samples 2 -o " + (dir / "x.obj").string());
  CHECK(bad.exit_code != 0);
  CHECK_FALSE(fs::exists(dir / "x.obj"));
}

// --tolerance: the same request as subdiv refine --adaptive L --tolerance T (one pipeline),
// so the same mesh; on a regular torus, where no face touches a feature, only the tolerance
// splits faces, and a finer tolerance splits more of them.
TEST_CASE("subdiv evaluate --adaptive --tolerance splits what subdiv refine --adaptive --tolerance splits") {
  const fs::path dir = test::fresh_dir("evaluate-cli-tolerance");
  const std::string mesh = test::source_path("examples/meshes/torus-quads.obj");
  Index previous = 0;
  for (const std::string tolerance : {"0", "0.05", "0.01"}) {
    CAPTURE(tolerance);
    const auto e = test::run_subdiv("evaluate " + mesh + " --adaptive 2 --tolerance " + tolerance + " -o " +
                                    (dir / "e.obj").string());
    const auto r = test::run_subdiv("refine " + mesh + " --adaptive 2 --tolerance " + tolerance + " -o " +
                                    (dir / "r.obj").string());
    REQUIRE_MESSAGE(e.exit_code == 0, e.output);
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const MeshData from_evaluate = read_mesh((dir / "e.obj").string()), from_refine = read_mesh((dir / "r.obj").string());
    CHECK(from_evaluate.face_vertices == from_refine.face_vertices);
    CHECK(from_evaluate.positions == from_refine.positions);
    const Index faces = Index(from_evaluate.face_offsets.size()) - 1;
    CHECK(faces > previous);
    previous = faces;
  }
  const auto alone = test::run_subdiv("evaluate " + mesh + " --samples 2 --tolerance 0.1 -o " + (dir / "x.obj").string());
  CHECK(alone.exit_code != 0);
  CHECK(alone.output.find("--tolerance goes with --adaptive") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "x.obj"));
}

TEST_CASE("subdiv evaluate refuses bad rows with their number and leaves no output") {
  const fs::path dir = test::fresh_dir("evaluate-cli-bad");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  struct Bad {
    const char* points;
    const char* message;
  };
  for (const Bad& b : {Bad{"face,u,v\n0,0.1,0.1\n6,0.5,0.5\n", "(row 2): face 6 does not exist: the mesh has 6 faces, numbered from 0 to 5"},
                       Bad{"face,u,v\n-1,0.5,0.5\n", "(row 1): face -1 does not exist: the mesh has 6 faces, numbered from 0 to 5"},
                       Bad{"face,u,v\n0,1.5,0.5\n", "(row 1): face 0 at (u, v) = (1.5, 0.5): (u, v) is outside"},
                       Bad{"face,u,v\n0,x,0.5\n", "(row 1): u = 'x' is not a number"},
                       Bad{"face,u\n0,0.5\n", "must be 'face,u,v'"},
                       Bad{"face,u,v\n0,0.5\n", "(row 1): 2 fields"}}) {
    CAPTURE(std::string(b.points));
    write(dir / "points.csv", b.points);
    const auto r = test::run_subdiv("evaluate " + mesh + " --at " + (dir / "points.csv").string() + " -o " +
                                    (dir / "out.csv").string());
    CHECK(r.exit_code != 0);
    CHECK(r.output.find(b.message) != std::string::npos);
    CHECK(!fs::exists(dir / "out.csv"));
  }
  write(dir / "points.csv", "face,u,v\n0,0.5,0.5\n");
  const auto mid_edge = test::run_subdiv("evaluate " + test::source_path("examples/meshes/plane-with-hole.obj") +
                                         " -s mid-edge --at " + (dir / "points.csv").string() + " -o " +
                                         (dir / "out.csv").string());
  CHECK(mid_edge.exit_code != 0);
  CHECK(mid_edge.output.find("mid-edge split and the mesh has a boundary") != std::string::npos);
  CHECK(!fs::exists(dir / "out.csv"));
  // A triangle scheme on quads: refused before any point, in the words refinement uses.
  for (const std::string& how : {" --at " + (dir / "points.csv").string() + " -o " + (dir / "out.csv").string(),
                                 " --samples 2 -o " + (dir / "out.vtp").string()}) {
    const auto loop = test::run_subdiv("evaluate " + mesh + " -s loop" + how);
    CHECK(loop.exit_code != 0);
    CHECK(loop.output.find("scheme 'loop' needs triangles, but face 0 of the mesh has 4 vertices; triangulate the "
                           "mesh first") != std::string::npos);
    CHECK(!fs::exists(dir / "out.csv"));
    CHECK(!fs::exists(dir / "out.vtp"));
  }
}

TEST_CASE("subdiv evaluate --samples writes a closed mesh of the limit surface with normals") {
  const fs::path dir = test::fresh_dir("evaluate-cli-samples");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  const auto r = test::run_subdiv("evaluate " + mesh + " --samples 4 -o " + (dir / "limit.obj").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const MeshData out = read_mesh((dir / "limit.obj").string());
  CHECK(out.face_count() == 6 * 16);
  CHECK(out.vertex_count() == 8 + 12 * 3 + 6 * 9);
  const Level L = level_from_mesh(out, "limit.obj");
  for (Index e = 0; e < L.edge_count(); ++e) CHECK(!L.edge_on_boundary(e));
  // Neither --at nor --samples, both, or a mesh format for --at: refused, no file.
  for (const std::string& args : {std::string(" -o ") + (dir / "x.obj").string(),
                                 std::string(" --samples 2 --at p.csv -o ") + (dir / "x.obj").string(),
                                 std::string(" --samples 2 -o ") + (dir / "x.csv").string()}) {
    CAPTURE(args);
    const auto bad = test::run_subdiv("evaluate " + mesh + args);
    CHECK(bad.exit_code != 0);
    CHECK(!fs::exists(dir / "x.obj"));
    CHECK(!fs::exists(dir / "x.csv"));
  }
}

TEST_CASE("subdiv evaluate takes dual schemes: the written numbers are the library's, nan where no derivative exists") {
  const fs::path dir = test::fresh_dir("evaluate-cli-dual");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  write(dir / "points.csv", "face,u,v\n0,0.3,0.2\n4,0.5,0.125\n2,0,0\n");
  const auto r = test::run_subdiv("evaluate " + mesh + " -s doo-sabin --at " + (dir / "points.csv").string() +
                                  " -o " + (dir / "out.csv").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  std::string header;
  const auto rows = read_csv(dir / "out.csv", header);
  REQUIRE(rows.size() == 3);
  const MeshData m = read_mesh(mesh);
  const LimitSurface s(load_scheme("doo-sabin"), level_from_mesh(m, mesh));
  for (const auto& row : rows) {
    const LimitSample p = s.evaluate(Index(row[0]), row[1], row[2], m.positions, 3);
    for (int c = 0; c < 3; ++c) {
      CHECK(row[size_t(3 + c)] == p.position[size_t(c)]);
      if (p.has_derivatives)
        CHECK(row[size_t(6 + c)] == p.du[size_t(c)]);
      else
        CHECK(std::isnan(row[size_t(6 + c)]));
    }
  }
  CHECK(std::isnan(rows[2][6]));  // the cube's corner: a valence-3 vertex, the centre of a triangular V-face
  // A lone triangle lies between creases on all sides (a lone quad is evaluated: its bilinear quad).
  write(dir / "open.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
  const auto refused = test::run_subdiv("evaluate " + (dir / "open.obj").string() + " -s doo-sabin --at " +
                                        (dir / "points.csv").string() + " -o " + (dir / "refused.csv").string());
  CHECK(refused.exit_code != 0);
  CHECK(refused.output.find("between two creases") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "refused.csv"));
}

TEST_CASE("subdiv evaluate takes dual schemes on meshes with a boundary: the library's numbers, the boundary on "
          "the boundary curve") {
  // A 2 x 2 grid of quads: its boundary is the clamped quadratic B-spline of the boundary
  // polygon; at a corner of the mesh the limit is the corner (docs/limit.md).
  const fs::path dir = test::fresh_dir("evaluate-cli-dual-boundary");
  write(dir / "grid.obj",
        "v 0 0 0\nv 1 0 0.2\nv 2 0 0\nv 0 1 0.1\nv 1 1 0.5\nv 2 1 -0.1\nv 0 2 0\nv 1 2 0.3\nv 2 2 0\n"
        "f 1 2 5 4\nf 2 3 6 5\nf 4 5 8 7\nf 5 6 9 8\n");
  write(dir / "points.csv", "face,u,v\n0,0,0\n0,0.5,0\n1,0.25,0.6\n3,0.9,0.1\n");
  const auto r = test::run_subdiv("evaluate " + (dir / "grid.obj").string() + " -s doo-sabin --at " +
                                  (dir / "points.csv").string() + " -o " + (dir / "out.csv").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  std::string header;
  const auto rows = read_csv(dir / "out.csv", header);
  REQUIRE(rows.size() == 4);
  const MeshData m = read_mesh((dir / "grid.obj").string());
  const LimitSurface s(load_scheme("doo-sabin"), level_from_mesh(m, (dir / "grid.obj").string()));
  for (const auto& row : rows) {
    const LimitSample p = s.evaluate(Index(row[0]), row[1], row[2], m.positions, 3);
    for (int c = 0; c < 3; ++c) CHECK(row[size_t(3 + c)] == p.position[size_t(c)]);
  }
  // The corner (0, 0, 0) stays; face 0 at (1/2, 0) is the clamped spline of (0,0,0), (1,0,0.2),
  // (2,0,0) (knots 0, 0, 0, 1, 1, 1: a quadratic Bezier) at t = 1/4 of the corner's edge in
  // Greville terms, i.e. (1/4 from the corner at 0, the middle point at 1/2): B(1/2) with
  // t = 1/4: (1 - t)^2 P0 + 2 t (1 - t) P1 + t^2 P2.
  for (int c = 0; c < 3; ++c) CHECK(std::abs(rows[0][size_t(3 + c)]) < 1e-15);
  const double t = 0.25;
  const double expected[3] = {2 * t * (1 - t) * 1 + t * t * 2, 0, 2 * t * (1 - t) * 0.2};
  for (int c = 0; c < 3; ++c) CHECK(std::abs(rows[1][size_t(3 + c)] - expected[c]) < 1e-14);
}

TEST_CASE("subdiv evaluate --samples writes the face-varying UVs with their seams") {
  const fs::path dir = test::fresh_dir("evaluate-cli-samples-uv");
  const auto r = test::run_subdiv("evaluate " + test::source_path("examples/meshes/textured-tube.obj") +
                                  " --samples 4 -o " + (dir / "tube.obj").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const MeshData m = read_mesh((dir / "tube.obj").string());
  REQUIRE(m.face_varying.size() == 1);
  CHECK(m.face_varying[0].role == ArrayRole::TextureCoordinates);
  CHECK(m.face_varying[0].indices.size() == m.face_vertices.size());
  CHECK(m.face_varying[0].value_count() > m.vertex_count());  // the seam's points carry two UVs
}

TEST_CASE("subdiv evaluate --at and --samples end with a line saying what was written") {
  const fs::path dir = test::fresh_dir("evaluate-cli-summary");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  write(dir / "points.csv", "face,u,v\n0,0.3,0.2\n4,0.5,0.125\n");
  const auto at = test::run_subdiv("evaluate " + mesh + " --at " + (dir / "points.csv").string() +
                                   " --derivatives 2 -o " + (dir / "out.csv").string());
  REQUIRE_MESSAGE(at.exit_code == 0, at.output);
  CHECK_MESSAGE(at.output.find(mesh + ": limit of catmull-clark at 2 point(s), with first and second derivatives in ") !=
                    std::string::npos,
                at.output);
  CHECK(at.output.find(" s -> " + (dir / "out.csv").string() + "\n") != std::string::npos);
  // A closed mesh of 6 quads sampled 2 x 2 per face: 24 faces, and by Euler (V - E + F = 2,
  // E = 2F) 26 vertices.
  const auto samples = test::run_subdiv("evaluate " + mesh + " --samples 2 -o " + (dir / "limit.obj").string());
  REQUIRE_MESSAGE(samples.exit_code == 0, samples.output);
  CHECK_MESSAGE(samples.output.find(mesh + ": limit of catmull-clark, 2 segment(s) per face edge -> 26 vertices, 24 "
                                           "faces in ") != std::string::npos,
                samples.output);
}

TEST_CASE("subdiv evaluate --samples out of range names the option, the range and why") {
  const fs::path dir = test::fresh_dir("evaluate-cli-samples-range");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  for (const char* n : {"2000", "0", "-3"}) {
    CAPTURE(n);
    const auto r = test::run_subdiv("evaluate " + mesh + " --samples " + n + " -o " + (dir / "x.vtp").string());
    CHECK(r.exit_code == 2);  // a usage error, as CLI11's range check was
    CHECK_MESSAGE(r.output.find(std::string("--samples: ") + n + " is out of range; give 1 to 1024 segments per face "
                                                                 "edge") != std::string::npos,
                  r.output);
    CHECK(!fs::exists(dir / "x.vtp"));
  }
  const auto big = test::run_subdiv("evaluate " + mesh + " --samples 2000 -o " + (dir / "x.vtp").string());
  CHECK(big.output.find("a million points per quad face") != std::string::npos);
  CHECK(big.output.find("subdiv refine MESH -l L --limit") != std::string::npos);
}

TEST_CASE("subdiv evaluate at a vertex of valence 1000 is refused at once, not after the steps to round-off") {
  // A disc of 1000 triangles round one vertex: the analysis takes valences up to 512
  // (kMaxPatchValence). A point at the vertex needs its mask, which no refinement changes.
  const fs::path dir = test::fresh_dir("evaluate-cli-fan");
  std::ofstream obj(dir / "fan.obj");
  const int n = 1000;
  obj << "v 0 0 0\n";
  for (int i = 0; i < n; ++i) obj << "v " << std::cos(2 * M_PI * i / n) << " " << std::sin(2 * M_PI * i / n) << " 0\n";
  for (int i = 0; i < n; ++i) obj << "f 1 " << i + 2 << " " << (i + 1) % n + 2 << "\n";
  obj.close();
  write(dir / "points.csv", "face,u,v\n0,0,0\n");
  const auto r = test::run_subdiv("evaluate " + (dir / "fan.obj").string() + " --at " + (dir / "points.csv").string() +
                                  " -o " + (dir / "out.csv").string());
  CHECK(r.exit_code == 1);
  // Refused before the first step: the point is the vertex from the start.
  CHECK_MESSAGE(r.output.find("no limit mask for the vertex reached after 0 step(s): valence 1000 cannot be analysed: "
                              "valences 2..512 are") != std::string::npos,
                r.output);
  CHECK(!fs::exists(dir / "out.csv"));
}
