// `subdiv interpolate` end to end: the written control mesh is checked with the papers'
// formulas (computed here), the refined output carries the residuals, bad input is refused
// with nothing written.
#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include "framework/io/mesh_read.h"
#include "interp_reference.h"
#include "support/cli_runner.h"
#include "support/vtk_read.h"

using namespace subdiv;
using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

const std::string kCross = source_path("examples/meshes/cross.obj");
const std::string kTwoStep = "--scheme catmull-clark-shape:1,catmull-clark";

Level level_of(const MeshData& d) { return build_level(d.vertex_count(), d.face_offsets, d.face_vertices); }

void check_refused(const std::string& args, const fs::path& dir, const std::string& message, bool refine = true,
                   const std::string& extension = "obj") {
  const fs::path out = dir / ("out." + extension), refined = dir / "out.pvd";
  const CliResult r =
      run_subdiv("interpolate " + args + " -o " + out.string() + (refine ? " --refined " + refined.string() : ""));
  CHECK(r.exit_code != 0);
  CHECK_MESSAGE(r.output.find(message) != std::string::npos, r.output);
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(fs::exists(refined));
  CHECK_FALSE(fs::exists(dir / "out_levels"));
}

}  // namespace

TEST_CASE("interpolate: Lin et al. 2015's local method on the cross; the written mesh's limits pass through the chosen vertices") {
  const auto dir = fresh_dir("interp-cli-local");
  const fs::path out = dir / "cross.obj", refined = dir / "cross.pvd";
  const CliResult r = run_subdiv("interpolate " + kCross + " " + kTwoStep + " --lambda 0.5 --select 0,5,10,20,33 -v -o " +
                                 out.string() + " --refined " + refined.string() + " --levels 2");
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const MeshData in = read_mesh(kCross), got = read_mesh(out);
  const Level L = level_of(in);
  REQUIRE(got.vertex_count() == in.vertex_count());
  CHECK(got.face_vertices == in.face_vertices);
  const std::set<Index> chosen{0, 5, 10, 20, 33};
  const double tol = 1e-10 * std::sqrt(5 * 5 + 5 * 5 + 1);  // the default: 1e-10 x bounding-box diagonal
  for (Index v = 0; v < L.vertex_count; ++v) {
    if (chosen.count(v)) {
      CHECK(dist(two_step_limit_point(L, got.positions, v, 0.5), at(in.positions, v)) < tol * 1.001);
    } else {
      CHECK(at(got.positions, v) == at(in.positions, v));
    }
  }
  // Per-point arrays at every level; at the finest, the chosen vertices' points and residuals.
  for (int l = 0; l <= 2; ++l) {
    const auto poly = read_vtp(dir / "cross_levels" / ("level_" + std::to_string(l) + ".vtp"));
    auto* base = poly->GetPointData()->GetArray("base_vertex");
    auto* role = poly->GetPointData()->GetArray("interpolated");
    auto* residual = poly->GetPointData()->GetArray("limit_residual");
    auto* distance = poly->GetPointData()->GetArray("target_distance");
    REQUIRE((base && role && residual && distance));
    int moving = 0;
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
      const double b = base->GetTuple1(i);
      if (b < 0) {
        CHECK(role->GetTuple1(i) == -1);
        continue;
      }
      const bool is_chosen = chosen.count(Index(b)) != 0;
      CHECK(role->GetTuple1(i) == (is_chosen ? 1 : 0));
      if (is_chosen) {
        ++moving;
        CHECK(residual->GetTuple1(i) < tol * 1.001);
      }
      double p[3];
      poly->GetPoint(i, p);
      CHECK(distance->GetTuple1(i) == doctest::Approx(dist({p[0], p[1], p[2]}, at(in.positions, Index(b)))));
    }
    CHECK(moving == 5);
  }
}

