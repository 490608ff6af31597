// Curve schemes read from JSON and analysed (Zorin et al. 2000; Dyn, Gregory & Levin 1991): B-splines of degree m are
// C^(m-1); the 4-point scheme with w = 1/16 is C1 and not proven C2; a mask with
// a(-1) != 0 does not converge; the local eigenvalues of the cubic B-spline and the 4-point
// scheme are the known ones (Zorin et al. 2000).
#include <doctest/doctest.h>

#include "framework/analysis/curve/curve_analysis.h"
#include "framework/analysis/curve/curve_mask.h"
#include "framework/util/error.h"

#include <nlohmann/json.hpp>

#include "framework/analysis/curve/curve_scheme_analysis.h"
#include "curve_report.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

void check_eigenvalues(const CurveAnalysis& a, const std::vector<double>& seed) {
  REQUIRE(a.eigen.eigenvalues.size() == seed.size());
  for (size_t i = 0; i < seed.size(); ++i) CHECK(std::abs(a.eigen.eigenvalues[i] - seed[i]) < 1e-7);
}

}  // namespace

TEST_CASE("curve schemes from JSON: the known verdicts and eigenvalues") {
  const auto cubic = analyse_curve_scheme(*load_curve_scheme_named("cubic-bspline"));
  CHECK(cubic.analysis.smoothness == 2);  // degree 3: C2
  CHECK_FALSE(cubic.level_dependent);
  check_eigenvalues(cubic.analysis, {1, 0.5, 0.25, 0.125, 0.125});
  // The cubic B-spline's limit point (P_{-1} + 4 P_0 + P_1)/6.
  REQUIRE(cubic.analysis.eigen.has_limit_mask);
  CHECK(cubic.analysis.eigen.limit_mask[1] == doctest::Approx(1.0 / 6));
  CHECK(cubic.analysis.eigen.limit_mask[2] == doctest::Approx(4.0 / 6));

  const auto chaikin = analyse_curve_scheme(*load_curve_scheme_named("chaikin"));
  CHECK(chaikin.analysis.smoothness == 1);  // degree 2: C1

  const auto four = analyse_curve_scheme(*load_curve_scheme_named("four-point", {{"w", "0.0625"}}));
  CHECK(four.analysis.smoothness == 1);  // C1, C2 not proven
  check_eigenvalues(four.analysis, {1, 0.5, 0.25, 0.25, 0.125, -0.0625, -0.0625});

  const auto ternary = analyse_curve_scheme(*load_curve_scheme_named("ternary-cubic-bspline"));
  CHECK(ternary.analysis.mask.arity == 3);
  CHECK(ternary.analysis.smoothness == 2);
}

TEST_CASE("curve schemes from JSON: a user file with a(-1) != 0 does not converge") {
  // Even rule sums to 1.2, odd rule to 0.8: a(1) = 2 but a(-1) = 0.4.
  const auto file = write_temp("bad-curve.json", R"({"name": "bad", "kind": "curve", "arity": 2, "rules": [
      {"start": -1, "w": ["0.3", "0.9"]}, {"start": 0, "w": ["0.4", "0.4"]}]})");
  CHECK(scheme_kind_of(file.string()) == "curve");
  // Loading refuses it with the reason (each rule must be affine: a(1) = 2 and a(-1) = 0).
  CHECK_THROWS_WITH_AS(load_curve_scheme_named(file.string()), doctest::Contains("weights sum to 1.2"), Error);
  // The mask itself, analysed: the necessary condition a(-1) = 0 fails.
  const CurveAnalysis r = analyse_curve(mask_from_rules(2, {-1, 0}, {{0.3, 0.9}, {0.4, 0.4}}));
  CHECK_FALSE(r.necessary_conditions_hold);
  CHECK_FALSE(r.convergent);
  CHECK(curve_summary(r).find("not convergent: necessary condition a(-1) = 0 fails") != std::string::npos);
}

TEST_CASE("curve schemes from JSON: level-dependent weights are flagged non-stationary") {
  // Like the non-stationary tension scheme (Morin, Warren & Weimer 2001); here a weight that depends on l.
  const auto file = write_temp("tension.json", R"json({"name": "tension", "kind": "curve", "arity": 2, "rules": [
      {"start": 0, "w": ["1"]}, {"start": -1, "w": ["-1/(16*(l+1))", "1/2 + 1/(16*(l+1))", "1/2 + 1/(16*(l+1))", "-1/(16*(l+1))"]}]})json");
  const auto curve = load_curve_scheme_named(file.string());
  CHECK(curve_scheme_is_level_dependent(*curve));
  const auto r0 = analyse_curve_scheme(*curve, 0);
  CHECK(r0.level_dependent);
  CHECK(r0.analysis.mask.at(-3) == doctest::Approx(-1.0 / 16));
  const auto r1 = analyse_curve_scheme(*curve, 1);
  CHECK(r1.analysis.mask.at(-3) == doctest::Approx(-1.0 / 32));
  CHECK(curve_scheme_summary(r0).find("non-stationary") != std::string::npos);
  CHECK(curve_scheme_json(r0)["stationary"] == false);
}
