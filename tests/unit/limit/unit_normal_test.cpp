// The unit normal from a point's derivatives: du x dv normalised, the same at any scale of
// the coordinates (a mesh at 1e300 or 1e-300 has the normals of the unit mesh), zero where
// there is none; and the sampled limit of a scaled cube keeps the unit cube's normals.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "framework/limit/unit_normal.h"
#include "framework/pipeline/evaluate_request.h"
#include "framework/pipeline/limit_mesh.h"
#include "support/cli_runner.h"

using namespace subdiv;

TEST_CASE("unit normal: du x dv over its length, at any scale, zero without one") {
  const double du[3] = {2, 0, 0}, dv[3] = {1, 3, 0};
  const std::array<double, 3> n = unit_normal(du, dv);
  CHECK(n[0] == 0);
  CHECK(n[1] == 0);
  CHECK(n[2] == 1);
  for (double scale : {1e300, 1e-300, 1e-320}) {
    const double su[3] = {2 * scale, 0.5 * scale, -scale}, sv[3] = {scale, 3 * scale, 0.25 * scale};
    const double pu[3] = {2, 0.5, -1}, pv[3] = {1, 3, 0.25};
    const std::array<double, 3> a = unit_normal(su, sv), b = unit_normal(pu, pv);
    for (int c = 0; c < 3; ++c) CHECK(a[size_t(c)] == doctest::Approx(b[size_t(c)]).epsilon(1e-12));
    CHECK(std::hypot(a[0], a[1], a[2]) == doctest::Approx(1).epsilon(1e-15));
  }
  const double zero[3] = {0, 0, 0}, nan[3] = {std::nan(""), 0, 0};
  CHECK(unit_normal(du, du) == std::array<double, 3>{0, 0, 0});   // parallel
  CHECK(unit_normal(zero, dv) == std::array<double, 3>{0, 0, 0});
  CHECK(unit_normal(nan, dv) == std::array<double, 3>{0, 0, 0});  // no derivatives there
}

TEST_CASE("the sampled limit of a cube scaled by 1e300 has the unit cube's normals") {
  auto sampled = [](double scale) {
    EvaluateRequest r;
    r.mesh_file = test::source_path("examples/meshes/cube.obj");
    r.scheme.text = "catmull-clark";
    PreparedEvaluation p = prepare_evaluation(r);
    if (scale != 1) {
      r.mesh_file.clear();
      r.mesh = p.mesh;
      for (double& x : r.mesh.positions) x *= scale;
      p = prepare_evaluation(r);
    }
    return sampled_limit_mesh(p, 4);
  };
  const MeshData unit = sampled(1), huge = sampled(1e300);
  REQUIRE(unit.positions.size() == huge.positions.size());
  const std::vector<double>& a = unit.point_data.front().values;
  const std::vector<double>& b = huge.point_data.front().values;
  REQUIRE(unit.point_data.front().name == "Normals");
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    CHECK(std::isfinite(b[i]));
    CHECK(b[i] == doctest::Approx(a[i]).epsilon(1e-12));
  }
  for (size_t i = 0; i < unit.positions.size(); ++i)  // the cube's size is 1e300
    CHECK(std::abs(huge.positions[i] - 1e300 * unit.positions[i]) <= 1e-13 * 1e300);
}
