// Variational interpolatory curve schemes (Kobbelt 1996, "A variational approach to
// subdivision", CAGD 13(8)): the new points minimise E = sum_i K(P_i)^2 over the refined
// polygon with the old points fixed. Checked against an independent dense least-squares
// solve of the whole energy, and by the properties the paper proves for the second
// difference K(P_i) = P_{i-1} - 2 P_i + P_{i+1}: interpolation, cubic reproduction on uniform
// data, and a C2 limit.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <complex>

#include "curve_test_support.h"
#include "framework/analysis/curve/curve_scheme_analysis.h"
#include "framework/analysis/curve/variational_curve.h"
#include "framework/scheme/scheme_loader.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

std::shared_ptr<const CurveScheme> variational(const std::string& alpha, int r) {
  return load_curve_scheme_text(fmt::format(R"({{"name": "v", "kind": "curve", "variational": {{"alpha": {}, "r": {}}}}})",
                                            alpha, r),
                                "v.json", {}, nullptr);
}

// Independent of the engine: the refined polygon's energy matrix M (E = |M P|^2) written
// out from the definition, and the new points that minimise it for fixed old points by a
// dense least-squares solve (QR), one column of coordinates at a time.
Eigen::MatrixXd dense_minimiser(const std::vector<double>& alpha, int r, const Eigen::MatrixXd& old, bool closed) {
  const long n = old.rows(), size = closed ? 2 * n : 2 * n - 1, s = long(alpha.size()) - 1;
  std::vector<std::vector<double>> rows;
  for (long i = 0; i < size; ++i) {
    std::vector<double> row(size_t(size), 0.0);
    bool inside = true;
    for (long j = 0; j <= s; ++j) {
      long f = i + j - r;
      if (closed) f = ((f % size) + size) % size;
      else if (f < 0 || f >= size) inside = false;
      if (inside) row[size_t(f)] += alpha[size_t(j)];
    }
    if (inside) rows.push_back(row);
  }
  const long unknowns = closed ? n : n - 1;
  Eigen::MatrixXd on_new = Eigen::MatrixXd::Zero(long(rows.size()), unknowns);
  Eigen::MatrixXd on_old = Eigen::MatrixXd::Zero(long(rows.size()), n);
  for (size_t q = 0; q < rows.size(); ++q)
    for (long f = 0; f < size; ++f)
      (f % 2 ? on_new(long(q), f / 2) : on_old(long(q), f / 2)) += rows[q][size_t(f)];
  return on_new.colPivHouseholderQr().solve(-on_old * old);
}

Eigen::MatrixXd as_matrix(const std::vector<double>& xyz) {
  Eigen::MatrixXd m(long(xyz.size() / 3), 3);
  for (long i = 0; i < m.rows(); ++i)
    for (int c = 0; c < 3; ++c) m(i, c) = xyz[size_t(3 * i + c)];
  return m;
}

// The refined points of one step, in polyline order (old, new, old, ...).
std::vector<double> one_step(const CurveScheme& scheme, const std::vector<double>& points, bool closed) {
  return refine_polyline(scheme, points, closed, 1).positions[1];
}

}  // namespace

TEST_CASE("variational second difference: new points minimise the energy (dense least squares), old points stay") {
  const auto scheme = variational("[1, -2, 1]", 1);
  for (bool closed : {true, false})
    for (int n : {3, 7, 20}) {
      CAPTURE(closed);
      CAPTURE(n);
      const std::vector<double> points = wiggly_points(n);
      const std::vector<double> refined = one_step(*scheme, points, closed);
      REQUIRE(long(refined.size()) == 3 * (closed ? 2 * n : 2 * n - 1));
      const Eigen::MatrixXd expected = dense_minimiser({1, -2, 1}, 1, as_matrix(points), closed);
      for (long i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) CHECK(refined[size_t(3 * 2 * i + c)] == points[size_t(3 * i + c)]);  // kept exactly
        if (!closed && i == n - 1) break;
        for (int c = 0; c < 3; ++c)
          CHECK(refined[size_t(3 * (2 * i + 1) + c)] == doctest::Approx(expected(i, c)).epsilon(1e-12));
      }
    }
}

TEST_CASE("variational third difference (alpha = -1, 3, -3, 1): the normal equations hold at round-off") {
  const std::vector<double> alpha = {-1, 3, -3, 1};
  const auto scheme = variational("[-1, 3, -3, 1]", 2);
  for (bool closed : {true, false}) {
    CAPTURE(closed);
    const std::vector<double> points = wiggly_points(11);
    const std::vector<double> refined = one_step(*scheme, points, closed);
    const Eigen::MatrixXd expected = dense_minimiser(alpha, 2, as_matrix(points), closed);
    for (long i = 0; i + (closed ? 0 : 1) < 11; ++i)
      for (int c = 0; c < 3; ++c)
        CHECK(refined[size_t(3 * (2 * i + 1) + c)] == doctest::Approx(expected(i, c)).epsilon(1e-11));
  }
}

