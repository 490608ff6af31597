// Limit points of polylines (framework/interpolation/curve_limits.h) and progressive
// interpolation of curves. Checked against closed forms (the B-spline's (1, 4, 1)/6 and
// (1, 6, 1)/8, the interpolatory schemes' identity), an independent de Boor evaluation of
// the cubic B-spline with the ends' linear extrapolation, and deep refinement.
#include <doctest/doctest.h>

#include "framework/analysis/curve/curve_basis.h"
#include "framework/curve/curve_rules.h"
#include "framework/interpolation/curve_limits.h"
#include "framework/interpolation/progressive.h"
#include "unit/curves/curve_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

double weight(const StencilTable& t, Index r, Index source) {
  double w = 0;
  for (Index i = t.offsets[r]; i < t.offsets[r + 1]; ++i)
    if (t.indices[i] == source) w += t.weights[i];
  return w;
}

// The smallest distance from x to the segments of a finely refined polyline (a dual
// scheme has no fine point at a control point's parameter, only segments around it).
double distance_to(const Vec3& x, const std::vector<double>& fine) {
  double best = 1e300;
  for (long i = 0; i + 1 < long(fine.size() / 3); ++i) {
    const Vec3 a = point(fine, i), b = point(fine, i + 1);
    double ab2 = 0, t = 0;
    for (int c = 0; c < 3; ++c) ab2 += (b[c] - a[c]) * (b[c] - a[c]), t += (x[c] - a[c]) * (b[c] - a[c]);
    t = ab2 > 0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
    Vec3 q;
    for (int c = 0; c < 3; ++c) q[c] = a[c] + t * (b[c] - a[c]);
    best = std::min(best, distance(x, q));
  }
  return best;
}

// Every stationary shipped curve scheme, and B-splines of degree 4 and 5, whose limit
// near an open end is not the uniform row (the ends' extrapolation is not reproduced).
const std::vector<std::pair<std::string, ParameterOverrides>> kStationary = {
    {"cubic-bspline", {}}, {"chaikin", {}},         {"four-point", {}},
    {"six-point", {}},     {"two-point", {}},       {"bspline", {}},
    {"bspline", {{"d", "4"}}}, {"bspline", {{"d", "5"}}}, {"ternary-bspline", {}},
    {"ternary-cubic-bspline", {}}, {"ternary-four-point", {}}};

}  // namespace

TEST_CASE("the refinable function at the integers and at the centre of its support") {
  const BasisSamples cubic = sample_basis(curve_mask(*load_curve("cubic-bspline")), "cubic-bspline");
  CHECK(cubic.centre == 0.0);
  REQUIRE(cubic.at_integers.size() == 5);  // phi(-2) .. phi(2), the support's integers
  CHECK(cubic.integers_first == -2);
  CHECK(cubic.at_integers[0] == 0.0);
  CHECK(cubic.at_integers[1] == doctest::Approx(1.0 / 6).epsilon(1e-14));
  CHECK(cubic.at_integers[2] == doctest::Approx(2.0 / 3).epsilon(1e-14));
  CHECK(cubic.at_integers[3] == doctest::Approx(1.0 / 6).epsilon(1e-14));
  CHECK(cubic.at_integers[4] == 0.0);
  // Chaikin: phi is the quadratic B-spline on [-2, 1], centre -1/2, where it is (1, 6, 1)/8.
  const BasisSamples chaikin = sample_basis(curve_mask(*load_curve("chaikin")), "chaikin");
  CHECK(chaikin.centre == -0.5);
  REQUIRE(chaikin.at_centre.size() == 3);
  CHECK(chaikin.at_centre[0] == doctest::Approx(1.0 / 8).epsilon(1e-14));
  CHECK(chaikin.at_centre[1] == doctest::Approx(3.0 / 4).epsilon(1e-14));
  CHECK(chaikin.at_centre[2] == doctest::Approx(1.0 / 8).epsilon(1e-14));
  // The ternary cubic B-spline has the binary one's values at the knots.
  const BasisSamples ternary = sample_basis(curve_mask(*load_curve("ternary-cubic-bspline")), "ternary-cubic-bspline");
  double at_zero = 0;
  for (size_t i = 0; i < ternary.at_centre.size(); ++i)
    if (ternary.centre_first + int(i) == 0) at_zero = ternary.at_centre[i];
  CHECK(at_zero == doctest::Approx(2.0 / 3).epsilon(1e-13));
  // Interpolatory: phi(k) = delta_k, exactly.
  const BasisSamples four = sample_basis(curve_mask(*load_curve("four-point")), "four-point");
  for (size_t i = 0; i < four.at_integers.size(); ++i)
    CHECK(four.at_integers[i] == (four.integers_first + int(i) == 0 ? 1.0 : 0.0));
  // A mask with no convergent limit: 2 P_i - (P_{i-1} + P_{i+1}) / 2 at old points.
  CurveMask bad;
  bad.arity = 2, bad.first = -2, bad.coefficients = {-0.25, 0.5, 2.0, 0.5, -0.25};
  CHECK_THROWS_WITH_AS(sample_basis(bad, "bad"), doctest::Contains("no limit points"), Error);
}

