// Laurent polynomials and the norms of iterated difference schemes (Dyn, Gregory & Levin 1991; Dyn 1992).
#include "framework/analysis/curve/curve_contractivity.h"
#include "framework/analysis/curve/curve_laurent.h"
#include "unit/analysis/curve_test_masks.h"

#include <cmath>
#include <doctest/doctest.h>

using namespace subdiv;

TEST_CASE("curve symbol: evaluation, product and upsampling") {
  const LaurentPolynomial a = symbol(test::cubic_bspline_mask());
  CHECK(a.lowest == -2);
  CHECK(a(1.0).real() == doctest::Approx(2.0));
  CHECK(std::abs(a(-1.0)) < 1e-15);
  const LaurentPolynomial p{-1, {1.0, 2.0}};  // z^-1 + 2
  const LaurentPolynomial pp = multiply(p, p);  // z^-2 + 4 z^-1 + 4
  CHECK(pp.lowest == -2);
  CHECK(pp.at(-2) == 1.0);
  CHECK(pp.at(-1) == 4.0);
  CHECK(pp.at(0) == 4.0);
  const LaurentPolynomial up = upsampled(p, 3);  // z^-3 + 2
  CHECK(up.lowest == -3);
  CHECK(up.at(0) == 2.0);
  CHECK(up.at(-1) == 0.0);
}

TEST_CASE("curve symbol: exact division by 1+z and 1+z+z^2") {
  // Dyn, Gregory & Levin 1991: the 4-point q(z) = a(z)/(1+z).
  const double w = 0.1;
  const ExactDivision d = divide_by_difference_factor(symbol(test::four_point_mask(w)), 2, 1e-12);
  REQUIRE(d.exact);
  CHECK(d.quotient.lowest == -3);
  const std::vector<double> q{-w, w, 0.5, 0.5, w, -w};  // z^-3 .. z^2
  REQUIRE(d.quotient.coefficients.size() == q.size());
  for (std::size_t i = 0; i < q.size(); ++i) CHECK(d.quotient.coefficients[i] == doctest::Approx(q[i]));

  const ExactDivision t = divide_by_difference_factor(symbol(test::ternary_linear_mask()), 3, 1e-12);
  REQUIRE(t.exact);  // (1 + z + z^2)^2 / 3 z^2
  CHECK(t.quotient.at(-2) == doctest::Approx(1.0 / 3));
  CHECK(t.quotient.at(0) == doctest::Approx(1.0 / 3));

  CHECK_FALSE(divide_by_difference_factor(LaurentPolynomial{0, {1.0, 2.0}}, 2, 1e-12).exact);
  CHECK_FALSE(divide_by_difference_factor(LaurentPolynomial{0, {2.0}}, 2, 1e-12).exact);
}

TEST_CASE("curve symbol: text form") {
  CHECK(to_string(LaurentPolynomial{-1, {0.5, 1.0, -0.5}}) == "0.5 z^-1 + 1 - 0.5 z");
  CHECK(to_string(LaurentPolynomial{0, {0.0}}) == "0");
}

TEST_CASE("curve contractivity: ||S_q|| of the 4-point scheme is 1/2 + 2|w|") {
  for (double w : {-0.2, 0.0, 1.0 / 16, 0.2}) {
    const auto q = divide_by_difference_factor(symbol(test::four_point_mask(w)), 2, 1e-12).quotient;
    CHECK(scheme_norm(q, 2) == doctest::Approx(0.5 + 2 * std::abs(w)));
  }
}

TEST_CASE("curve contractivity: ||S_q^2|| of the 4-point scheme matches its closed form (lecture notes \"Subdivision curves and surfaces\" §7)") {
  for (double w : {-0.3, 0.05, 0.3}) {
    const auto q = divide_by_difference_factor(symbol(test::four_point_mask(w)), 2, 1e-12).quotient;
    const double n2 = scheme_norm(next_iterate(q, q, 2), 4);
    const double first = std::abs(0.5 + w) * std::abs(w) + std::abs(0.25 + w * w - 0.5 * w) +
                         std::abs(w) * std::abs(1 + w) + w * w;
    const double second = std::abs(w) * std::abs(w - 0.5) + std::abs(0.25 + 0.5 * w - w * w) + 2 * w * w;
    CHECK(n2 == doctest::Approx(std::max(first, second)));
  }
}

TEST_CASE("curve contractivity: the L search reports the first contractive power") {
  ContractivityOptions options;
  // w = 0.3: ||S_q|| = 1.1 but ||S_q^2|| < 1 since 0.3 < (-1 + sqrt 13)/8 (from the closed form above).
  const auto q = divide_by_difference_factor(symbol(test::four_point_mask(0.3)), 2, 1e-12).quotient;
  const ContractivitySearch s = find_contractive_power(q, 2, options);
  CHECK(s.contractive);
  CHECK(s.power == 2);
  CHECK(s.norms[0] == doctest::Approx(1.1));
  // q = 1 (symbol of the degree-1 B-spline's divided differences): norm 1 for every L.
  const ContractivitySearch one = find_contractive_power(LaurentPolynomial{0, {1.0}}, 2, options);
  CHECK_FALSE(one.contractive);
  CHECK(one.searched_up_to == 10);
  CHECK(one.norms.back() == doctest::Approx(1.0));
}

TEST_CASE("curve contractivity: the coefficient budget stops the search early") {
  ContractivityOptions options;
  options.max_coefficients = 100;
  const ContractivitySearch s = find_contractive_power(LaurentPolynomial{0, {1.0, 0.5}}, 3, options);
  CHECK_FALSE(s.contractive);
  CHECK(s.stopped_by_size);
  CHECK(s.searched_up_to < 10);
}
