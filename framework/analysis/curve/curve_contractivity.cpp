#include "framework/analysis/curve/curve_contractivity.h"

#include "framework/analysis/curve/curve_integer.h"
#include "framework/util/error.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace subdiv {

double scheme_norm(const LaurentPolynomial& s, long long dilation) {
  const long long size = static_cast<long long>(s.coefficients.size());
  if (size == 0) return 0.0;
  if (dilation >= size) {
    // Powers lowest .. lowest + size - 1 span less than the dilation: every coefficient is
    // alone in its residue class, so the norm is the largest |s_i|.
    double largest = 0.0;
    for (double c : s.coefficients) largest = std::max(largest, std::abs(c));
    return largest;
  }
  std::vector<double> sums(static_cast<std::size_t>(dilation), 0.0);
  for (long long i = 0; i < size; ++i) {
    const long long power = static_cast<long long>(s.lowest) + i;
    sums[static_cast<std::size_t>(positive_mod(power, dilation))] +=
        std::abs(s.coefficients[static_cast<std::size_t>(i)]);
  }
  return *std::max_element(sums.begin(), sums.end());
}

LaurentPolynomial next_iterate(const LaurentPolynomial& q, const LaurentPolynomial& q_L, int arity) {
  // q(z) q_L(z^m): coefficient i of q meets coefficient j of q_L at power i + m j.
  LaurentPolynomial r;
  const std::size_t m = static_cast<std::size_t>(arity);
  r.lowest = q.lowest + arity * q_L.lowest;
  r.coefficients.assign((q_L.coefficients.size() - 1) * m + q.coefficients.size(), 0.0);
  for (std::size_t j = 0; j < q_L.coefficients.size(); ++j) {
    const double b = q_L.coefficients[j];
    if (b == 0.0) continue;
    for (std::size_t i = 0; i < q.coefficients.size(); ++i)
      r.coefficients[i + m * j] += q.coefficients[i] * b;
  }
  return r;
}

ContractivitySearch find_contractive_power(const LaurentPolynomial& q, int arity,
                                           const ContractivityOptions& options) {
  if (arity < 2) throw Error(fmt::format("contractivity: arity {} is invalid", arity));
  if (options.max_power < 1)
    throw Error(fmt::format("contractivity: the largest power L must be at least 1, got {}",
                            options.max_power));
  ContractivitySearch out;
  if (q.coefficients.empty()) return out;
  LaurentPolynomial q_L = q;   // Step 4: q_1 = q
  long long dilation = arity;  // m^L
  for (int L = 1; L <= options.max_power; ++L) {
    const double norm = scheme_norm(q_L, dilation);  // Step 5(a)
    out.norms.push_back(norm);
    out.searched_up_to = L;
    if (norm < 1.0 - options.margin) {               // Step 5(b)
      out.contractive = true;
      out.power = L;
      return out;
    }
    if (L == options.max_power) break;
    const std::size_t next_size = (q_L.coefficients.size() - 1) * static_cast<std::size_t>(arity) +
                                  q.coefficients.size();
    if (next_size > options.max_coefficients) {
      out.stopped_by_size = true;
      break;
    }
    q_L = next_iterate(q, q_L, arity);               // Step 5(c)
    // Past the coefficient count the exact dilation no longer matters (every coefficient
    // is alone in its class), so saturate instead of overflowing.
    dilation = dilation > std::numeric_limits<long long>::max() / arity
                   ? std::numeric_limits<long long>::max()
                   : dilation * arity;
  }
  return out;                                        // Step 6: not proven up to L
}

}  // namespace subdiv
