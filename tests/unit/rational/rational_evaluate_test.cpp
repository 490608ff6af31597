// The rational limit surface at (face, u, v) (pipeline/evaluate_request.h): the homogeneous
// limit (w·p, w) projected, with derivatives by the quotient rule. Checked against the
// rational limit positions of the vertices (SchemeLimits, another code path), against
// uniform weights (the polynomial surface), and against differences of the evaluated points.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <vector>

#include "framework/pipeline/evaluate_request.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/util/error.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

MeshData weighted_cube(const std::vector<double>& w) {
  MeshData d = test::mesh_data(test::cube());
  d.point_data.push_back({"weight", 1, w});
  return d;
}

// Weights in [0.5, 2] that differ from vertex to vertex.
std::vector<double> uneven_weights(size_t n) {
  std::vector<double> w(n);
  for (size_t v = 0; v < n; ++v) w[v] = 0.5 + 1.5 * std::fmod(0.618033988749895 * double(v + 1), 1.0);
  return w;
}

PreparedEvaluation prepared(MeshData mesh) {
  EvaluateRequest r;
  r.mesh = std::move(mesh);
  r.mesh_name = "weighted cube";
  r.scheme.text = "catmull-clark";
  return prepare_evaluation(std::move(r));
}

EvaluatedPoints at(const PreparedEvaluation& p, Index face, double u, double v, int derivatives) {
  const std::array<Index, 1> faces{face};
  const std::array<double, 2> uv{u, v};
  return evaluate_limit_points(p, faces, uv, derivatives);
}

}  // namespace

TEST_CASE("rational evaluation: uniform weights give the polynomial surface") {
  const PreparedEvaluation plain = prepared(test::mesh_data(test::cube()));
  const PreparedEvaluation twos = prepared(weighted_cube(std::vector<double>(8, 2.0)));
  REQUIRE(!twos.weights.empty());
  for (const auto& [u, v] : std::vector<std::array<double, 2>>{{0.3, 0.7}, {0.01, 0.02}, {0.5, 0.5}}) {
    const EvaluatedPoints a = at(plain, 2, u, v, 2), b = at(twos, 2, u, v, 2);
    for (int c = 0; c < 3; ++c) {
      CHECK(b.position[size_t(c)] == doctest::Approx(a.position[size_t(c)]).epsilon(1e-13));
      CHECK(b.du[size_t(c)] == doctest::Approx(a.du[size_t(c)]).epsilon(1e-12));
      CHECK(b.duv[size_t(c)] == doctest::Approx(a.duv[size_t(c)]).epsilon(1e-11));
    }
  }
}

TEST_CASE("rational evaluation: at a face corner, the vertex's rational limit position") {
  const std::vector<double> w = uneven_weights(8);
  const PreparedEvaluation p = prepared(weighted_cube(w));
  RefineRequest r;
  r.mesh = weighted_cube(w);
  r.mesh_name = "weighted cube";
  r.scheme.text = "catmull-clark";
  r.levels = 0;
  r.limit_positions = true;
  const RefineResult limits = refine_mesh(std::move(r));
  const std::vector<double>& exact = limits.levels.back().positions;
  const test::Mesh cube = test::cube();
  for (Index f = 0; f < 6; ++f) {
    const Index corner = cube.corners[size_t(4 * f)];  // (u, v) = (0, 0) is the face's first corner
    const EvaluatedPoints e = at(p, f, 0, 0, 0);
    for (int c = 0; c < 3; ++c)
      CHECK(e.position[size_t(c)] == doctest::Approx(exact[size_t(3 * corner + c)]).epsilon(1e-12));
  }
}

TEST_CASE("rational evaluation: derivatives are those of the evaluated points") {
  const PreparedEvaluation p = prepared(weighted_cube(uneven_weights(8)));
  const double h = 1e-5;
  // Away from the lines u, v = j / 2^k, where the pieces of the limit near the cube's
  // extraordinary corners meet with only C1 parametric continuity.
  for (const auto& [u, v] : std::vector<std::array<double, 2>>{{0.3, 0.6}, {0.45, 0.4}, {0.8, 0.3}}) {
    const EvaluatedPoints e = at(p, 1, u, v, 2);
    const EvaluatedPoints pu = at(p, 1, u + h, v, 1), mu = at(p, 1, u - h, v, 1);
    const EvaluatedPoints pv = at(p, 1, u, v + h, 1), mv = at(p, 1, u, v - h, 1);
    for (int c = 0; c < 3; ++c) {
      const auto k = size_t(c);
      CHECK(e.du[k] == doctest::Approx((pu.position[k] - mu.position[k]) / (2 * h)).epsilon(1e-7));
      CHECK(e.dv[k] == doctest::Approx((pv.position[k] - mv.position[k]) / (2 * h)).epsilon(1e-7));
      CHECK(e.duu[k] == doctest::Approx((pu.du[k] - mu.du[k]) / (2 * h)).epsilon(1e-6));
      CHECK(e.dvv[k] == doctest::Approx((pv.dv[k] - mv.dv[k]) / (2 * h)).epsilon(1e-6));
      CHECK(e.duv[k] == doctest::Approx((pv.du[k] - mv.du[k]) / (2 * h)).epsilon(1e-6));
    }
  }
}

TEST_CASE("rational evaluation: limit stencils are refused with the reason") {
  const PreparedEvaluation p = prepared(weighted_cube(uneven_weights(8)));
  const std::array<Index, 1> faces{0};
  const std::array<double, 2> uv{0.5, 0.5};
  CHECK_THROWS_WITH_AS(limit_stencil_matrices(p, faces, uv, 1), doctest::Contains("not linear"), Error);
}

}  // namespace subdiv
