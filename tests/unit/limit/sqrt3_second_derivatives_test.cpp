// Second derivatives of √3 limit surfaces (docs/limit.md, "√3 schemes"): Kobbelt's √3 is C2
// on regular regions (Kobbelt 2000, "√3-subdivision"; its regular vertex's eigenvalues are
// 1, 1/3, 1/3, 1/9 (three times), then 0.0410 = 3^-2.907, so the second derivatives are
// Hölder continuous with exponent about 0.907), Labsik & Greiner's interpolating √3 only C1
// (its regular vertex has 0.180 > 1/9: the curvature is unbounded there). Checked against
// central differences of the evaluated first derivatives, against the exact Hessian of
// sampled quadratics (the scheme generates quadratics: their limit is the quadratic plus an
// affine function), near extraordinary vertices, next to a boundary, and as stencils.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>

#include "framework/features/sharpness.h"
#include "framework/limit/limit_surface.h"
#include "framework/limit/sqrt3_limit.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"
#include "unit/limit/sqrt3_creased_meshes.h"

using namespace subdiv;

namespace {

using limit_test::bumped;
using limit_test::distance;

// The largest difference between the evaluated second derivatives at (face, u, v) and central
// differences (step h) of the evaluated first derivatives, relative to the largest second
// derivative there (at least 1e-3, so that a vanishing one is not divided by).
double second_difference_error(const LimitSurface& s, Index face, double u, double v, std::span<const double> P,
                               double h) {
  const LimitSample p = s.evaluate(face, u, v, P, 3, 2);
  REQUIRE(p.has_second_derivatives);
  const LimitSample a = s.evaluate(face, u + h, v, P, 3, 1), b = s.evaluate(face, u - h, v, P, 3, 1);
  const LimitSample c = s.evaluate(face, u, v + h, P, 3, 1), d = s.evaluate(face, u, v - h, P, 3, 1);
  double size = 1e-3, worst = 0;
  for (size_t r = 0; r < 3; ++r) {
    size = std::max({size, std::fabs(p.duu[r]), std::fabs(p.duv[r]), std::fabs(p.dvv[r])});
    worst = std::max(worst, std::fabs((a.du[r] - b.du[r]) / (2 * h) - p.duu[r]));
    worst = std::max(worst, std::fabs((c.dv[r] - d.dv[r]) / (2 * h) - p.dvv[r]));
    worst = std::max(worst, std::fabs((a.dv[r] - b.dv[r]) / (2 * h) - p.duv[r]));
    worst = std::max(worst, std::fabs((c.du[r] - d.du[r]) / (2 * h) - p.duv[r]));
  }
  return worst / size;
}

// A stencil's row of weights over `vertices` applied to xyz control points.
std::array<double, 3> stencil_applied(const std::vector<Index>& vertices, const std::vector<double>& weights,
                                      std::span<const double> positions) {
  std::array<double, 3> x{};
  for (size_t e = 0; e < vertices.size(); ++e)
    for (size_t r = 0; r < 3; ++r) x[r] += weights[e] * positions[size_t(3 * vertices[e]) + r];
  return x;
}

// A bumped regular torus: every vertex of valence 6.
test::Mesh regular_torus() { return bumped(test::torus(12, 12, true), 0.2); }

// A random point of a triangle at least `margin` inside it.
std::array<double, 2> inside(std::mt19937& rng, double margin) {
  std::uniform_real_distribution<double> U(margin, 1 - 2 * margin);
  for (;;) {
    const double u = U(rng), v = U(rng);
    if (u + v <= 1 - margin) return {u, v};
  }
}

}  // namespace

TEST_CASE("sqrt3 second derivatives: central differences of first derivatives on a regular torus") {
  // C2 with second derivatives Hölder continuous of exponent about 0.9: a central difference
  // of step h is off by about h^0.9 (measured 1e-5 relative at h = 1e-4); a wrong factor (the
  // 9 per double step, the normalisation) is off by O(1).
  const test::Mesh m = regular_torus();
  const LimitSurface s(load_scheme("sqrt3"), m.level());
  std::mt19937 rng(7);
  double worst = 0;
  for (int k = 0; k < 12; ++k) {
    const auto uv = inside(rng, 0.01);
    const Index f = Index((37 * k + 5) % m.level().face_count());
    worst = std::max(worst, second_difference_error(s, f, uv[0], uv[1], m.positions, 1e-4));
  }
  MESSAGE("worst relative difference: " << worst);
  CHECK(worst < 2e-4);
  // At the face's centroid (a vertex from level 1 on, to round-off) and a point off the lattice.
  for (const std::array<double, 2> uv : {std::array<double, 2>{1.0 / 3, 1.0 / 3}, {0.5, 0.25}}) {
    CAPTURE(uv[0]);
    CAPTURE(uv[1]);
    CHECK(second_difference_error(s, 40, uv[0], uv[1], m.positions, 1e-4) < 2e-4);
  }
}

