#pragma once
// Laurent polynomials in one variable: the symbol a(z) = sum_i a_i z^i of a curve mask
// (Dyn, Gregory & Levin 1991) and the symbols derived from it by exact division.
#include "framework/analysis/curve/curve_mask.h"

#include <complex>
#include <string>
#include <vector>

namespace subdiv {

struct LaurentPolynomial {
  int lowest = 0;                     // power of z of coefficients[0]
  std::vector<double> coefficients;   // z^lowest .. z^highest()

  int highest() const { return lowest + static_cast<int>(coefficients.size()) - 1; }
  double at(int power) const;         // zero outside the stored range
  std::complex<double> operator()(std::complex<double> z) const;
  double abs_sum() const;             // sum of |coefficients|, a scale for tolerances
};

// a(z) of the mask (Dyn, Gregory & Levin 1991).
LaurentPolynomial symbol(const CurveMask& mask);

LaurentPolynomial multiply(const LaurentPolynomial& p, const LaurentPolynomial& q);
LaurentPolynomial scaled(const LaurentPolynomial& p, double factor);
// p(z^m): the symbol of a scheme applied on a grid m times coarser.
LaurentPolynomial upsampled(const LaurentPolynomial& p, int m);

// Division by 1 + z + ... + z^{m-1}, the factor that links a scheme of arity m to its
// difference scheme, since (1 - z^m) = (1 - z)(1 + z + ... + z^{m-1}) (Dyn, Gregory
// & Levin 1991 for m = 2).
struct ExactDivision {
  bool exact = false;                 // remainder within tolerance
  double remainder = 0.0;             // max |remainder coefficient| / p.abs_sum()
  LaurentPolynomial quotient;         // meaningful only when exact
};

// p(z) / (1 + z + ... + z^{m-1}) by long division; exact when every remainder coefficient
// is at most relative_tolerance * p.abs_sum().
ExactDivision divide_by_difference_factor(const LaurentPolynomial& p, int arity,
                                          double relative_tolerance);

// "0.125 z^-2 + 0.5 z^-1 + 0.75 + 0.5 z + 0.125 z^2" (coefficients below 1e-15 of the
// largest are left out).
std::string to_string(const LaurentPolynomial& p);

}  // namespace subdiv