TEST_CASE("closed polygons: every row is the scheme's limit row, around the polygon") {
  const CurveLevel pentagon = single_polyline(5, true);
  const StencilTable cubic = curve_limit_stencils(*load_curve("cubic-bspline"), pentagon);
  const StencilTable chaikin = curve_limit_stencils(*load_curve("chaikin"), pentagon);
  const StencilTable four = curve_limit_stencils(*load_curve("four-point"), pentagon);
  for (Index j = 0; j < 5; ++j) {
    const Index prev = (j + 4) % 5, next = (j + 1) % 5;
    CHECK(weight(cubic, j, j) == doctest::Approx(2.0 / 3).epsilon(1e-14));
    CHECK(weight(cubic, j, prev) == doctest::Approx(1.0 / 6).epsilon(1e-14));
    CHECK(weight(cubic, j, next) == doctest::Approx(1.0 / 6).epsilon(1e-14));
    CHECK(weight(chaikin, j, j) == doctest::Approx(3.0 / 4).epsilon(1e-14));
    CHECK(weight(chaikin, j, prev) == doctest::Approx(1.0 / 8).epsilon(1e-14));
    CHECK(weight(chaikin, j, next) == doctest::Approx(1.0 / 8).epsilon(1e-14));
    CHECK(four.row_size(j) == 1);
    CHECK(weight(four, j, j) == 1.0);
  }
  // A triangle is shorter than the cubic mask: the weights wrap onto the same points.
  const StencilTable small = curve_limit_stencils(*load_curve("cubic-bspline"), single_polyline(3, true));
  CHECK(weight(small, 0, 1) == doctest::Approx(1.0 / 6).epsilon(1e-14));
}

TEST_CASE("open cubic B-spline polylines: the limit rows are de Boor's, with the ends' extrapolation") {
  // With ends "interpolate", refinement near an end equals uniform refinement of the
  // polygon extended by P_-d = P_0 + d (P_0 - P_1) (the extension is reproduced at every
  // level), so the limit curve is the uniform cubic B-spline of the extended polygon and
  // the limit point of vertex j is that spline at t = j (basis centred on j: shift -2).
  for (int count : {4, 7, 30}) {
    CAPTURE(count);
    const std::vector<double> p = wiggly_points(count);
    auto control = [&](long j) {
      const long n = count;
      const long base = j < 0 ? 0 : n - 1, other = j < 0 ? 1 : n - 2, d = j < 0 ? -j : j - (n - 1);
      if (j >= 0 && j < n) return point(p, j);
      Vec3 x;
      for (int c = 0; c < 3; ++c) x[c] = p[3 * base + c] + double(d) * (p[3 * base + c] - p[3 * other + c]);
      return x;
    };
    const std::vector<double> limit =
        curve_limit_stencils(*load_curve("cubic-bspline"), single_polyline(count, false)).apply(p, 3);
    for (long j = 0; j < count; ++j) CHECK(distance(point(limit, j), de_boor(3, -2.0, double(j), control)) < 1e-12);
  }
}