TEST_CASE("sqrt3 second derivatives: sampled quadratics give their Hessian exactly") {
  // Control points at (x, y, q(x, y)) with (x, y) their grid coordinates (the regular torus
  // unrolled away from the seam, sqrt3_limit_test.cpp's linear precision test) and q a
  // quadratic: a scheme that generates quadratics has q plus an affine function as the
  // limit's z, whose second derivatives are q's. Face 2 (j n + i) has grid point
  // (i + u + v, j + v), face 2 (j n + i) + 1 has (i + u, j + u + v).
  const int n = 30;
  test::Mesh m = test::torus(n, n, true);
  const double qxx = 0.7, qxy = -0.3, qyy = 0.4;  // q = qxx x²/2 + qxy x y + qyy y²/2
  for (Index v = 0; v < m.vertex_count; ++v) {
    const double x = double(v % n), y = double(v / n);
    m.positions[size_t(3 * v)] = x, m.positions[size_t(3 * v + 1)] = y;
    m.positions[size_t(3 * v + 2)] = qxx * x * x / 2 + qxy * x * y + qyy * y * y / 2;
  }
  const LimitSurface s(load_scheme("sqrt3"), m.level());
  std::mt19937 rng(3);
  for (int k = 0; k < 8; ++k) {
    const int i = 14 + k % 2, j = 14 + (k / 2) % 2, half = k % 3 == 0 ? 1 : 0;
    const auto uv = inside(rng, 0);
    const LimitSample p = s.evaluate(Index(2 * (j * n + i) + half), uv[0], uv[1], m.positions, 3, 2);
    REQUIRE(p.has_second_derivatives);
    // The nearest vertex is off by (3^-k)^0.9 in the second derivatives (Hölder continuous):
    // 43 double steps bring that below round-off (sqrt3_limit.h).
    CHECK(p.steps == Sqrt3Limit::kSecondOrderSteps);
    // d/du, d/dv as combinations of d/dx, d/dy.
    const std::array<double, 2> du = half ? std::array<double, 2>{1, 1} : std::array<double, 2>{1, 0};
    const std::array<double, 2> dv = half ? std::array<double, 2>{0, 1} : std::array<double, 2>{1, 1};
    auto hessian = [&](const std::array<double, 2>& a, const std::array<double, 2>& b) {
      return qxx * a[0] * b[0] + qxy * (a[0] * b[1] + a[1] * b[0]) + qyy * a[1] * b[1];
    };
    CHECK(std::fabs(p.duu[2] - hessian(du, du)) < 1e-10);
    CHECK(std::fabs(p.duv[2] - hessian(du, dv)) < 1e-10);
    CHECK(std::fabs(p.dvv[2] - hessian(dv, dv)) < 1e-10);
    // x and y are linear: no second derivatives.
    for (size_t r = 0; r < 2; ++r) {
      CHECK(std::fabs(p.duu[r]) < 1e-10);
      CHECK(std::fabs(p.duv[r]) < 1e-10);
      CHECK(std::fabs(p.dvv[r]) < 1e-10);
    }
  }
}

