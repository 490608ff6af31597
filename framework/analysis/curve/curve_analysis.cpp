#include "framework/analysis/curve/curve_analysis.h"

#include "framework/analysis/curve/curve_integer.h"
#include "framework/util/error.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace subdiv {

namespace {

std::string root_name(int arity, int k) {
  if (arity == 2) return "a(-1)";
  return k == 1 ? "a(w)" : fmt::format("a(w^{})", k);
}

// Dyn, Gregory & Levin 1991's necessary conditions, for arity m.
std::vector<NecessaryCondition> necessary_conditions(const CurveAnalysis& r, double tolerance) {
  const int m = r.mask.arity;
  const double scale = std::max(1.0, r.symbol.abs_sum());
  std::vector<NecessaryCondition> out;
  NecessaryCondition one{"a(1)", r.symbol(1.0), static_cast<double>(m), false};
  out.push_back(one);
  for (int k = 1; k < m; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / m;
    const std::complex<double> w = (m == 2) ? std::complex<double>(-1.0, 0.0) : std::polar(1.0, angle);
    out.push_back({root_name(m, k), r.symbol(w), 0.0, false});
  }
  for (auto& c : out) c.holds = std::abs(c.value - c.expected) <= tolerance * scale;
  return out;
}

std::vector<double> sub_mask_sums(const CurveMask& mask) {
  std::vector<double> sums(static_cast<std::size_t>(mask.arity), 0.0);
  for (int i = mask.first; i <= mask.last(); ++i)
    sums[static_cast<std::size_t>(positive_mod(i, mask.arity))] += mask.at(i);
  return sums;
}

// Levels k = 0, 1, ... of the header: divide b_k by σ, test q_k = b_k/σ, b_{k+1} = m q_k.
std::vector<SmoothnessLevel> smoothness_levels(const LaurentPolynomial& a, int arity,
                                               const CurveAnalysisOptions& options) {
  std::vector<SmoothnessLevel> levels;
  LaurentPolynomial b = a;
  for (int k = 0;; ++k) {
    SmoothnessLevel level;
    level.order = k;
    const ExactDivision division = divide_by_difference_factor(b, arity, options.division_tolerance);
    level.factor_divides = division.exact;
    level.remainder = division.remainder;
    if (!division.exact) {
      levels.push_back(std::move(level));
      return levels;  // no factor: neither this level nor any higher one can be shown
    }
    level.difference_symbol = division.quotient;
    level.contractivity = find_contractive_power(division.quotient, arity, options.contractivity);
    b = scaled(division.quotient, static_cast<double>(arity));
    levels.push_back(std::move(level));
  }
}

void check_options(const CurveAnalysisOptions& options) {
  if (options.contractivity.max_power < 1)
    throw Error(fmt::format("curve analysis: the largest power L must be at least 1, got {}",
                            options.contractivity.max_power));
  if (!(options.division_tolerance >= 0.0) || !(options.condition_tolerance >= 0.0))
    throw Error("curve analysis: tolerances must be non-negative numbers");
}

}  // namespace

CurveAnalysis analyse_curve(const CurveMask& mask, const CurveAnalysisOptions& options) {
  validate(mask);
  check_options(options);
  CurveAnalysis r;
  r.mask = mask;
  r.symbol = symbol(mask);
  r.max_power = options.contractivity.max_power;
  r.conditions = necessary_conditions(r, options.condition_tolerance);
  r.sub_mask_sums = sub_mask_sums(mask);
  r.necessary_conditions_hold = true;
  for (const auto& c : r.conditions) r.necessary_conditions_hold = r.necessary_conditions_hold && c.holds;
  if (r.necessary_conditions_hold) {  // Dyn 1992's algorithm stops here otherwise
    r.levels = smoothness_levels(r.symbol, mask.arity, options);
    r.convergent = r.levels.front().proven();
    // C^(k+1) implies C^k, so the largest proven level is the smoothness, even past a gap.
    for (const auto& level : r.levels)
      if (level.proven()) r.smoothness = level.order;
  }
  r.local_matrix = local_subdivision_matrix(mask);
  r.eigen = analyse_local_matrix(r.local_matrix);
  return r;
}

}  // namespace subdiv