TEST_CASE("open Chaikin polylines: the quadratic B-spline of the polygon with doubled end points") {
  // Keeping the end point P_0 and cutting the first edge as usual is Chaikin's refinement of
  // the polygon P_0, P_0, P_1, ... (the doubled point's own edge gives P_0 twice), so the
  // limit of vertex j >= 1 is still (P_{j-1} + 6 P_j + P_{j+1}) / 8, next to the ends too.
  for (int count : {3, 6, 30}) {
    CAPTURE(count);
    const StencilTable limit = curve_limit_stencils(*load_curve("chaikin"), single_polyline(count, false));
    CHECK(weight(limit, 0, 0) == 1.0);
    CHECK(weight(limit, count - 1, count - 1) == 1.0);
    for (Index j = 1; j + 1 < count; ++j) {
      CHECK(limit.row_size(j) == 3);
      CHECK(weight(limit, j, j - 1) == doctest::Approx(1.0 / 8).epsilon(1e-12));
      CHECK(weight(limit, j, j) == doctest::Approx(3.0 / 4).epsilon(1e-12));
      CHECK(weight(limit, j, j + 1) == doctest::Approx(1.0 / 8).epsilon(1e-12));
    }
  }
}

TEST_CASE("interpolatory curve schemes: every point is its own limit, ends and windows included") {
  for (const char* name : {"four-point", "six-point", "ternary-four-point", "two-point"})
    for (int count : {5, 40}) {
      CAPTURE(name);
      CAPTURE(count);
      const std::vector<double> p = wiggly_points(count);
      const std::vector<double> limit = curve_limit_stencils(*load_curve(name), single_polyline(count, false)).apply(p, 3);
      for (long j = 0; j < count; ++j) CHECK(distance(point(limit, j), point(p, j)) < 1e-12);
    }
}

TEST_CASE("every stationary shipped curve scheme: limit points lie on the limit curve, and interpolation converges") {
  for (const auto& stationary : kStationary)
    for (bool closed : {false, true}) {
      // References, not a structured binding: clang 14 cannot capture those in lambdas (CAPTURE).
      const auto& name = stationary.first;
      const auto& params = stationary.second;
      CAPTURE(name);
      CAPTURE(params.size() ? params.begin()->second : std::string("default"));
      CAPTURE(closed);
      const auto scheme = load_curve(name, params);
      const int count = 24;
      const std::vector<double> p = wiggly_points(count);
      const CurveLevel level = single_polyline(count, closed);
      const StencilTable limit = curve_limit_stencils(*scheme, level);
      for (Index r = 0; r < limit.row_count(); ++r) {
        double sum = 0;
        for (Index i = limit.offsets[r]; i < limit.offsets[r + 1]; ++i) sum += limit.weights[i];
        CHECK(sum == doctest::Approx(1.0).epsilon(1e-12));
      }
      // On the curve: within the chord error of a deep refinement (spacing 2^-13 or 3^-9 of
      // the control spacing, chord error of order its square).
      const int levels = scheme->arity == 2 ? 13 : 9;
      const std::vector<double> fine = refine_polyline(*scheme, p, closed, levels).positions.back();
      const std::vector<double> at = limit.apply(p, 3);
      for (long j = 0; j < count; ++j) CHECK(distance_to(point(at, j), fine) < 1e-6);
      // Interpolation: the limit points of the result are the targets, and a deep
      // refinement of the result passes through them.
      ProgressiveOptions o;
      o.tolerance = 1e-11;
      const ProgressiveResult r = progressive_interpolation(limit, p, {}, o);
      CHECK(r.converged);
      const std::vector<double> through = refine_polyline(*scheme, r.control, closed, levels).positions.back();
      for (long j = 0; j < count; ++j) CHECK(distance_to(point(p, j), through) < 1e-6);
    }
}

TEST_CASE("curve limits refuse what has no limit point") {
  // Ends "uniform": open polylines shrink, their end vertices have no limit point.
  const CurveScheme uniform = with_ends(*load_curve("cubic-bspline"), CurveEnds::Uniform);
  CHECK_THROWS_WITH_AS(curve_limit_stencils(uniform, single_polyline(8, false)),
                       doctest::Contains("do not keep their end points"), Error);
  CHECK(curve_limit_stencils(uniform, single_polyline(8, true)).row_count() == 8);  // closed: fine
  // Non-stationary: the tension B-spline's weights change with the level.
  CHECK_THROWS_WITH_AS(curve_limit_stencils(*load_curve("tension-bspline"), single_polyline(8, true)),
                       doctest::Contains("stationary"), Error);
}
