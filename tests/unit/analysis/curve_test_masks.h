#pragma once
// Masks of known curve schemes for the analysis tests, built from their rules as the
// literature writes them (Chaikin 1974; Lane & Riesenfeld 1980; Dyn, Levin & Gregory 1987; Deslauriers & Dubuc 1989;
// Hassan et al. 2002).
#include "framework/analysis/curve/curve_mask.h"

#include <cmath>
#include <vector>

namespace subdiv::test {

inline double binomial(int n, int k) {
  double c = 1.0;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

// Degree-d uniform B-spline: c_i = 2^-d C(d+1, i), i = 0..d+1 (Lane & Riesenfeld 1980), centred.
inline CurveMask bspline_mask(int degree) {
  CurveMask mask;
  mask.arity = 2;
  mask.first = -(degree + 1) / 2;
  for (int i = 0; i <= degree + 1; ++i) mask.coefficients.push_back(binomial(degree + 1, i) / std::pow(2.0, degree));
  return mask;
}

// Chaikin 1974: v'_{2i} = 1/4 v_{i-1} + 3/4 v_i, v'_{2i+1} = 3/4 v_i + 1/4 v_{i+1}.
inline CurveMask chaikin_mask() { return mask_from_rules(2, {-1, 0}, {{0.25, 0.75}, {0.75, 0.25}}); }

// Lane & Riesenfeld 1980: even (1/8, 3/4, 1/8) on P_{i-1..i+1}, odd (1/2, 1/2) on P_{i..i+1}.
inline CurveMask cubic_bspline_mask() {
  return mask_from_rules(2, {-1, 0}, {{0.125, 0.75, 0.125}, {0.5, 0.5}});
}

// Dyn, Levin & Gregory 1987: P_{2i} = P_i, P_{2i+1} = -w(P_{i-1} + P_{i+2}) + (1/2 + w)(P_i + P_{i+1}).
inline CurveMask four_point_mask(double w) {
  return mask_from_rules(2, {0, -1}, {{1.0}, {-w, 0.5 + w, 0.5 + w, -w}});
}

// Deslauriers & Dubuc 1989: odd rule (3, -25, 150, 150, -25, 3)/256 on P_{i-2..i+3}.
inline CurveMask six_point_mask() {
  std::vector<double> odd{3, -25, 150, 150, -25, 3};
  for (double& x : odd) x /= 256.0;
  return mask_from_rules(2, {0, -2}, {{1.0}, odd});
}

// Ternary 4-point scheme of Hassan, Ivrissimtzis, Dodgson, Sabin (CAGD 19, 2002):
// P_{3i} = P_i, P_{3i+1} = a0 P_{i-1} + a1 P_i + a2 P_{i+1} + a3 P_{i+2}, P_{3i+2} mirrored,
// a0 = -1/18 - mu/6, a1 = 13/18 + mu/2, a2 = 7/18 - mu/2, a3 = -1/18 + mu/6.
inline CurveMask ternary_four_point_mask(double mu) {
  const double a0 = -1.0 / 18 - mu / 6, a1 = 13.0 / 18 + mu / 2;
  const double a2 = 7.0 / 18 - mu / 2, a3 = -1.0 / 18 + mu / 6;
  return mask_from_rules(3, {0, -1, -1}, {{1.0}, {a0, a1, a2, a3}, {a3, a2, a1, a0}});
}

// Ternary linear interpolation: (1/3, 2/3, 1, 2/3, 1/3) on -2..2.
inline CurveMask ternary_linear_mask() {
  return CurveMask{3, -2, {1.0 / 3, 2.0 / 3, 1.0, 2.0 / 3, 1.0 / 3}};
}

// B-spline of degree d and arity m: symbol m ((1 + z + ... + z^{m-1})/m)^(d+1).
inline CurveMask mary_bspline_mask(int arity, int degree) {
  std::vector<double> c{1.0};
  for (int k = 0; k <= degree; ++k) {
    std::vector<double> next(c.size() + static_cast<std::size_t>(arity - 1), 0.0);
    for (std::size_t i = 0; i < c.size(); ++i)
      for (std::size_t t = 0; t < static_cast<std::size_t>(arity); ++t) next[i + t] += c[i] / arity;
    c = next;
  }
  for (double& x : c) x *= arity;
  return CurveMask{arity, -static_cast<int>(c.size() - 1) / 2, c};
}

inline CurveMask ternary_bspline_mask(int degree) { return mary_bspline_mask(3, degree); }

}  // namespace subdiv::test
