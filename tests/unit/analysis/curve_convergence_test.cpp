// Convergence and smoothness verdicts of analyse_curve against known mathematics
// (Dyn, Gregory & Levin 1991; Dyn 1992; Dyn-Levin 2002; Hassan et al. 2002).
#include "framework/analysis/curve/curve_analysis.h"
#include "framework/util/error.h"
#include "unit/analysis/curve_test_masks.h"

#include <doctest/doctest.h>

using namespace subdiv;

namespace {

int proof_power(const CurveAnalysis& r, int order) {
  return r.levels.at(static_cast<std::size_t>(order)).contractivity.power;
}

}  // namespace

TEST_CASE("curve analysis: degree-d B-splines are exactly C^(d-1) by the algorithm") {
  // Dyn 1992: a(z) = (1+z)^(d+1)/2^d; b_{d-1} = (1+z)^2/2 converges (norm 1/2);
  // b_d = 1 + z gives q = 1 (norm 1 for every L); b_{d+1} = 2 has no factor (1+z).
  for (int d = 1; d <= 6; ++d) {
    CAPTURE(d);
    const CurveAnalysis r = analyse_curve(test::bspline_mask(d));
    CHECK(r.necessary_conditions_hold);
    CHECK(r.convergent);
    CHECK(r.smoothness == d - 1);
    CHECK(proof_power(r, d - 1) == 1);
    REQUIRE(r.levels.size() == static_cast<std::size_t>(d + 2));
    const SmoothnessLevel& cd = r.levels[static_cast<std::size_t>(d)];
    CHECK(cd.factor_divides);
    CHECK_FALSE(cd.contractivity.contractive);
    CHECK(cd.contractivity.searched_up_to == 10);
    CHECK(cd.contractivity.norms.back() == doctest::Approx(1.0));
    CHECK_FALSE(r.levels.back().factor_divides);
  }
}

TEST_CASE("curve analysis: Chaikin is C1, cubic B-spline is C2") {
  CHECK(analyse_curve(test::chaikin_mask()).smoothness == 1);
  CHECK(analyse_curve(test::cubic_bspline_mask()).smoothness == 2);
}

TEST_CASE("curve analysis: 4-point scheme w = 1/16 is C1 proven, C2 not (Dyn, Gregory & Levin 1991)") {
  const CurveAnalysis r = analyse_curve(test::four_point_mask(1.0 / 16));
  CHECK(r.convergent);
  CHECK(proof_power(r, 0) == 1);  // ||S_q|| = 1/2 + 2/16 < 1
  CHECK(r.smoothness == 1);
  CHECK(proof_power(r, 1) == 2);  // ||S_r|| >= 1 but ||S_r^2|| < 1 for 0 < w < 0.154
  // t(z) = 4a/(1+z)^3: ||S_t^L|| = 1 for all L.
  const SmoothnessLevel& c2 = r.levels.at(2);
  CHECK(c2.factor_divides);
  CHECK_FALSE(c2.contractivity.contractive);
  for (double n : c2.contractivity.norms) CHECK(n == doctest::Approx(1.0));
}

TEST_CASE("curve analysis: 4-point scheme in the tension range of Dyn, Gregory & Levin 1991 is C1") {
  // Dyn, Gregory & Levin 1991: ||S_r^2|| < 1 for 0 < w < (-1 + sqrt 5)/8, so L <= 2 proves C1.
  for (double w : {0.01, 0.05, 0.1, 0.125, 0.15}) {
    CAPTURE(w);
    const CurveAnalysis r = analyse_curve(test::four_point_mask(w));
    CHECK(r.smoothness >= 1);
    CHECK(proof_power(r, 1) <= 2);
  }
  // From the closed form of ||S_q^2|| (curve_symbol_test.cpp): < 1 for -3/8 < w < (-1 + sqrt 13)/8: convergence by L = 2.
  for (double w : {-0.3, -0.1, 0.2, 0.3}) {
    CAPTURE(w);
    const CurveAnalysis r = analyse_curve(test::four_point_mask(w));
    CHECK(r.convergent);
    CHECK(proof_power(r, 0) <= 2);
  }
}

TEST_CASE("curve analysis: 4-point scheme with w = 0 is linear interpolation, C0 not C1") {
  const CurveAnalysis r = analyse_curve(test::four_point_mask(0.0));
  CHECK(r.convergent);
  CHECK(r.smoothness == 0);
  CHECK_FALSE(r.levels.at(1).contractivity.contractive);  // q = 1
  CHECK_FALSE(r.levels.at(2).factor_divides);             // b_2 = 2: no factor (1+z)
}

TEST_CASE("curve analysis: 6-point scheme is C2 (Weissman 1990) and the algorithm finds it") {
  const CurveAnalysis r = analyse_curve(test::six_point_mask());
  CHECK(r.convergent);
  CHECK(r.smoothness == 2);
  CHECK(proof_power(r, 2) == 2);
}