TEST_CASE("interpolate: Chen et al.'s global method on plain Catmull-Clark, and lambda per vertex from a file") {
  const auto dir = fresh_dir("interp-cli-global");
  const std::string torus = source_path("examples/meshes/torus-quads.obj");
  const fs::path out = dir / "torus.obj";
  CliResult r = run_subdiv("interpolate " + torus + " --scheme catmull-clark --tol 1e-11 -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const MeshData in = read_mesh(torus);
  const Level L = level_of(in);
  MeshData got = read_mesh(out);
  for (Index v = 0; v < L.vertex_count; ++v) CHECK(dist(cc_limit_point(L, got.positions, v), at(in.positions, v)) < 1.1e-11);

  std::ofstream lambda(dir / "lambda.txt");
  lambda << "# one lambda per vertex\n";
  for (Index v = 0; v < L.vertex_count; ++v) lambda << (v % 2 ? "0.4" : "0.9") << "\n";
  lambda.close();
  r = run_subdiv("interpolate " + torus + " " + kTwoStep + " --lambda " + (dir / "lambda.txt").string() +
                 " --tol 1e-11 -o " + out.string() + " --refined " + (dir / "torus.pvd").string() + " --levels 5");
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  got = read_mesh(out);
  for (Index v = 0; v < L.vertex_count; ++v)
    CHECK(dist(two_step_limit_point(L, got.positions, v, v % 2 ? 0.4 : 0.9), at(in.positions, v)) < 1.1e-11);
  // The refined output uses the same per-vertex first step: the base vertices' points close
  // in on their targets level by level (Catmull-Clark's vertex points converge like 1/4^l).
  double previous = 1e9;
  for (int l = 1; l <= 5; ++l) {
    const auto poly = read_vtp(dir / "torus_levels" / ("level_" + std::to_string(l) + ".vtp"));
    auto* distance = poly->GetPointData()->GetArray("target_distance");
    auto* base = poly->GetPointData()->GetArray("base_vertex");
    double worst = 0;
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
      if (base->GetTuple1(i) >= 0) worst = std::max(worst, distance->GetTuple1(i));
    CHECK(worst < previous / 3);
    previous = worst;
  }
  CHECK(previous < 1e-3);
}

TEST_CASE("interpolate: bad input is refused, nothing is written") {
  const auto dir = fresh_dir("interp-cli-errors");
  check_refused(kCross + " " + kTwoStep + " --lambda 0.35", dir, "lambda = 0.35 is outside its range (0.35, 1]");
  check_refused(kCross + " " + kTwoStep + " --lambda 1.5", dir, "lambda = 1.5 is outside its range (0.35, 1]");
  check_refused(kCross + " --scheme catmull-clark --lambda 0.5", dir, "no scheme in 'catmull-clark' has a parameter lambda");
  check_refused(kCross + " --select 0,3,40", dir, "vertex 40 does not exist; the mesh has 40 vertices");
  check_refused(kCross + " --select " + (dir / "missing.txt").string(), dir, "no such file");
  std::ofstream(dir / "ids.txt") << "1\n2\n# then\n7 123\n";
  check_refused(kCross + " --select " + (dir / "ids.txt").string(), dir, "ids.txt line 4: vertex 123 does not exist");
  // Per-vertex values (the cross has 40 vertices): a value out of range names its vertex, a
  // word that is not a number its line, a wrong count the count.
  auto lambda_file = [&](const std::string& name, const std::string& second, int count) {
    std::ofstream f(dir / name);
    f << "0.5\n" << second << "\n";
    for (int v = 2; v < count; ++v) f << "0.5\n";
    return (dir / name).string();
  };
  check_refused(kCross + " " + kTwoStep + " --lambda " + lambda_file("range.txt", "0.2", 40), dir,
                "per-vertex parameter 'lambda' (vertex 1): lambda = 0.2 is outside its range (0.35, 1]");
  check_refused(kCross + " " + kTwoStep + " --lambda " + lambda_file("word.txt", "0.5x", 40), dir,
                "word.txt line 2: '0.5x' is not a finite number");
  check_refused(kCross + " " + kTwoStep + " --lambda " + lambda_file("count.txt", "0.5", 39), dir,
                "39 values of 'lambda' for a mesh of 40 vertices");
  check_refused(kCross + " " + kTwoStep + " --vertex-param beta=" + lambda_file("beta.txt", "0.5", 40), dir,
                "per-vertex parameter 'beta': no scheme of the run reads it per vertex");
  // Mid-edge makes no point at a vertex, so its boundary corners do not stay.
  check_refused(source_path("examples/meshes/plane-with-hole.obj") + " --scheme mid-edge", dir,
                "vertex 0 is a corner");
  // v' = 2 v - mean(ring) over bilinear edge points diverges: no eigenvector of 1 dominates.
  std::ofstream(dir / "divergent.json") << R"json({"name": "divergent", "split": "quad", "faces": "any",
    "curve": "cubic-bspline", "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
    "edge": [{"sum": "ends", "w": "1/2"}], "vertex": [{"at": "self", "w": "2"}, {"sum": "ring", "w": "-1/n"}]}})json";
  check_refused(kCross + " --scheme " + (dir / "divergent.json").string(), dir, "scheme 'divergent' has no limit mask");
  check_refused(source_path("examples/meshes/cube.obj") + " --scheme loop", dir, "triangles");
  check_refused(kCross + " --scheme cubic-bspline", dir, "a curve scheme refines polylines only");
  check_refused(kCross + " --scheme chaikin:1,cubic-bspline", dir, "'chaikin' is a curve scheme inside a sequence");
  check_refused(source_path("examples/curves/circle8.obj"), dir, "has no faces (it has 1 polyline)");
  check_refused(source_path("examples/curves/circle8.obj") + " --scheme cubic-bspline --lambda 0.5", dir,
                "Lin et al. 2015's shape parameter is for surfaces");
  check_refused(source_path("examples/curves/open-zigzag.obj") + " --scheme cubic-bspline", dir, "hold no polylines",
                false, "off");
  check_refused(source_path("examples/curves/circle8.obj") + " --scheme tension-bspline", dir, "stationary");
  check_refused(kCross + " --refined " + (dir / "x.obj").string(), dir, "use .pvd", false);
  CHECK_FALSE(fs::exists(dir / "x.obj"));
}

