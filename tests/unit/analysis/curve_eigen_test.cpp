// Local subdivision matrices and their eigen-analysis (Zorin et al. 2000).
#include "framework/analysis/curve/curve_analysis.h"
#include "framework/analysis/curve/curve_eigen.h"
#include "framework/analysis/curve/curve_local_matrix.h"
#include "unit/analysis/curve_test_masks.h"

#include <doctest/doctest.h>

using namespace subdiv;

namespace {

void check_eigenvalues(const LocalEigenAnalysis& e, const std::vector<double>& expected) {
  REQUIRE(e.eigenvalues.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    CAPTURE(i);
    // Defective eigenvalues (Jordan blocks) are only accurate to ~sqrt(machine epsilon).
    CHECK(e.eigenvalues[i].real() == doctest::Approx(expected[i]).epsilon(1e-6));
    CHECK(std::abs(e.eigenvalues[i].imag()) < 1e-6);
  }
}

void check_vector(const std::vector<double>& v, const std::vector<double>& expected) {
  REQUIRE(v.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    CAPTURE(i);
    CHECK(v[i] == doctest::Approx(expected[i]).epsilon(1e-9));
  }
}

}  // namespace

TEST_CASE("curve local matrix: cubic B-spline matrix is the known 5x5 (Zorin et al. 2000)") {
  const LocalSubdivisionMatrix s = local_subdivision_matrix(test::cubic_bspline_mask());
  CHECK(s.first_index == -2);
  REQUIRE(s.size() == 5);
  const double expected[5][5] = {{1, 6, 1, 0, 0}, {0, 4, 4, 0, 0}, {0, 1, 6, 1, 0},
                                 {0, 0, 4, 4, 0}, {0, 0, 1, 6, 1}};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      CHECK(s.rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] == doctest::Approx(expected[i][j] / 8));
}

TEST_CASE("curve local matrix: 4-point matrix is the known 7x7 (Zorin et al. 2000)") {
  const LocalSubdivisionMatrix s = local_subdivision_matrix(test::four_point_mask(1.0 / 16));
  CHECK(s.first_index == -3);
  REQUIRE(s.size() == 7);
  const double expected[7][7] = {{-1, 9, 9, -1, 0, 0, 0}, {0, 0, 16, 0, 0, 0, 0}, {0, -1, 9, 9, -1, 0, 0},
                                 {0, 0, 0, 16, 0, 0, 0},  {0, 0, -1, 9, 9, -1, 0}, {0, 0, 0, 0, 16, 0, 0},
                                 {0, 0, 0, -1, 9, 9, -1}};
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      CHECK(s.rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] == doctest::Approx(expected[i][j] / 16));
}

TEST_CASE("curve eigen: cubic B-spline eigenvalues, limit and tangent masks (Halstead, Kass & DeRose 1993)") {
  const CurveAnalysis r = analyse_curve(test::cubic_bspline_mask());
  check_eigenvalues(r.eigen, {1, 0.5, 0.25, 0.125, 0.125});
  REQUIRE(r.eigen.has_limit_mask);
  check_vector(r.eigen.limit_mask, {0, 1.0 / 6, 2.0 / 3, 1.0 / 6, 0});
  REQUIRE(r.eigen.has_tangent_mask);
  CHECK(r.eigen.subdominant.real() == doctest::Approx(0.5));
  check_vector(r.eigen.tangent_mask, {0, -0.5, 0, 0.5, 0});  // B-spline derivative at a knot
  CHECK(r.eigen.indication.find("lambda1^2 = |lambda2| > |lambda3|") == 0);
}

TEST_CASE("curve eigen: 4-point (w = 1/16) eigenvalues (Zorin et al. 2000)") {
  const CurveAnalysis r = analyse_curve(test::four_point_mask(1.0 / 16));
  check_eigenvalues(r.eigen, {1, 0.5, 0.25, 0.25, 0.125, -0.0625, -0.0625});
  REQUIRE(r.eigen.has_limit_mask);
  check_vector(r.eigen.limit_mask, {0, 0, 0, 1, 0, 0, 0});  // interpolatory
  REQUIRE(r.eigen.has_tangent_mask);
  // Tangent of the 4-point limit at a vertex: it reproduces cubics, so the mask is exact on
  // P_j = j (1) and on P_j = j^2 (0, symmetric) and on P_j = j^3 (0).
  double on_j = 0, on_j2 = 0, on_j3 = 0;
  for (std::size_t k = 0; k < 7; ++k) {
    const double j = static_cast<double>(static_cast<int>(k) - 3);
    on_j += r.eigen.tangent_mask[k] * j;
    on_j2 += r.eigen.tangent_mask[k] * j * j;
    on_j3 += r.eigen.tangent_mask[k] * j * j * j;
  }
  CHECK(on_j == doctest::Approx(1.0));
  CHECK(on_j2 == doctest::Approx(0.0));
  CHECK(on_j3 == doctest::Approx(0.0));
  CHECK(r.eigen.indication.find("lambda1^2 = |lambda2| = |lambda3|") == 0);
}

TEST_CASE("curve eigen: Chaikin around index 0 and the ternary linear scheme") {
  const CurveAnalysis chaikin = analyse_curve(test::chaikin_mask());
  CHECK(chaikin.local_matrix.size() == 4);  // points -2..1: support [-1, 2] of phi
  CHECK(chaikin.eigen.eigenvalues.at(0).real() == doctest::Approx(1.0));
  CHECK(chaikin.eigen.eigenvalues.at(1).real() == doctest::Approx(0.5));
  REQUIRE(chaikin.eigen.has_limit_mask);
  double sum = 0.0;
  for (double x : chaikin.eigen.limit_mask) sum += x;
  CHECK(sum == doctest::Approx(1.0));

  // Piecewise linear: lambda_1 = lambda_2 = 1/3, so no tangent (Halstead, Kass & DeRose 1993).
  const CurveAnalysis linear = analyse_curve(test::ternary_linear_mask());
  check_eigenvalues(linear.eigen, {1, 1.0 / 3, 1.0 / 3});
  CHECK(linear.eigen.has_limit_mask);
  CHECK_FALSE(linear.eigen.has_tangent_mask);
}

TEST_CASE("curve eigen: ternary 4-point subdominant eigenvalue is 1/3") {
  const CurveAnalysis r = analyse_curve(test::ternary_four_point_mask(1.0 / 11));
  CHECK(r.eigen.eigenvalues.at(0).real() == doctest::Approx(1.0));
  CHECK(r.eigen.subdominant.real() == doctest::Approx(1.0 / 3));
  CHECK(r.eigen.has_tangent_mask);
}
