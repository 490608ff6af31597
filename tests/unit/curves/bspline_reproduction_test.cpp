// The B-spline schemes reproduce uniform B-splines: refining a control polygon is knot
// insertion (Lane & Riesenfeld 1980: P(t) = sum_i P^0_i N(t - i) = sum_i P^1_i N(2t - i)), so the
// spline of the refined points on the refined knots is the spline of the original points,
// at every level. Both sides are evaluated with de Boor's algorithm (de Boor 1972).
#include <doctest/doctest.h>

#include <random>

#include "curve_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// Compares sum_j P_j phi(t - j) with sum_c Q_c phi(m^L t - c) at random t wherever both
// evaluations read only existing control points. `p_index` and `q_index` map a control
// index to a point (closed: periodic; open: -1 when missing). Returns the number of t
// compared.
int compare_splines(int degree, double shift, int arity, int level, const std::vector<double>& p,
                    const std::function<long(long)>& p_index, const std::vector<double>& q,
                    const std::function<long(long)>& q_index, double t_lo, double t_hi) {
  std::mt19937 random(1234);
  std::uniform_real_distribution<double> uniform(t_lo, t_hi);
  const double scale = std::pow(double(arity), level);
  int compared = 0;
  for (int sample = 0; sample < 400; ++sample) {
    const double t = uniform(random);
    bool available = true;
    auto [p_lo, p_hi] = de_boor_support(degree, shift, t);
    auto [q_lo, q_hi] = de_boor_support(degree, shift, scale * t);
    for (long j = p_lo; j <= p_hi; ++j) available &= p_index(j) >= 0;
    for (long c = q_lo; c <= q_hi; ++c) available &= q_index(c) >= 0;
    if (!available) continue;
    const Vec3 original = de_boor(degree, shift, t, [&](long j) { return point(p, p_index(j)); });
    const Vec3 refined = de_boor(degree, shift, scale * t, [&](long c) { return point(q, q_index(c)); });
    CAPTURE(t);
    CHECK(distance(original, refined) <= 1e-12);
    ++compared;
  }
  return compared;
}

long periodic(long i, long n) { return ((i % n) + n) % n; }

// Closed polygon of n points refined `levels` times; compared at every level.
void check_closed(const CurveScheme& scheme, int degree, double shift, int n, int levels) {
  const auto p = wiggly_points(n);
  const RefinedCurve r = refine_polyline(scheme, p, true, levels);
  const int m = scheme.arity;
  for (int l = 1; l <= levels; ++l) {
    CAPTURE(l);
    const long count = long(r.positions[l].size() / 3);
    REQUIRE(count == n * long(std::pow(m, l)));
    const int compared = compare_splines(
        degree, shift, m, l, p, [&](long j) { return periodic(j, n); }, r.positions[l],
        [&](long c) { return periodic(c, count); }, 0.0, double(n));
    CHECK(compared == 400);
  }
}

// Open polygon with ends "uniform": level l's points are the bi-infinite scheme's points
// with grid indices first_l .. first_l + count - 1 (tracked through the origins:
// child m*i + r of parent grid index first + i).
void check_open_uniform(const CurveScheme& file_scheme, int degree, double shift, int n, int levels) {
  const CurveScheme scheme = with_ends(file_scheme, CurveEnds::Uniform);
  const auto p = wiggly_points(n);
  const RefinedCurve r = refine_polyline(scheme, p, false, levels);
  const int m = scheme.arity;
  long first = 0;
  for (int l = 1; l <= levels; ++l) {
    CAPTURE(l);
    const CurveOrigins& o = r.hierarchy.origins[l - 1];
    const long count = long(r.positions[l].size() / 3);
    // Consecutive points are consecutive grid points, all made by the scheme's rules.
    std::vector<long> grid;
    for (long k = 0; k < count; ++k) {
      REQUIRE(o.rule[k] >= 0);
      grid.push_back(m * (first + o.index[k]) + o.rule[k]);
    }
    for (long k = 1; k < count; ++k) REQUIRE(grid[k] == grid[k - 1] + 1);
    first = grid[0];
    const int compared = compare_splines(
        degree, shift, m, l, p, [&](long j) { return j >= 0 && j < n ? j : -1; }, r.positions[l],
        [&](long c) { return c >= first && c < first + count ? c - first : -1; }, -2.0, double(n + 2));
    CHECK(compared > 40);
  }
}

}  // namespace

