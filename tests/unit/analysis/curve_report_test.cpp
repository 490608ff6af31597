// The text summary and the JSON form of a curve analysis.
#include "framework/analysis/curve/curve_analysis.h"
#include "curve_report.h"
#include "unit/analysis/curve_test_masks.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

using namespace subdiv;

namespace {

bool has_line(const std::string& text, const std::string& line) {
  return text.find(line + "\n") != std::string::npos;
}

}  // namespace

TEST_CASE("curve report: cubic B-spline summary states one fact per line") {
  const std::string s = curve_summary(analyse_curve(test::cubic_bspline_mask()));
  CAPTURE(s);
  CHECK(has_line(s, "a(1) = 2 ok"));
  CHECK(has_line(s, "a(-1) = 0 ok"));
  CHECK(has_line(s, "symbol a(z) = 0.125 z^-2 + 0.5 z^-1 + 0.75 + 0.5 z + 0.125 z^2"));
  CHECK(has_line(s, "contractive difference scheme at L=1 (norm 0.5) -> C0"));
  CHECK(has_line(s, "C2 proven (L=1); C3 not proven up to L=10"));
  CHECK(has_line(s, "eigenvalues: 1, 0.5, 0.25, 0.125, 0.125"));
  CHECK(has_line(s, "limit mask on points -2..2: 0, 0.166667, 0.666667, 0.166667, 0"));
}

TEST_CASE("curve report: 4-point summary and a failing mask") {
  const std::string s = curve_summary(analyse_curve(test::four_point_mask(1.0 / 16)));
  CAPTURE(s);
  CHECK(has_line(s, "C1 proven (L=2); C2 not proven up to L=10"));
  CHECK(has_line(s, "eigenvalues: 1, 0.5, 0.25, 0.25, 0.125, -0.0625, -0.0625"));

  const std::string bad = curve_summary(analyse_curve(CurveMask{2, 0, {0.6, 0.5, 0.6, 0.3}}));
  CAPTURE(bad);
  CHECK(has_line(bad, "a(-1) = 0.4 FAILS (must be 0)"));
  CHECK(has_line(bad, "not convergent: necessary condition a(-1) = 0 fails"));

  const std::string linear = curve_summary(analyse_curve(test::four_point_mask(0.0)));
  CAPTURE(linear);
  CHECK(has_line(linear, "C0 proven (L=1); C1 not proven up to L=10"));
  CHECK(has_line(linear, "C2: symbol has no factor (1+z)^3 (relative remainder 1)"));
}

TEST_CASE("curve report: ternary summary names the roots of unity") {
  const std::string s = curve_summary(analyse_curve(test::ternary_linear_mask()));
  CAPTURE(s);
  CHECK(has_line(s, "w = exp(2 pi i/3)"));
  CHECK(has_line(s, "a(1) = 3 ok"));
  CHECK(has_line(s, "a(w) = 0 ok"));
  CHECK(has_line(s, "a(w^2) = 0 ok"));
  CHECK(has_line(s, "C0 proven (L=1); C1 not proven up to L=10"));
}

TEST_CASE("curve report: JSON carries the verdicts and the numbers") {
  const nlohmann::json j = curve_json(analyse_curve(test::four_point_mask(1.0 / 16)));
  CHECK(j["arity"] == 2);
  CHECK(j["mask"]["first"] == -3);
  CHECK(j["convergent"] == true);
  CHECK(j["smoothness"] == 1);
  CHECK(j["max_L"] == 10);
  CHECK(j["levels"][1]["L"] == 2);
  CHECK(j["levels"][2]["proven"] == false);
  CHECK(j["levels"][2]["L"].is_null());
  CHECK(j["necessary_conditions"][1]["name"] == "a(-1)");
  CHECK(j["necessary_conditions"][1]["holds"] == true);
  CHECK(j["local"]["eigenvalues"].size() == 7);
  CHECK(j["local"]["eigenvalues"][1][0].get<double>() == doctest::Approx(0.5));
  CHECK(j["local"]["limit_mask"].size() == 7);
  CHECK(j["verdict"] == "C1 proven (L=2); C2 not proven up to L=10");
  // Round trip through text.
  CHECK(nlohmann::json::parse(j.dump()) == j);
}

TEST_CASE("curve report: unproven convergence and a degenerate mask") {
  CurveAnalysisOptions options;
  options.contractivity.max_power = 1;  // w = 0.3 needs L = 2 (norm 1.1 at L = 1)
  const std::string s = curve_summary(analyse_curve(test::four_point_mask(0.3), options));
  CAPTURE(s);
  CHECK(has_line(s, "C0: difference scheme not contractive up to L=1 (last norm 1.1)"));
  CHECK(has_line(s, "convergence not proven up to L=1"));

  // One coefficient at index 1, arity 3: no control point has a basis function at t = 0.
  const CurveAnalysis d = analyse_curve(CurveMask{3, 1, {3.0}});
  CHECK(d.local_matrix.size() == 0);
  CHECK(d.eigen.eigenvalues.empty());
  CHECK_FALSE(d.necessary_conditions_hold);
  CHECK(has_line(curve_summary(d), "no invariant neighbourhood (degenerate mask)"));
}
