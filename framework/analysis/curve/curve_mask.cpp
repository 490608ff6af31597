#include "framework/analysis/curve/curve_mask.h"

#include "framework/analysis/curve/curve_integer.h"
#include "framework/util/error.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace subdiv {

double CurveMask::at(int i) const {
  if (i < first || i > last()) return 0.0;
  return coefficients[static_cast<std::size_t>(i - first)];
}

void validate(const CurveMask& mask) {
  if (mask.arity < 2 || mask.arity > kMaxCurveArity)
    throw Error(fmt::format("curve mask: arity {} is invalid; use 2 (binary), 3 (ternary) or more, "
                            "at most {}", mask.arity, kMaxCurveArity));
  if (mask.coefficients.empty()) throw Error("curve mask: no coefficients; give at least one");
  for (std::size_t k = 0; k < mask.coefficients.size(); ++k)
    if (!std::isfinite(mask.coefficients[k]))
      throw Error(fmt::format("curve mask: coefficient a_{} is not a finite number",
                              mask.first + static_cast<int>(k)));
  const bool all_zero = std::all_of(mask.coefficients.begin(), mask.coefficients.end(),
                                    [](double c) { return c == 0.0; });
  if (all_zero) throw Error("curve mask: all coefficients are zero");
}

namespace {

void check_rules(int arity, const std::vector<int>& starts,
                 const std::vector<std::vector<double>>& weights) {
  if (arity < 2 || arity > kMaxCurveArity)
    throw Error(fmt::format("curve rules: arity {} is invalid; use 2 (binary), 3 (ternary) or more, "
                            "at most {}", arity, kMaxCurveArity));
  if (starts.size() != static_cast<std::size_t>(arity) ||
      weights.size() != static_cast<std::size_t>(arity))
    throw Error(fmt::format("curve rules: arity {} needs {} rules (one per new point m*i + r), "
                            "got {} starts and {} weight lists",
                            arity, arity, starts.size(), weights.size()));
  for (int r = 0; r < arity; ++r) {
    if (weights[r].empty())
      throw Error(fmt::format("curve rules: rule {} has no weights", r));
    for (double w : weights[r])
      if (!std::isfinite(w))
        throw Error(fmt::format("curve rules: rule {} has a weight that is not a finite number", r));
  }
}

// Mask index of weight t of rule r: a_{r - m (start_r + t)} (see the header).
int mask_index(int arity, int r, int start, int t) { return r - arity * (start + t); }

}  // namespace

CurveMask mask_from_rules(int arity, const std::vector<int>& starts,
                          const std::vector<std::vector<double>>& weights) {
  check_rules(arity, starts, weights);
  int lo = mask_index(arity, 0, starts[0], 0);
  int hi = lo;
  for (int r = 0; r < arity; ++r) {
    const int n = static_cast<int>(weights[r].size());
    hi = std::max(hi, mask_index(arity, r, starts[r], 0));          // largest index: t = 0
    lo = std::min(lo, mask_index(arity, r, starts[r], n - 1));      // smallest: last t
  }
  CurveMask mask;
  mask.arity = arity;
  mask.first = lo;
  mask.coefficients.assign(static_cast<std::size_t>(hi - lo + 1), 0.0);
  // Different (r, t) give different indices (distinct residues mod m, distinct t), so no
  // coefficient is written twice.
  for (int r = 0; r < arity; ++r)
    for (int t = 0; t < static_cast<int>(weights[r].size()); ++t)
      mask.coefficients[static_cast<std::size_t>(mask_index(arity, r, starts[r], t) - lo)] =
          weights[r][static_cast<std::size_t>(t)];
  return mask;
}

std::vector<CurveRule> rules_from_mask(const CurveMask& mask) {
  validate(mask);
  const int m = mask.arity;
  std::vector<CurveRule> rules(static_cast<std::size_t>(m));
  for (int r = 0; r < m; ++r) {
    // a_{r - m s} with first <= r - m s <= last  <=>  s in [ceil((r-last)/m), floor((r-first)/m)]
    int s_lo = ceil_div(r - mask.last(), m);
    int s_hi = floor_div(r - mask.first, m);
    while (s_lo <= s_hi && mask.at(r - m * s_lo) == 0.0) ++s_lo;
    while (s_hi >= s_lo && mask.at(r - m * s_hi) == 0.0) --s_hi;
    CurveRule& rule = rules[static_cast<std::size_t>(r)];
    if (s_lo > s_hi) continue;
    rule.start = s_lo;
    for (int s = s_lo; s <= s_hi; ++s) rule.weights.push_back(mask.at(r - m * s));
  }
  return rules;
}

CurveMask trimmed(const CurveMask& mask) {
  validate(mask);
  const auto& c = mask.coefficients;
  std::size_t lo = 0, hi = c.size();
  while (c[lo] == 0.0) ++lo;           // validate() guarantees a non-zero coefficient
  while (c[hi - 1] == 0.0) --hi;
  CurveMask out;
  out.arity = mask.arity;
  out.first = mask.first + static_cast<int>(lo);
  out.coefficients.assign(c.begin() + static_cast<std::ptrdiff_t>(lo),
                          c.begin() + static_cast<std::ptrdiff_t>(hi));
  return out;
}

}  // namespace subdiv