TEST_CASE("variational: long polylines (windowed rules) equal the whole solve to round-off") {
  const VariationalEnergy e{2, {1, -2, 1}, 1, "v.json"};
  for (bool closed : {true, false}) {
    CAPTURE(closed);
    const long n = 2 * kVariationalWindow + 37;
    const std::vector<double> points = wiggly_points(int(n));
    const std::vector<double> refined = one_step(*variational("[1, -2, 1]", 1), points, closed);
    const Eigen::MatrixXd expected = dense_minimiser(e.alpha, 1, as_matrix(points), closed);
    double worst = 0;
    for (long i = 0; i + (closed ? 0 : 1) < n; ++i)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(refined[size_t(3 * (2 * i + 1) + c)] - expected(i, c)));
    CHECK(worst < 1e-11);
  }
}

TEST_CASE("variational second difference reproduces cubics on uniform data and keeps lines straight to the ends") {
  const auto scheme = variational("[1, -2, 1]", 1);
  const long n = 40;
  std::vector<double> cubic, line;
  auto f = [](double x) { return 0.3 - x + 0.7 * x * x - 1.1 * x * x * x; };
  for (long i = 0; i < n; ++i) {
    const double x = double(i) / n;
    cubic.insert(cubic.end(), {x, f(x), 0.0});
    line.insert(line.end(), {x, 2 * x - 1, 3 - x});
  }
  // Closed-form cubic reproduction away from an open polyline's ends (the natural end
  // conditions bend it there; the energy's solution decays by 3 - 2 sqrt 2 per point).
  const std::vector<double> refined = one_step(*scheme, cubic, false);
  for (long i = 15; i < n - 16; ++i) {
    const double x = (i + 0.5) / n;
    CHECK(refined[size_t(3 * (2 * i + 1) + 1)] == doctest::Approx(f(x)).epsilon(1e-10));
  }
  const std::vector<double> straight = one_step(*scheme, line, false);
  for (long i = 0; i + 1 < n; ++i) {
    const double x = (i + 0.5) / n;
    CHECK(straight[size_t(3 * (2 * i + 1))] == doctest::Approx(x).epsilon(1e-12));
    CHECK(straight[size_t(3 * (2 * i + 1) + 1)] == doctest::Approx(2 * x - 1).epsilon(1e-12));
    CHECK(straight[size_t(3 * (2 * i + 1) + 2)] == doctest::Approx(3 - x).epsilon(1e-12));
  }
}

TEST_CASE("variational-cubic: symbol (1+z)^4 z^-2 / (z^2 + 6 + z^-2), interpolatory, C2 by symbol analysis") {
  const auto scheme = load_curve("variational-cubic");
  const CurveSchemeAnalysis a = analyse_curve_scheme(*scheme);
  // Normal equations of the second difference at new point 2i+1 (Kobbelt 1996):
  // Q_{i-1} + 6 Q_i + Q_{i+1} = 4 (p_i + p_{i+1}), so a(z) (z^2 + 6 + z^-2) = (1 + z)^4 z^-2.
  for (double t : {0.1, 0.7, 1.3, 2.9}) {
    const std::complex<double> z = std::polar(1.0, t);
    std::complex<double> symbol = 0;
    for (size_t i = 0; i < a.analysis.mask.coefficients.size(); ++i)
      symbol += a.analysis.mask.coefficients[i] * std::pow(z, a.analysis.mask.first + int(i));
    const std::complex<double> expected = std::pow(1.0 + z, 4) / (z * z) / (z * z + 6.0 + 1.0 / (z * z));
    CHECK(std::abs(symbol - expected) < 1e-14);
  }
  CHECK(a.analysis.mask.at(0) == 1.0);
  for (int k : {2, 4, -2, -4}) CHECK(a.analysis.mask.at(k) == 0.0);  // interpolatory: even coefficients vanish
  CHECK(a.analysis.convergent);
  CHECK(a.analysis.smoothness == 2);
}

TEST_CASE("variational schemes refused where they cannot work") {
  CHECK_THROWS_WITH_AS(variational("[1, -2, 2]", 1), doctest::Contains("sum to"), Error);
  CHECK_THROWS_WITH_AS(variational("[1, -2, 1]", 3), doctest::Contains("variational.r"), Error);
  CHECK_THROWS_WITH_AS(load_curve_scheme_text(R"({"name": "v", "kind": "curve", "variational": {"alpha": [1, -2, 1], "r": 1}, "ends": "uniform"})", "v.json", {}, nullptr),
                       doctest::Contains("energy decides the ends"), Error);
  CHECK_THROWS_WITH_AS(load_scheme_text(R"({"name": "s", "split": "triangle", "curve": "variational-cubic",
      "rules": {"edge": [{"sum": "ends", "w": "1/2"}], "vertex": [{"at": "self", "w": "1"}]}})", "s.json"),
                       doctest::Contains("variational"), Error);
}
