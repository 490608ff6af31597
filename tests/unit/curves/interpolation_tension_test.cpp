// Interpolatory schemes keep old points at every level; the non-stationary tension scheme
// (Morin, Warren & Weimer 2001) keeps a regular polygon's points on a circle and converges to a circle.
#include <doctest/doctest.h>

#include <cmath>

#include "curve_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// Old point i is new point m*i at every level, closed or open (ends interpolate keeps the
// primal layout: new point m*i sits on old point i).
void check_interpolates(const CurveScheme& scheme, bool closed) {
  const int levels = 5, m = scheme.arity;
  const RefinedCurve r = refine_polyline(scheme, wiggly_points(7), closed, levels);
  for (int l = 1; l <= levels; ++l) {
    CAPTURE(l);
    const auto& parent = r.positions[l - 1];
    const auto& child = r.positions[l];
    const long parents = long(parent.size() / 3);
    REQUIRE(long(child.size() / 3) == (closed ? m * parents : m * (parents - 1) + 1));
    for (long i = 0; i < parents; ++i) CHECK(point(child, m * i) == point(parent, i));
  }
}

// n points on the circle of radius `radius` about `centre` in a tilted plane.
std::vector<double> regular_polygon(int n, const Vec3& centre, double radius, double phase) {
  const Vec3 u{0.6, 0.8, 0.0}, v{-0.48, 0.36, 0.8};  // orthonormal
  std::vector<double> p;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * M_PI * i / n;
    for (int c = 0; c < 3; ++c) p.push_back(centre[c] + radius * (std::cos(a) * u[c] + std::sin(a) * v[c]));
  }
  return p;
}

// Smallest and largest distance of the points from `centre`.
std::pair<double, double> radii(const std::vector<double>& p, const Vec3& centre) {
  double lo = 1e300, hi = 0;
  for (long i = 0; i < long(p.size() / 3); ++i) {
    const double d = distance(point(p, i), centre);
    lo = std::min(lo, d), hi = std::max(hi, d);
  }
  return {lo, hi};
}

}  // namespace

TEST_CASE("four-point, six-point, two-point and ternary-four-point keep old points at every level") {
  for (const char* name : {"four-point", "six-point", "two-point", "ternary-four-point"}) {
    CAPTURE(name);
    const auto scheme = load_curve(name);
    check_interpolates(*scheme, true);
    check_interpolates(*scheme, false);
  }
  check_interpolates(*load_curve("four-point", {{"w", "0.1"}}), false);
  check_interpolates(*load_curve("ternary-four-point", {{"mu", "0.07"}}), true);
}

TEST_CASE("four-point with w = 1/16 is exact on cubics (Dyn, Levin & Gregory 1987: Lagrange interpolation at 1/2)") {
  // Points of a cubic polynomial curve at equal parameter steps stay on it: every new
  // point is the cubic at the midpoint parameter, open ends aside.
  auto cubic = [](double t) { return Vec3{t, 0.5 * t * t - t, 0.1 * t * t * t - 0.3 * t}; };
  std::vector<double> p;
  for (int i = 0; i < 9; ++i) {
    const Vec3 q = cubic(i);
    p.insert(p.end(), q.begin(), q.end());
  }
  const RefinedCurve r = refine_polyline(*load_curve("four-point"), p, false, 4);
  const auto& fine = r.positions[4];
  for (long c = 0; c < long(fine.size() / 3); ++c) {
    const double t = c / 16.0;
    if (t < 2 || t > 6) continue;  // the end rules extrapolate linearly; the middle is exact
    CHECK(distance(point(fine, c), cubic(t)) <= 1e-12);
  }
}

TEST_CASE("tension-bspline: a regular N-gon's points stay on one circle, radius R prod_k cos(theta/2^k), with alpha0 = cos(2 pi/N)") {
  const Vec3 centre{0.3, -0.2, 1.5};
  const double radius = 2.0;
  for (int n : {4, 5, 6, 8, 12}) {
    CAPTURE(n);
    const double theta = 2 * M_PI / n, alpha0 = std::cos(theta);
    const auto scheme = load_curve("tension-bspline", {{"alpha0", fmt::format("{:.17g}", alpha0)}});
    const RefinedCurve r = refine_polyline(*scheme, regular_polygon(n, centre, radius, 0.3), true, 6);
    double expected = radius;
    for (int l = 1; l <= 6; ++l) {
      // Morin, Warren & Weimer 2001: with alpha_l = cos(theta / 2^l), even and odd points of level l
      // both lie at distance cos(theta / 2^l) times the previous radius.
      expected *= std::cos(theta / std::pow(2.0, l));
      const auto [lo, hi] = radii(r.positions[l], centre);
      CAPTURE(l);
      CHECK(std::abs(lo - expected) <= 1e-12 * radius);
      CHECK(std::abs(hi - expected) <= 1e-12 * radius);
    }
  }
}

TEST_CASE("tension-bspline converges to a circle: radius R sin(theta)/theta; the square with alpha0 = 0 (Morin, Warren & Weimer 2001)") {
  const Vec3 centre{0, 0, 0};
  const auto scheme = load_curve("tension-bspline");  // default alpha0 = 0 = cos(2 pi/4)
  const RefinedCurve r = refine_polyline(*scheme, regular_polygon(4, centre, 1.0, 0.0), true, 14);
  const auto [lo, hi] = radii(r.positions[14], centre);
  const double limit = std::sin(M_PI / 2) / (M_PI / 2);  // prod_k cos(theta/2^k) = sin(theta)/theta
  CHECK(std::abs(lo - limit) <= 1e-8);
  CHECK(std::abs(hi - limit) <= 1e-8);
}

TEST_CASE("stationary schemes do not keep a regular polygon on a circle") {
  const Vec3 centre{0.3, -0.2, 1.5};
  for (const char* name : {"four-point", "cubic-bspline", "six-point"}) {
    CAPTURE(name);
    const RefinedCurve r = refine_polyline(*load_curve(name), regular_polygon(6, centre, 2.0, 0.3), true, 6);
    const auto [lo, hi] = radii(r.positions[6], centre);
    CHECK(hi - lo > 1e-4);
  }
  // The tension scheme with the wrong alpha0 (that of a square on a hexagon) does not either.
  const RefinedCurve wrong =
      refine_polyline(*load_curve("tension-bspline", {{"alpha0", "0"}}), regular_polygon(6, centre, 2.0, 0.3), true, 6);
  const auto [lo, hi] = radii(wrong.positions[6], centre);
  CHECK(hi - lo > 1e-4);
}

TEST_CASE("tension-bspline with alpha0 = 1 refines exactly like the cubic B-spline") {
  const auto p = wiggly_points(8);
  const RefinedCurve a = refine_polyline(*load_curve("tension-bspline", {{"alpha0", "1"}}), p, true, 5);
  const RefinedCurve b = refine_polyline(*load_curve("cubic-bspline"), p, true, 5);
  for (int l = 1; l <= 5; ++l)
    for (size_t i = 0; i < a.positions[l].size(); ++i) CHECK(a.positions[l][i] == doctest::Approx(b.positions[l][i]).epsilon(1e-15));
}