TEST_CASE("sqrt3 second derivatives: near extraordinary vertices, none at them, none for the interpolating scheme") {
  const test::Mesh m = bumped(test::octahedron());
  const LimitSurface s(load_scheme("sqrt3"), m.level());
  // The vertex itself (valence 4): the curvature is not defined there.
  const LimitSample at = s.evaluate(0, 0, 0, m.positions, 3, 2);
  CHECK(!at.has_second_derivatives);
  // Beside it the surface is C2; the second derivatives change on the scale of the distance d,
  // so the difference step is a fraction of d.
  for (double d : {1e-1, 1e-2, 1e-3}) {
    CAPTURE(d);
    CHECK(second_difference_error(s, 0, d, 0.7 * d, m.positions, 1e-4 * d) < 1e-3);
  }
  // Labsik & Greiner's interpolating √3 is C1 only (its regular vertex's eigenvalue 0.180
  // exceeds 1/9: the second differences of its limit grow like h^-0.44 at the vertices).
  const test::Mesh t = regular_torus();
  const LimitSurface i(load_scheme("interpolating-sqrt3"), t.level());
  for (const std::array<double, 2> uv : {std::array<double, 2>{0.2, 0.3}, {1.0 / 3, 1.0 / 3}}) {
    const LimitSample p = i.evaluate(5, uv[0], uv[1], t.positions, 3, 2);
    CHECK(p.has_derivatives);
    CHECK(!p.has_second_derivatives);
  }
}

TEST_CASE("sqrt3 second derivatives: close to vertices of valence 3, 5 and 7") {
  // The apex of a bipyramid (corner 2 of every upper face) has valence n; the surface is C2
  // beside it, so central differences of the first derivatives match the second derivatives
  // at every distance d down to where the descent takes the self-similar levels' powers
  // (d = 1e-6 is about 12 double steps in), the difference step a fraction of d.
  for (const int n : {3, 5, 7}) {
    CAPTURE(n);
    const test::Mesh m = bumped(test::bipyramid(n));
    const LimitSurface s(load_scheme("sqrt3"), m.level());
    CHECK(!s.evaluate(0, 0, 1, m.positions, 3, 2).has_second_derivatives);
    for (const double d : {1e-1, 1e-2, 1e-4, 1e-6}) {
      CAPTURE(d);
      CHECK(second_difference_error(s, 2, 0.7 * d, 1 - 1.6 * d, m.positions, 1e-4 * d) < 1e-3);
    }
  }
}

TEST_CASE("sqrt3 second derivatives: stencils equal evaluation") {
  for (const test::Mesh& m : {regular_torus(), bumped(test::octahedron())}) {
    const LimitSurface s(load_scheme("sqrt3"), m.level());
    std::mt19937 rng(5);
    for (int k = 0; k < 4; ++k) {
      const auto uv = inside(rng, 0.02);
      const Index f = Index(k % m.level().face_count());
      const LimitSample p = s.evaluate(f, uv[0], uv[1], m.positions, 3, 2);
      const LimitStencil st = s.stencil(f, uv[0], uv[1], 2);
      REQUIRE(p.has_second_derivatives);
      REQUIRE(st.has_second_derivatives);
      CHECK(distance(stencil_applied(st.vertices, st.duu, m.positions), p.duu) < 1e-10);
      CHECK(distance(stencil_applied(st.vertices, st.duv, m.positions), p.duv) < 1e-10);
      CHECK(distance(stencil_applied(st.vertices, st.dvv, m.positions), p.dvv) < 1e-10);
    }
  }
}

TEST_CASE("sqrt3 second derivatives: next to sharp and semi-sharp creases, none on an infinitely sharp one") {
  // Face 2 (2 n + 3) of the creased torus has the crease edge (3, 2)-(4, 2) at v = 0. Sharpness
  // 2 is followed as triadic pairs, 1 as single steps before them (a sequence); both decay,
  // and the surface is C2 beside the former crease. Beside an infinitely sharp one the second
  // derivatives grow as the crease nears, so the difference step is a fraction of the distance.
  using limit_test::sqrt3::creased_torus;
  const Index f = Index(2 * (2 * limit_test::sqrt3::kCreasedTorusSize + 3));
  for (const float sharpness : {kInfinitelySharp, 2.f, 1.f}) {
    CAPTURE(sharpness);
    const limit_test::sqrt3::Tagged t = creased_torus(sharpness);
    const LimitSurface s(load_scheme("sqrt3"), t.level);
    for (const double d : {0.2, 0.01}) {
      CAPTURE(d);
      CHECK(second_difference_error(s, f, 0.3, d, t.mesh.positions, 1e-4 * d) < 1e-3);
    }
    if (sharpness >= kInfinitelySharp) CHECK(!s.evaluate(f, 0.3, 0, t.mesh.positions, 3, 2).has_second_derivatives);
  }
}
