#pragma once
// Contractivity of a difference scheme S_q: the search for L with ||S_q^L||_inf < 1,
// following the step-by-step algorithm of Dyn 1992, for any arity m.
#include "framework/analysis/curve/curve_laurent.h"

#include <cstddef>
#include <vector>

namespace subdiv {

// ||S||_inf of the scheme f_i <- sum_j s_{i - M j} f_j with symbol s(z) and dilation M:
// the largest sum of |s_i| over one residue class i mod M (Dyn 1992).
double scheme_norm(const LaurentPolynomial& s, long long dilation);

// The symbol of S_q^{L+1} from that of S_q^L: q_{L+1}(z) = q(z) q_L(z^m)
// (Dyn 1992 for m = 2; the same telescoping for any m).
LaurentPolynomial next_iterate(const LaurentPolynomial& q, const LaurentPolynomial& q_L, int arity);

struct ContractivitySearch {
  bool contractive = false;
  int power = 0;                  // smallest L with ||S_q^L||_inf < 1, when contractive
  int searched_up_to = 0;         // largest L whose norm was computed
  std::vector<double> norms;      // norms[L - 1] = ||S_q^L||_inf
  bool stopped_by_size = false;   // q_L outgrew the coefficient budget before max_power
};

struct ContractivityOptions {
  int max_power = 10;                       // largest power L tried (Dyn 1992's M)
  double margin = 1e-10;                    // prove only ||S_q^L|| < 1 - margin (round-off)
  std::size_t max_coefficients = 1u << 24;  // budget for q_L (it has ~ m^L coefficients)
};

// Tries L = 1 .. max_power and stops at the first L with ||S_q^L||_inf < 1 - margin.
ContractivitySearch find_contractive_power(const LaurentPolynomial& q, int arity,
                                           const ContractivityOptions& options);

}  // namespace subdiv