TEST_CASE("curve analysis: a mask with a(-1) != 0 fails the necessary condition") {
  // a(1) = 2 but the even and odd sub-masks sum to 1.2 and 0.8.
  const CurveAnalysis r = analyse_curve(CurveMask{2, 0, {0.6, 0.5, 0.6, 0.3}});
  CHECK(r.conditions.at(0).holds);
  CHECK_FALSE(r.conditions.at(1).holds);
  CHECK(r.conditions.at(1).value.real() == doctest::Approx(0.4));
  CHECK_FALSE(r.necessary_conditions_hold);
  CHECK_FALSE(r.convergent);
  CHECK(r.smoothness == -1);
  CHECK(r.levels.empty());
  CHECK(r.sub_mask_sums.at(0) == doctest::Approx(1.2));
}

TEST_CASE("curve analysis: a(1) != m fails even when the difference scheme contracts") {
  // Half the linear B-spline: (1+z)^2/4 has q = (1+z)/4, contractive, yet a(1) = 1.
  const CurveAnalysis r = analyse_curve(CurveMask{2, -1, {0.25, 0.5, 0.25}});
  CHECK_FALSE(r.conditions.at(0).holds);
  CHECK_FALSE(r.convergent);
  CHECK(r.smoothness == -1);
}

TEST_CASE("curve analysis: ternary linear scheme is C0, not C1") {
  const CurveAnalysis r = analyse_curve(test::ternary_linear_mask());
  REQUIRE(r.conditions.size() == 3);
  CHECK(r.conditions[0].value.real() == doctest::Approx(3.0));
  CHECK(r.conditions[1].name == "a(w)");
  CHECK(r.conditions[2].name == "a(w^2)");
  CHECK(r.necessary_conditions_hold);
  for (double s : r.sub_mask_sums) CHECK(s == doctest::Approx(1.0));
  CHECK(r.convergent);
  CHECK(proof_power(r, 0) == 1);          // q = (1 + z + z^2)/3 z^2: norm 1/3
  CHECK(r.smoothness == 0);
  CHECK_FALSE(r.levels.at(1).contractivity.contractive);  // q_1 = 1
}

TEST_CASE("curve analysis: ternary B-splines of degree d are C^(d-1)") {
  for (int d = 1; d <= 4; ++d) {
    CAPTURE(d);
    const CurveAnalysis r = analyse_curve(test::ternary_bspline_mask(d));
    CHECK(r.convergent);
    CHECK(r.smoothness == d - 1);
  }
}

TEST_CASE("curve analysis: quaternary B-splines of degree d are C^(d-1)") {
  for (int d = 1; d <= 3; ++d) {
    CAPTURE(d);
    const CurveAnalysis r = analyse_curve(test::mary_bspline_mask(4, d));
    CHECK(r.necessary_conditions_hold);
    CHECK(r.smoothness == d - 1);
  }
}

TEST_CASE("curve analysis: ternary 4-point scheme is C2 for 1/15 < mu < 1/9 (Hassan et al. 2002)") {
  for (double mu : {0.07, 1.0 / 11, 0.1, 0.11}) {
    CAPTURE(mu);
    const CurveAnalysis r = analyse_curve(test::ternary_four_point_mask(mu));
    CHECK(r.necessary_conditions_hold);
    CHECK(r.smoothness == 2);
  }
  // Outside that range the algorithm proves C1 only (it is a sufficient condition).
  const CurveAnalysis r = analyse_curve(test::ternary_four_point_mask(0.2));
  CHECK(r.smoothness == 1);
}

TEST_CASE("curve analysis: a ternary mask with a wrong sub-mask fails a(w) = 0") {
  CurveMask mask = test::ternary_linear_mask();
  mask.coefficients[1] += 0.1;  // a_{-1}: sub-mask 2 sums to 1.1
  mask.coefficients[2] -= 0.1;  // a_0: sub-mask 0 sums to 0.9, a(1) stays 3
  const CurveAnalysis r = analyse_curve(mask);
  CHECK(r.conditions[0].holds);
  CHECK_FALSE(r.conditions[1].holds);
  CHECK_FALSE(r.conditions[2].holds);
  CHECK_FALSE(r.convergent);
}

TEST_CASE("curve analysis: invalid input throws subdiv::Error") {
  CHECK_THROWS_AS(analyse_curve(CurveMask{2, 0, {}}), Error);
  CurveAnalysisOptions options;
  options.contractivity.max_power = 0;
  CHECK_THROWS_AS(analyse_curve(test::cubic_bspline_mask(), options), Error);
}

TEST_CASE("curve analysis: a smaller L limit is respected") {
  CurveAnalysisOptions options;
  options.contractivity.max_power = 1;
  // The 4-point C1 proof needs L = 2.
  const CurveAnalysis r = analyse_curve(test::four_point_mask(1.0 / 16), options);
  CHECK(r.smoothness == 0);
  CHECK(r.levels.at(1).contractivity.searched_up_to == 1);
}
