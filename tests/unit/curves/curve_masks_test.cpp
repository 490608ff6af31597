// Each shipped curve scheme's rules equal its mask as the papers write it, and
// the symbol analysis confirms the smoothness the scheme files claim.
#include <doctest/doctest.h>

#include <cmath>

#include "curve_test_support.h"
#include "framework/analysis/curve/curve_analysis.h"
#include "framework/curve/curve_rules.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// Binomial coefficient by Pascal's triangle, independent of the formula library.
double pascal(int n, int k) {
  std::vector<double> row{1.0};
  for (int i = 0; i < n; ++i) {
    std::vector<double> next(row.size() + 1, 0.0);
    for (size_t q = 0; q < row.size(); ++q) next[q] += row[q], next[q + 1] += row[q];
    row = next;
  }
  return k < 0 || k > n ? 0.0 : row[size_t(k)];
}

// Compares masks coefficient by coefficient over the union of their ranges.
void check_same_mask(const CurveMask& got, const CurveMask& expected, double tolerance = 1e-15) {
  REQUIRE(got.arity == expected.arity);
  const int lo = std::min(got.first, expected.first), hi = std::max(got.last(), expected.last());
  for (int i = lo; i <= hi; ++i) {
    CAPTURE(i);
    CHECK(got.at(i) == doctest::Approx(expected.at(i)).epsilon(tolerance).scale(1.0));
  }
}

CurveMask mask(int arity, int first, std::vector<double> a, double scale = 1.0) {
  for (double& x : a) x /= scale;
  return CurveMask{arity, first, a};
}

std::shared_ptr<const CurveScheme> curve(const std::string& name, const ParameterOverrides& p = {}) {
  return load_curve(name, p);
}

}  // namespace

TEST_CASE("chaikin: rules equal the mask (1, 3, 3, 1)/4 of Chaikin 1974") {
  // The usual numbering of the quadratic B-spline rules: P_2i = 3/4 P_i + 1/4 P_i+1,
  // P_2i+1 = 1/4 P_i + 3/4 P_i+1 (both new points on segment (i, i+1)), so the mask
  // a_{r - 2 s} sits on -2..1.
  check_same_mask(curve_mask(*curve("chaikin")), mask(2, -2, {1, 3, 3, 1}, 4));
  const auto rules = evaluate_curve_rules(*curve("chaikin"), 0);
  CHECK(rules.starts == std::vector<int>{0, 0});
  CHECK(rules.weights == std::vector<std::vector<double>>{{0.75, 0.25}, {0.25, 0.75}});
  CHECK(rules.offsets == std::vector<double>{0.25, 0.75});
}

TEST_CASE("cubic-bspline: rules equal the mask (1, 4, 6, 4, 1)/8 of Lane & Riesenfeld 1980") {
  check_same_mask(curve_mask(*curve("cubic-bspline")), mask(2, -2, {1, 4, 6, 4, 1}, 8));
}

TEST_CASE("bspline of degree d: the mask is c_i = 2^-d C(d+1, i) (Lane & Riesenfeld 1980), for d = 1..12") {
  for (int d = 1; d <= 12; ++d) {
    CAPTURE(d);
    std::vector<double> c;
    for (int i = 0; i <= d + 1; ++i) c.push_back(pascal(d + 1, i) / std::pow(2.0, d));
    // Odd d: primal, symmetric about 0; even d: dual, both new points of old point i on
    // segment (i, i+1) as in Chaikin's quadratic rules (symmetric about -1/2).
    check_same_mask(curve_mask(*curve("bspline", {{"d", std::to_string(d)}})), mask(2, -((d + 2) / 2), c));
  }
  // d = 2 is Chaikin, d = 3 the cubic B-spline: same rules, number for number.
  const auto quad = evaluate_curve_rules(*curve("bspline", {{"d", "2"}}), 0);
  const auto chaikin = evaluate_curve_rules(*curve("chaikin"), 0);
  CHECK(quad.starts == chaikin.starts);
  CHECK(quad.weights == chaikin.weights);
  const auto cubic = evaluate_curve_rules(*curve("bspline"), 0);
  const auto reference = evaluate_curve_rules(*curve("cubic-bspline"), 0);
  CHECK(cubic.starts == reference.starts);
  CHECK(cubic.weights == reference.weights);
}

TEST_CASE("two-point: mask (1, 2, 1)/2") {
  check_same_mask(curve_mask(*curve("two-point")), mask(2, -1, {1, 2, 1}, 2));
}

TEST_CASE("four-point: mask (-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w); w = 1/16 gives (-1, 0, 9, 16, 9, 0, -1)/16") {
  check_same_mask(curve_mask(*curve("four-point")), mask(2, -3, {-1, 0, 9, 16, 9, 0, -1}, 16));
  for (double w : {0.0, 0.03, 0.1, 0.125, 0.154508}) {
    CAPTURE(w);
    check_same_mask(curve_mask(*curve("four-point", {{"w", fmt::format("{:.17g}", w)}})),
                    mask(2, -3, {-w, 0, 0.5 + w, 1, 0.5 + w, 0, -w}));
  }
}

TEST_CASE("six-point: odd rule (3, -25, 150, 150, -25, 3)/256 of Deslauriers & Dubuc 1989") {
  check_same_mask(curve_mask(*curve("six-point")),
                  mask(2, -5, {3, 0, -25, 0, 150, 256, 150, 0, -25, 0, 3}, 256));
}