TEST_CASE("interpolate: polylines with a curve scheme; the written points' limits are the targets") {
  const auto dir = fresh_dir("interp-cli-curves");
  for (const char* file : {"examples/curves/circle8.obj", "examples/curves/open-zigzag.obj"}) {
    CAPTURE(file);
    const fs::path out = dir / "curve.obj", refined = dir / "curve.pvd";
    const CliResult r = run_subdiv("interpolate " + source_path(file) + " --scheme cubic-bspline --tol 1e-12 -o " +
                                   out.string() + " --refined " + refined.string() + " --levels 2");
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    CHECK(r.output.find("converged") != std::string::npos);
    const MeshData in = read_mesh(source_path(file)), got = read_mesh(out);
    REQUIRE(got.vertex_count() == in.vertex_count());
    CHECK(got.line_count() == in.line_count());
    // The cubic B-spline's limit point (P_{j-1} + 4 P_j + P_{j+1}) / 6 of the written
    // points, computed here, is the input point (open ends: the end point itself).
    const auto& lines = got.line_offsets;
    for (size_t l = 0; l + 1 < lines.size(); ++l) {
      const Index first = lines[l], last = lines[l + 1];
      const bool closed = got.line_vertices[size_t(first)] == got.line_vertices[size_t(last - 1)];
      const Index n = last - first - (closed ? 1 : 0);
      for (Index j = 0; j < n; ++j) {
        const Index v = got.line_vertices[size_t(first + j)];
        std::array<double, 3> limit = at(got.positions, v);
        if (closed || (j > 0 && j + 1 < n)) {
          const Index prev = got.line_vertices[size_t(first + (j + n - 1) % n)];
          const Index next = got.line_vertices[size_t(first + (j + 1) % n)];
          for (int c = 0; c < 3; ++c)
            limit[c] = (got.positions[3 * prev + c] + 4 * got.positions[3 * v + c] + got.positions[3 * next + c]) / 6;
        }
        CHECK(dist(limit, at(in.positions, v)) < 1e-11);
      }
    }
    CHECK(fs::exists(refined));
  }
}
