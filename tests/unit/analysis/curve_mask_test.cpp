// Mask <-> rules conversion and its index convention (curve_mask.h).
#include "framework/analysis/curve/curve_mask.h"
#include "framework/util/error.h"
#include "unit/analysis/curve_test_masks.h"

#include <doctest/doctest.h>

using namespace subdiv;

namespace {

void check_mask(const CurveMask& mask, int first, const std::vector<double>& expected) {
  CHECK(mask.first == first);
  REQUIRE(mask.coefficients.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) CHECK(mask.coefficients[i] == doctest::Approx(expected[i]));
}

}  // namespace

TEST_CASE("curve mask: cubic B-spline rules give (1,4,6,4,1)/8 centred on 0") {
  check_mask(test::cubic_bspline_mask(), -2, {0.125, 0.5, 0.75, 0.5, 0.125});
}

TEST_CASE("curve mask: Chaikin rules give (1,3,3,1)/4 on -1..2") {
  check_mask(test::chaikin_mask(), -1, {0.25, 0.75, 0.75, 0.25});
}

TEST_CASE("curve mask: 4-point rules give the mask of Dyn, Levin & Gregory 1987") {
  const double w = 1.0 / 16;
  // a_0 = 1, a_{+-1} = 1/2 + w, a_{+-2} = 0, a_{+-3} = -w
  check_mask(test::four_point_mask(w), -3, {-w, 0.0, 0.5 + w, 1.0, 0.5 + w, 0.0, -w});
}

TEST_CASE("curve mask: a_i is the weight of P_j in P'_{i + m j}") {
  // Apply the mask formula P'_i = sum_j a_{i - 2j} P_j and the rules to the same data.
  const CurveMask mask = test::cubic_bspline_mask();
  const std::vector<double> p{3.0, -1.0, 4.0, 1.0, 5.0, 9.0, 2.0};  // P_0 .. P_6
  for (int i = 2; i <= 4; ++i) {
    double even = 0.0, odd = 0.0;
    for (int j = 0; j < 7; ++j) {
      even += mask.at(2 * i - 2 * j) * p[static_cast<std::size_t>(j)];
      odd += mask.at(2 * i + 1 - 2 * j) * p[static_cast<std::size_t>(j)];
    }
    const auto P = [&](int j) { return p[static_cast<std::size_t>(j)]; };
    CHECK(even == doctest::Approx(P(i - 1) / 8 + 0.75 * P(i) + P(i + 1) / 8));
    CHECK(odd == doctest::Approx(0.5 * P(i) + 0.5 * P(i + 1)));
  }
}

TEST_CASE("curve mask: rules_from_mask inverts mask_from_rules") {
  const auto rules = rules_from_mask(test::four_point_mask(1.0 / 16));
  REQUIRE(rules.size() == 2);
  CHECK(rules[0].start == 0);
  REQUIRE(rules[0].weights.size() == 1);  // the zero a_{+-2} are trimmed away
  CHECK(rules[0].weights[0] == doctest::Approx(1.0));
  CHECK(rules[1].start == -1);
  REQUIRE(rules[1].weights.size() == 4);
  CHECK(rules[1].weights[0] == doctest::Approx(-1.0 / 16));
  CHECK(rules[1].weights[1] == doctest::Approx(9.0 / 16));

  const CurveMask ternary = test::ternary_four_point_mask(0.1);
  std::vector<int> starts;
  std::vector<std::vector<double>> weights;
  for (const auto& r : rules_from_mask(ternary)) {
    starts.push_back(r.start);
    weights.push_back(r.weights);
  }
  const CurveMask again = mask_from_rules(3, starts, weights);
  CHECK(again.first == ternary.first);
  REQUIRE(again.coefficients.size() == ternary.coefficients.size());
  for (std::size_t i = 0; i < again.coefficients.size(); ++i)
    CHECK(again.coefficients[i] == doctest::Approx(ternary.coefficients[i]));
}

TEST_CASE("curve mask: trimmed drops zero ends") {
  const CurveMask t = trimmed(CurveMask{2, -3, {0.0, 0.5, 1.0, 0.5, 0.0, 0.0}});
  CHECK(t.first == -2);
  CHECK(t.coefficients.size() == 3);
}

TEST_CASE("curve mask: invalid input throws subdiv::Error") {
  CHECK_THROWS_AS(mask_from_rules(1, {0}, {{1.0}}), Error);
  CHECK_THROWS_AS(mask_from_rules(2, {0}, {{1.0}}), Error);
  CHECK_THROWS_AS(mask_from_rules(2, {0, 0}, {{1.0}, {}}), Error);
  CHECK_THROWS_AS(mask_from_rules(2, {0, 0}, {{1.0}, {std::nan("")}}), Error);
  CHECK_THROWS_AS(validate(CurveMask{2, 0, {}}), Error);
  CHECK_THROWS_AS(validate(CurveMask{2, 0, {0.0, 0.0}}), Error);
  CHECK_THROWS_AS(validate(CurveMask{0, 0, {1.0}}), Error);
  CHECK_THROWS_AS(validate(CurveMask{kMaxCurveArity + 1, 0, {1.0}}), Error);
  CHECK_THROWS_WITH_AS(mask_from_rules(3, {0, 0}, {{1.0}, {1.0}}),
                       doctest::Contains("needs 3 rules"), Error);
}