TEST_CASE("ternary-four-point: the rules of Hassan, Ivrissimtzis, Dodgson and Sabin (2002)") {
  for (double mu : {1.0 / 15, 1.0 / 11, 0.1, 1.0 / 9}) {
    CAPTURE(mu);
    const double a0 = -1.0 / 18 - mu / 6, a1 = 13.0 / 18 + mu / 2, a2 = 7.0 / 18 - mu / 2, a3 = -1.0 / 18 + mu / 6;
    // P_3i = P_i; P_3i+1 = a0 P_i-1 + a1 P_i + a2 P_i+1 + a3 P_i+2; P_3i+2 mirrored.
    // a_{r - 3 s} on old point i + s: r = 1: a_4 = a0, a_1 = a1, a_-2 = a2, a_-5 = a3.
    CurveMask expected{3, -5, std::vector<double>(11, 0.0)};
    auto set = [&](int i, double v) { expected.coefficients[size_t(i + 5)] = v; };
    set(0, 1.0);
    set(4, a0), set(1, a1), set(-2, a2), set(-5, a3);
    set(5, a3), set(2, a2), set(-1, a1), set(-4, a0);
    check_same_mask(curve_mask(*curve("ternary-four-point", {{"mu", fmt::format("{:.17g}", mu)}})), expected, 1e-14);
  }
}

TEST_CASE("ternary-bspline: mask 3((1 + z + z^2)/3)^3 = (1, 3, 6, 7, 6, 3, 1)/9") {
  check_same_mask(curve_mask(*curve("ternary-bspline")), mask(3, -3, {1, 3, 6, 7, 6, 3, 1}, 9), 1e-15);
}

TEST_CASE("tension-bspline: level l has the mask (1, 2 + 2a, 2 + 4a, 2 + 2a, 1)/(4 + 4a), a = alpha_{l+1} (Morin, Warren & Weimer 2001)") {
  for (double alpha0 : {-1.0, -0.5, 0.0, 0.5, 1.0, 10.0, 100.0}) {
    CAPTURE(alpha0);
    const auto scheme = curve("tension-bspline", {{"alpha0", fmt::format("{:.17g}", alpha0)}});
    double alpha = alpha0;
    for (int l = 0; l < 8; ++l) {
      CAPTURE(l);
      alpha = std::sqrt((1 + alpha) / 2);  // alpha_{l+1}, used by the step that makes level l + 1
      const double s = 4 + 4 * alpha;
      check_same_mask(curve_mask(*scheme, l), mask(2, -2, {1 / s, (2 + 2 * alpha) / s, (2 + 4 * alpha) / s,
                                                           (2 + 2 * alpha) / s, 1 / s}), 1e-14);
    }
  }
  // alpha0 = 1 keeps alpha_k = 1: the cubic B-spline at every level.
  const auto one = curve("tension-bspline", {{"alpha0", "1"}});
  for (int l = 0; l < 6; ++l) check_same_mask(curve_mask(*one, l), mask(2, -2, {1, 4, 6, 4, 1}, 8));
}

TEST_CASE("the smoothness the scheme files state holds by the symbol analysis (Dyn, Gregory & Levin 1991)") {
  auto smoothness = [](const CurveScheme& s) { return analyse_curve(curve_mask(s)).smoothness; };
  CHECK(smoothness(*curve("chaikin")) == 1);
  CHECK(smoothness(*curve("cubic-bspline")) == 2);
  for (int d = 1; d <= 6; ++d) CHECK(smoothness(*curve("bspline", {{"d", std::to_string(d)}})) == d - 1);
  CHECK(smoothness(*curve("two-point")) == 0);
  CHECK(smoothness(*curve("ternary-bspline")) == 1);
  // four-point: w in [0, 0.154508], just below (sqrt(5) - 1)/8 (Dyn, Gregory, Levin 1991); the
  // 1987 paper states smoothness for (0, 1/8). C1 for every w > 0 in the range, C0 at w = 0.
  CHECK(smoothness(*curve("four-point", {{"w", "0"}})) == 0);
  for (const char* w : {"0.01", "0.0625", "0.1", "0.125", "0.15", "0.154508"}) {
    CAPTURE(w);
    CHECK(smoothness(*curve("four-point", {{"w", w}})) == 1);
  }
  CHECK(smoothness(*curve("six-point")) >= 2);
  // ternary 4-point: C2 inside (1/15, 1/9), at least C1 at the bounds.
  for (const char* mu : {"0.07", "0.0909090909090909", "0.1", "0.11"}) {
    CAPTURE(mu);
    CHECK(smoothness(*curve("ternary-four-point", {{"mu", mu}})) == 2);
  }
  for (const char* mu : {"0.06666666666666667", "0.1111111111111111"}) {
    CAPTURE(mu);
    CHECK(smoothness(*curve("ternary-four-point", {{"mu", mu}})) >= 1);
  }
}

TEST_CASE("parameter ranges: values outside the validated ranges are refused with the range") {
  CHECK_THROWS_WITH_AS(load_curve("four-point", {{"w", "0.2"}}), doctest::Contains("outside its range"), Error);
  CHECK_THROWS_WITH_AS(load_curve("tension-bspline", {{"alpha0", "-1.5"}}), doctest::Contains("outside its range"),
                       Error);
  CHECK_THROWS_WITH_AS(load_curve("bspline", {{"d", "2.5"}}), doctest::Contains("not a whole number"), Error);
  CHECK_THROWS_WITH_AS(load_curve("chaikin", {{"w", "1"}}), doctest::Contains("no parameter 'w'"), Error);
}
