// Derivatives of √3 limit surfaces at and next to a boundary (docs/limit.md, "√3 schemes at
// boundaries and holes"). Along a boundary edge Kobbelt's √3 is the ternary cubic B-spline of
// the boundary's control points, in its own parameter (a closed form). Across the boundary the
// (u, v) derivative does not exist: the boundary rules shrink the rows next to the boundary by
// about 0.37 per double step, more than the parameter's 1/3, so the one-sided difference quotient
// grows without bound (measured: evaluation returns none, `nan`). Next to the boundary the
// second derivatives exist and match central differences.
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

using limit_test::bumped;
using limit_test::distance;

// A bumped triangulated 8 x 8 grid: face 2 i (i < 8) is (i, 0), (i + 1, 0), (i + 1, 1), its
// edge v = 0 on the boundary, u running from vertex i to vertex i + 1.
test::Mesh open_grid() { return bumped(test::grid(8, 8, true), 0.3); }

// The uniform cubic B-spline through control points P[i - 1 .. i + 2] (vertices i - 1 .. i + 2
// of the grid's bottom row) at t in [0, 1] of the segment from i to i + 1, and its derivative
// (de Boor 1978, the uniform basis).
std::array<double, 3> bspline(const test::Mesh& m, int i, double t, bool derivative) {
  const double s = 1 - t;
  const std::array<double, 4> b = derivative
                                      ? std::array<double, 4>{-3 * s * s, 9 * t * t - 12 * t, -9 * t * t + 6 * t + 3, 3 * t * t}
                                      : std::array<double, 4>{s * s * s, 3 * t * t * t - 6 * t * t + 4,
                                                              -3 * t * t * t + 3 * t * t + 3 * t + 1, t * t * t};
  std::array<double, 3> x{};
  for (int k = 0; k < 4; ++k)
    for (size_t r = 0; r < 3; ++r) x[r] += b[size_t(k)] / 6 * m.positions[size_t(3 * (i - 1 + k)) + r];
  return x;
}

}  // namespace

TEST_CASE("sqrt3 at a boundary: the boundary curve and its derivative are the cubic B-spline's") {
  const test::Mesh m = open_grid();
  const LimitSurface s(load_scheme("sqrt3"), m.level());
  for (const int i : {3, 4})
    for (const double t : {0.123, 0.37, 0.5}) {
      CAPTURE(i);
      CAPTURE(t);
      const LimitSample p = s.evaluate(Index(2 * i), t, 0, m.positions, 3);
      CHECK(distance(p.position, bspline(m, i, t, false)) < 1e-13);
      // Along the edge: a central difference of the evaluated positions (step h, error h²).
      const double h = 1e-5;
      const LimitSample a = s.evaluate(Index(2 * i), t + h, 0, m.positions, 3, 0);
      const LimitSample b = s.evaluate(Index(2 * i), t - h, 0, m.positions, 3, 0);
      std::array<double, 3> along{};
      for (size_t r = 0; r < 3; ++r) along[r] = (a.position[r] - b.position[r]) / (2 * h);
      CHECK(distance(along, bspline(m, i, t, true)) < 1e-8);
      // On the boundary no (u, v) derivatives are returned (below: across, none exist).
      CHECK(!p.has_derivatives);
    }
}

TEST_CASE("sqrt3 at a boundary: across it the one-sided difference quotient grows without bound") {
  // At u = 1/2 of a boundary edge (the fixed point of its middle third) the limit's distance
  // from the boundary point shrinks by about 0.37 per double step while the parameter shrinks
  // by 1/3: |P(1/2, δ) - P(1/2, 0)| / δ grows like δ^-0.1 (measured 1.07 ... 1.10 per third of δ).
  // So there is no derivative across the boundary to return, for either scheme.
  const test::Mesh m = open_grid();
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    const LimitSurface s(load_scheme(name), m.level());
    const LimitSample at = s.evaluate(6, 0.5, 0, m.positions, 3, 0);
    auto quotient = [&](int j) {
      const double delta = std::pow(3.0, -j);
      return distance(s.evaluate(6, 0.5, delta, m.positions, 3, 0).position, at.position) / delta;
    };
    const double q6 = quotient(6), q12 = quotient(12), q18 = quotient(18);
    MESSAGE("quotients at 3^-6, 3^-12, 3^-18: " << q6 << " " << q12 << " " << q18);
    CHECK(q12 > 1.2 * q6);
    CHECK(q18 > 1.2 * q12);
  }
}

TEST_CASE("sqrt3 next to a boundary: second derivatives against central differences, none on it") {
  const test::Mesh m = open_grid();
  const LimitSurface s(load_scheme("sqrt3"), m.level());
  for (const double d : {1e-1, 1e-2, 1e-3}) {
    CAPTURE(d);
    const double u = 0.4, h = 1e-4 * d;
    const LimitSample p = s.evaluate(6, u, d, m.positions, 3, 2);
    REQUIRE(p.has_second_derivatives);
    const LimitSample a = s.evaluate(6, u + h, d, m.positions, 3, 1), b = s.evaluate(6, u - h, d, m.positions, 3, 1);
    const LimitSample c = s.evaluate(6, u, d + h, m.positions, 3, 1), e = s.evaluate(6, u, d - h, m.positions, 3, 1);
    double size = 0, worst = 0;
    for (size_t r = 0; r < 3; ++r) {
      size = std::max({size, std::fabs(p.duu[r]), std::fabs(p.duv[r]), std::fabs(p.dvv[r])});
      worst = std::max(worst, std::fabs((a.du[r] - b.du[r]) / (2 * h) - p.duu[r]));
      worst = std::max(worst, std::fabs((c.dv[r] - e.dv[r]) / (2 * h) - p.dvv[r]));
      worst = std::max(worst, std::fabs((a.dv[r] - b.dv[r]) / (2 * h) - p.duv[r]));
    }
    MESSAGE("largest second derivative " << size << ", worst difference " << worst);
    CHECK(worst < 1e-3 * size);
  }
  const LimitSample on = s.evaluate(6, 0.4, 0, m.positions, 3, 2);
  CHECK(!on.has_second_derivatives);
}
