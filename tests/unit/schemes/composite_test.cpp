#include <doctest/doctest.h>

#include <cmath>

#include "support/refine_helpers.h"

using namespace subdiv;

namespace {

void check_same(const std::vector<double>& a, const std::vector<double>& b, double tol) {
  REQUIRE(a.size() == b.size());
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  CHECK(worst < tol);
}

}  // namespace

TEST_CASE("loop-composite (linear split + Loop's averaging mask alpha(k)) equals loop, boundaries included") {
  for (const auto& m : {test::octahedron(), test::torus(6, 5, true), test::grid(4, 3, true)}) {
    const auto a = test::refine_mesh(m, "loop", 3);
    const auto b = test::refine_mesh(m, "loop-composite", 3);
    check_same(a.positions, b.positions, 1e-12);
  }
}

TEST_CASE("quad-bspline of degree 3 equals catmull-clark on a regular quad torus and on grid boundaries") {
  for (const auto& m : {test::torus(7, 6), test::grid(4, 4)}) {
    const auto a = test::refine_mesh(m, "catmull-clark", 3);
    const auto b = test::refine_mesh(m, "quad-bspline", 3);
    check_same(a.positions, b.positions, 1e-12);
  }
}

TEST_CASE("quad-bspline differs from catmull-clark at an extraordinary vertex exactly as the vertex rules predict") {
  // Catmull-Clark: (n-3)/n v + 2/n R + 1/n Q; plain averaging: v/4 + R/2 + Q/4.
  const test::Mesh m = test::cube();  // valence 3 everywhere, quads only
  const auto cc = test::refine_mesh(m, "catmull-clark", 1);
  const auto qb = test::refine_mesh(m, "quad-bspline", 1);
  const Level& L = cc.hierarchy.levels[0];
  const double n = 3;
  for (Index v = 0; v < L.vertex_count; ++v) {
    double Q[3] = {0, 0, 0}, R[3] = {0, 0, 0};
    for (Index f : L.ring_faces(v))
      for (Index u : L.face(f))
        for (int i = 0; i < 3; ++i) Q[i] += m.positions[3 * u + i] / (4 * n);
    for (Index e : L.ring_edges(v))
      for (int i = 0; i < 3; ++i) R[i] += (m.positions[3 * v + i] + m.positions[3 * L.other_end(e, v) + i]) / (2 * n);
    for (int i = 0; i < 3; ++i) {
      const double p = m.positions[3 * v + i];
      CHECK(cc.positions[3 * v + i] == doctest::Approx((n - 3) / n * p + 2 / n * R[i] + Q[i] / n).epsilon(1e-14));
      CHECK(qb.positions[3 * v + i] == doctest::Approx(p / 4 + R[i] / 2 + Q[i] / 4).epsilon(1e-14));
    }
  }
  // Edge and face points agree on all-quad meshes.
  for (Index c = L.vertex_count; c < cc.hierarchy.levels[1].vertex_count; ++c)
    for (int i = 0; i < 3; ++i) CHECK(qb.positions[3 * c + i] == doctest::Approx(cc.positions[3 * c + i]).epsilon(1e-14));
}
