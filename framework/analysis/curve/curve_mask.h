#pragma once
// The mask of a linear, stationary, uniform curve subdivision scheme of arity m, and its
// conversion from and to the per-point rules a scheme author writes.
//
// Index convention (Dyn, Gregory & Levin 1991, generalised to arity m):
//
//     P^{k+1}_i = sum_j a_{i - m j} P^k_j .
//
// Old point j sits at parameter j, new point i at parameter i/m (in units of the old
// spacing), so new point m*j + 0 lies on old point j. The refinable function then satisfies
// phi(t) = sum_i a_i phi(m t - i) and the limit curve is sum_j P_j phi(t - j).
//
// A rule r (0 <= r < m) gives the new point m*i + r from old points i + start_r + t,
// t = 0, 1, ..., with weights w_{r,t}. Comparing with the formula above,
//
//     a_{r - m (start_r + t)} = w_{r,t} .
//
// Example (Lane & Riesenfeld 1980, cubic B-spline, m = 2): even rule start -1, (1/8, 3/4, 1/8); odd
// rule start 0, (1/2, 1/2). This gives a_2 = a_{-2} = 1/8, a_0 = 3/4, a_1 = a_{-1} = 1/2,
// i.e. the mask (1, 4, 6, 4, 1)/8 on indices -2..2.
#include <vector>

namespace subdiv {

// Larger arities are refused: no scheme in use comes near, and the analysis allocates
// per residue class.
inline constexpr int kMaxCurveArity = 64;

struct CurveMask {
  int arity = 2;                      // m: new points per old point (2 binary, 3 ternary)
  int first = 0;                      // index of coefficients[0]
  std::vector<double> coefficients;   // a_first .. a_{first + size - 1}

  int last() const { return first + static_cast<int>(coefficients.size()) - 1; }
  double at(int i) const;             // a_i, zero outside the stored range
};

// One rule of a curve scheme: weights on old points i + start, i + start + 1, ...
struct CurveRule {
  int start = 0;
  std::vector<double> weights;
};

// Throws subdiv::Error unless 2 <= arity <= kMaxCurveArity and the mask is non-empty,
// finite and not all zero.
void validate(const CurveMask& mask);

// Builds the mask from the rules (see the convention above): rule r has weights[r] on old
// points i + starts[r] + t. Throws subdiv::Error on a wrong number of rules, an empty rule
// or a non-finite weight.
CurveMask mask_from_rules(int arity, const std::vector<int>& starts,
                          const std::vector<std::vector<double>>& weights);

// The inverse: the m rules of the mask, each trimmed of zero weights at both ends (an
// all-zero rule comes back with no weights).
std::vector<CurveRule> rules_from_mask(const CurveMask& mask);

// The same mask without zero coefficients at either end.
CurveMask trimmed(const CurveMask& mask);

}  // namespace subdiv
