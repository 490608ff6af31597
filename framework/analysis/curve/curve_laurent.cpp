#include "framework/analysis/curve/curve_laurent.h"

#include "framework/util/error.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace subdiv {

double LaurentPolynomial::at(int power) const {
  if (power < lowest || power > highest()) return 0.0;
  return coefficients[static_cast<std::size_t>(power - lowest)];
}

std::complex<double> LaurentPolynomial::operator()(std::complex<double> z) const {
  // Horner on the ordinary polynomial, then the factor z^lowest.
  std::complex<double> sum = 0.0;
  for (auto it = coefficients.rbegin(); it != coefficients.rend(); ++it) sum = sum * z + *it;
  return sum * std::pow(z, lowest);
}

double LaurentPolynomial::abs_sum() const {
  double s = 0.0;
  for (double c : coefficients) s += std::abs(c);
  return s;
}

LaurentPolynomial symbol(const CurveMask& mask) {
  return LaurentPolynomial{mask.first, mask.coefficients};
}

LaurentPolynomial multiply(const LaurentPolynomial& p, const LaurentPolynomial& q) {
  LaurentPolynomial r;
  if (p.coefficients.empty() || q.coefficients.empty()) return r;
  r.lowest = p.lowest + q.lowest;
  r.coefficients.assign(p.coefficients.size() + q.coefficients.size() - 1, 0.0);
  for (std::size_t i = 0; i < p.coefficients.size(); ++i)
    for (std::size_t j = 0; j < q.coefficients.size(); ++j)
      r.coefficients[i + j] += p.coefficients[i] * q.coefficients[j];
  return r;
}

LaurentPolynomial scaled(const LaurentPolynomial& p, double factor) {
  LaurentPolynomial r = p;
  for (double& c : r.coefficients) c *= factor;
  return r;
}

LaurentPolynomial upsampled(const LaurentPolynomial& p, int m) {
  LaurentPolynomial r;
  if (p.coefficients.empty()) return r;
  r.lowest = p.lowest * m;
  r.coefficients.assign((p.coefficients.size() - 1) * static_cast<std::size_t>(m) + 1, 0.0);
  for (std::size_t i = 0; i < p.coefficients.size(); ++i)
    r.coefficients[i * static_cast<std::size_t>(m)] = p.coefficients[i];
  return r;
}

ExactDivision divide_by_difference_factor(const LaurentPolynomial& p, int arity,
                                          double relative_tolerance) {
  const std::size_t d = static_cast<std::size_t>(arity - 1);  // degree of the divisor
  ExactDivision out;
  const double scale = p.abs_sum();
  if (p.coefficients.size() <= d || scale == 0.0) {
    out.remainder = 1.0;  // nothing to divide: a non-zero constant remainder
    return out;
  }
  // Long division by the monic divisor 1 + z + ... + z^d, from the top coefficient down.
  std::vector<double> rest = p.coefficients;
  std::vector<double> q(rest.size() - d, 0.0);
  for (std::size_t k = q.size(); k-- > 0;) {
    q[k] = rest[k + d];
    for (std::size_t t = 0; t <= d; ++t) rest[k + t] -= q[k];
  }
  double worst = 0.0;
  for (std::size_t t = 0; t < d; ++t) worst = std::max(worst, std::abs(rest[t]));
  out.remainder = worst / scale;
  out.exact = out.remainder <= relative_tolerance;
  out.quotient = LaurentPolynomial{p.lowest, std::move(q)};
  return out;
}

namespace {

std::string power_text(int power) {
  if (power == 0) return "";
  if (power == 1) return " z";
  return fmt::format(" z^{}", power);
}

}  // namespace

std::string to_string(const LaurentPolynomial& p) {
  double largest = 0.0;
  for (double c : p.coefficients) largest = std::max(largest, std::abs(c));
  std::string text;
  for (std::size_t i = 0; i < p.coefficients.size(); ++i) {
    const double c = p.coefficients[i];
    if (std::abs(c) <= 1e-15 * largest || c == 0.0) continue;
    const int power = p.lowest + static_cast<int>(i);
    if (text.empty())
      text = fmt::format("{:.10g}", c);
    else
      text += fmt::format(" {} {:.10g}", c < 0 ? '-' : '+', std::abs(c));
    text += power_text(power);
  }
  return text.empty() ? "0" : text;
}

}  // namespace subdiv