TEST_CASE("bspline of degree d reproduces the uniform B-spline of degree d: closed polygons, d = 1..7") {
  for (int d = 1; d <= 7; ++d) {
    CAPTURE(d);
    const auto scheme = load_curve("bspline", {{"d", std::to_string(d)}});
    // Mask first index -floor((d+2)/2): phi(t) = N_{d+1}(t + floor((d+2)/2)).
    check_closed(*scheme, d, -double((d + 2) / 2), 9, 5);
  }
}

TEST_CASE("bspline of degree d reproduces the uniform B-spline on open polygons (ends uniform), d = 1..6") {
  for (int d = 1; d <= 6; ++d) {
    CAPTURE(d);
    check_open_uniform(*load_curve("bspline", {{"d", std::to_string(d)}}), d, -double((d + 2) / 2), 12, 5);
  }
}

TEST_CASE("Chaikin's limit is the uniform quadratic B-spline (Chaikin 1974; Lane & Riesenfeld 1980)") {
  const auto chaikin = load_curve("chaikin");
  // Mask on -2..1: phi(t) = N_3(t + 2), support [-2, 1].
  check_closed(*chaikin, 2, -2.0, 7, 6);
  check_open_uniform(*chaikin, 2, -2.0, 8, 6);
  // The refined polygon converges to the curve: at level 10 every point is within
  // O(4^-10) of the spline at its Greville abscissa, the centre (c - 1/2)/2^10 of its
  // basis function's support.
  const auto p = wiggly_points(7);
  const RefinedCurve r = refine_polyline(*chaikin, p, true, 10);
  const long count = long(r.positions[10].size() / 3);
  double worst = 0;
  for (long c = 0; c < count; ++c) {
    const double t = (c - 0.5) / 1024.0;
    const Vec3 on_curve = de_boor(2, -2.0, t, [&](long j) { return point(p, periodic(j, 7)); });
    worst = std::max(worst, distance(on_curve, point(r.positions[10], c)));
  }
  CHECK(worst < 1e-5);
}

TEST_CASE("cubic-bspline and the ternary quadratic B-spline reproduce their B-splines") {
  check_closed(*load_curve("cubic-bspline"), 3, -2.0, 6, 6);
  check_open_uniform(*load_curve("cubic-bspline"), 3, -2.0, 7, 5);
  // Ternary: mask on -3..3, phi = N_3(t + 3/2) (support [-3/2, 3/2]); knots refined by 3.
  check_closed(*load_curve("ternary-bspline"), 2, -1.5, 5, 4);
  check_open_uniform(*load_curve("ternary-bspline"), 2, -1.5, 7, 4);
}

TEST_CASE("ends interpolate: end points stay, and points away from the ends are the uniform B-spline's") {
  for (int d : {2, 3, 5}) {
    CAPTURE(d);
    const auto scheme = load_curve("bspline", {{"d", std::to_string(d)}});
    const int n = 20, levels = 5;
    const auto p = wiggly_points(n);
    const RefinedCurve with_end_rules = refine_polyline(*scheme, p, false, levels);
    const RefinedCurve uniform = refine_polyline(with_ends(*scheme, CurveEnds::Uniform), p, false, levels);
    const auto& fine = with_end_rules.positions[levels];
    const long count = long(fine.size() / 3);
    CHECK(point(fine, 0) == point(p, 0));
    CHECK(point(fine, count - 1) == point(p, n - 1));
    // Each point is matched with the uniform scheme's point at the same place; rule
    // supports reach at most (d + 2)/2 old spacings, so the end rules' influence stays
    // within d + 2 spacings of level 0 from each end.
    const auto& reference = uniform.positions[levels];
    int matched = 0;
    for (long c = 0; c < count; ++c) {
      const Vec3 q = point(fine, c);
      double nearest = 1e9;
      for (long k = 0; k < long(reference.size() / 3); ++k) nearest = std::min(nearest, distance(q, point(reference, k)));
      // Parameter of point c (primal: c / 2^L; dual: ends inserted, about c / 2^L too).
      const double t = double(c) / std::pow(2.0, levels);
      if (t > d + 2 && t < n - 1 - (d + 2)) {
        CHECK(nearest <= 1e-13);
        ++matched;
      }
    }
    CHECK(matched > 100);
  }
}
