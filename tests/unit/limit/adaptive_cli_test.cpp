// subdiv refine --adaptive L: a closed, watertight mesh with the cell arrays, its summary
// line, and bad combinations refused with a message and no output file.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "support/cli_runner.h"
#include "support/mesh_data_of.h"
#include "unit/limit/non_manifold_meshes.h"

using namespace subdiv;
namespace fs = std::filesystem;

TEST_CASE("subdiv refine --adaptive writes a watertight mesh with face_level and base_face") {
  const fs::path dir = test::fresh_dir("refine-cli-adaptive");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  const auto r = test::run_subdiv("refine " + mesh + " --adaptive 5 -o " + (dir / "a.vtp").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  // 96 + 72 (L - 2) faces on a cube (8 valence-3 vertices, 3 faces each split per level).
  CHECK(r.output.find("312 faces") != std::string::npos);
  CHECK(r.output.find("uniform level 5: 6144 faces") != std::string::npos);
  const MeshData m = read_mesh((dir / "a.vtp").string());
  const Level L = level_from_mesh(m, "a.vtp");
  int open = 0;
  for (Index e = 0; e < L.edge_count(); ++e) open += L.edge_face_count(e) != 2;
  CHECK(open == 0);
  CHECK(L.vertex_count - L.edge_count() + L.face_count() == 2);
  // face_level comes back; base_face is one of SubdivKit's own arrays, which the reader leaves out.
  int max_level = -1;
  for (const DataArray& a : m.cell_data)
    if (a.name == "face_level")
      for (double l : a.values) max_level = std::max(max_level, int(l));
  CHECK(max_level == 5);
}

TEST_CASE("subdiv refine --adaptive refuses what it cannot do, leaving no file") {
  const fs::path dir = test::fresh_dir("refine-cli-adaptive-bad");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  const std::string out = (dir / "x.obj").string();
  const char* bad[][2] = {
      {"--adaptive 3 -l 2", "ask for two finest levels"},
      {"--adaptive 3 --tolerance -1", "--tolerance -1"},
      {"--adaptive 3 -s doo-sabin", "binary quad and triangle splits"},
      {"--adaptive 3 -s catmull-clark:1,loop", "sequence"},
      {"--adaptive 3 --pieces 2", "--pieces"},
  };
  for (const auto& b : bad) {
    CAPTURE(b[0]);
    const auto r = test::run_subdiv("refine " + mesh + " " + b[0] + " -o " + out);
    CHECK(r.exit_code != 0);
    CHECK(r.output.find(b[1]) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
  const auto pvd = test::run_subdiv("refine " + mesh + " --adaptive 2 -o " + (dir / "x.pvd").string());
  CHECK(pvd.exit_code != 0);
  CHECK(pvd.output.find("one mesh") != std::string::npos);
}

TEST_CASE("subdiv refine --adaptive carries the mesh's point arrays, placed like the positions") {
  const fs::path dir = test::fresh_dir("refine-cli-adaptive-arrays");
  MeshData m = read_mesh(test::source_path("examples/meshes/cube.obj"));
  DataArray height{"height", 1, {}, false};  // an affine function of the positions: 2z - x
  for (size_t v = 0; v < m.positions.size() / 3; ++v) height.values.push_back(2 * m.positions[3 * v + 2] - m.positions[3 * v]);
  m.point_data.push_back(height);
  write_mesh(dir / "cube.vtp", m);
  for (const char* limit : {"", " --limit"}) {
    CAPTURE(std::string(limit));
    const auto r = test::run_subdiv("refine " + (dir / "cube.vtp").string() + " --adaptive 3" + limit + " -o " +
                                    (dir / "out.vtp").string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const MeshData out = read_mesh((dir / "out.vtp").string());
    const DataArray* h = nullptr;
    for (const DataArray& a : out.point_data)
      if (a.name == "height") h = &a;
    REQUIRE(h != nullptr);
    REQUIRE(h->values.size() == out.positions.size() / 3);
    double worst = 0;
    for (size_t v = 0; v < h->values.size(); ++v)
      worst = std::max(worst, std::fabs(h->values[v] - (2 * out.positions[3 * v + 2] - out.positions[3 * v])));
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("subdiv refine --adaptive --transitions triangles: triangles and quads, the same points, watertight") {
  const fs::path dir = test::fresh_dir("refine-cli-adaptive-transitions");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  const std::string polygons = (dir / "p.vtp").string(), triangles = (dir / "t.vtp").string(),
                    evaluated = (dir / "e.vtp").string();
  const auto p = test::run_subdiv("refine " + mesh + " --adaptive 4 --limit -o " + polygons);
  REQUIRE_MESSAGE(p.exit_code == 0, p.output);
  const auto t = test::run_subdiv("refine " + mesh + " --adaptive 4 --limit --transitions triangles -o " + triangles);
  REQUIRE_MESSAGE(t.exit_code == 0, t.output);
  const auto e = test::run_subdiv("evaluate " + mesh + " --adaptive 4 --limit --transitions triangles -o " + evaluated);
  REQUIRE_MESSAGE(e.exit_code == 0, e.output);
  const MeshData P = read_mesh(polygons), T = read_mesh(triangles), E = read_mesh(evaluated);
  CHECK(T.positions == P.positions);  // the same vertices, in the same order
  CHECK(E.positions == T.positions);
  CHECK(E.face_vertices == T.face_vertices);
  int big = 0, bigger = 0;
  for (size_t f = 0; f + 1 < T.face_offsets.size(); ++f) big += T.face_offsets[f + 1] - T.face_offsets[f] > 4;
  for (size_t f = 0; f + 1 < P.face_offsets.size(); ++f) bigger += P.face_offsets[f + 1] - P.face_offsets[f] > 4;
  CHECK(big == 0);
  CHECK(bigger > 0);  // the polygon output has transition polygons
  const Level L = level_from_mesh(T, "t.vtp");
  int open = 0;
  for (Index f = 0; f < L.edge_count(); ++f) open += L.edge_face_count(f) != 2;
  CHECK(open == 0);
  CHECK(L.vertex_count - L.edge_count() + L.face_count() == 2);
  const char* bad[][2] = {
      {"refine MESH --adaptive 3 --transitions quads", "--transitions"},
      {"refine MESH --transitions triangles", "--transitions goes with --adaptive"},
      {"evaluate MESH --samples 2 --transitions triangles", "--transitions goes with --adaptive"},
  };
  for (const auto& b : bad) {
    CAPTURE(b[0]);
    std::string command = b[0];
    command.replace(command.find("MESH"), 4, mesh);
    const std::string out = (dir / "x.vtp").string();
    const auto r = test::run_subdiv(command + " -o " + out);
    CHECK(r.exit_code != 0);
    CHECK(r.output.find(b[1]) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
}

TEST_CASE("subdiv refine --adaptive --limit refines a non-manifold mesh: three flaps on a hinge, welded") {
  // Three flaps on a hinge of two edges (tests/unit/limit/non_manifold_meshes.h): the hinge is
  // isolated to level 3 in every flap, so its 2 x 8 segments have the three flaps' faces each,
  // every other edge one or two; three discs glued along a path: Euler characteristic 1.
  const fs::path dir = test::fresh_dir("refine-cli-adaptive-flaps");
  write_mesh(dir / "flaps.obj", test::mesh_data(non_manifold_test::book(3, 2)));
  const std::string out = (dir / "x.vtp").string();
  for (const char* transitions : {"", " --transitions triangles"}) {
    CAPTURE(std::string(transitions));
    const auto r = test::run_subdiv("refine " + (dir / "flaps.obj").string() + " --adaptive 3 --limit" + transitions +
                                    " -o " + out);
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const MeshData m = read_mesh(out);
    const Level L = level_from_mesh(m, "x.vtp");
    int hinge = 0, other = 0;
    for (Index e = 0; e < L.edge_count(); ++e) {
      hinge += L.edge_face_count(e) == 3;
      other += L.edge_face_count(e) != 3 && L.edge_face_count(e) != 1 && L.edge_face_count(e) != 2;
    }
    CHECK(hinge == 16);
    CHECK(other == 0);
    CHECK(L.vertex_count - L.edge_count() + L.face_count() == 1);
    CHECK(L.face_count() < 3 * 4 * 64);  // uniform level 3: 768 faces
  }
}
