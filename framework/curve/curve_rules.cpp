#include "framework/curve/curve_rules.h"

#include <cmath>
#include <fmt/format.h>

#include "framework/analysis/curve/variational_curve.h"
#include "framework/rules/formula.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

std::vector<double> evaluate_rule(FormulaSet& formulas, const std::vector<std::string>& weights,
                                  const std::string& where, int level) {
  std::vector<double> out;
  double sum = 0, magnitude = 0;
  for (size_t t = 0; t < weights.size(); ++t) {
    const std::string place = fmt::format("{}.w[{}]", where, t);
    const double w = formulas.evaluate(formulas.add(weights[t], place), {0, 0, double(t), double(level)});
    if (!std::isfinite(w))
      throw Error(fmt::format("{}: weight {} is {} at level {}", place, subdiv::quoted(weights[t]), w, level));
    out.push_back(w);
    sum += w, magnitude += std::abs(w);
  }
  if (std::abs(sum - 1.0) > 1e-9 * std::max(1.0, magnitude))
    throw Error(fmt::format("{}: weights sum to {} at level {}, not 1: a new point must be an affine "
                            "combination of old points", where, sum, level));
  return out;
}

}  // namespace

CurveRulesAtLevel evaluate_curve_rules(const CurveScheme& scheme, int level) {
  if (!scheme.variational() && (int(scheme.starts.size()) != scheme.arity || int(scheme.weights.size()) != scheme.arity))
    throw Error(fmt::format("{}: curve scheme {} has {} rules for arity {}", scheme.path, subdiv::quoted(scheme.name),
                            scheme.weights.size(), scheme.arity));
  FormulaSet formulas(scheme.parameters, scheme.definitions);
  CurveRulesAtLevel out;
  out.arity = scheme.arity;
  out.level = level;
  out.ends = scheme.ends;
  std::vector<int> variational_starts;
  std::vector<std::vector<double>> variational_weights;
  if (scheme.variational()) {
    const VariationalEnergy energy = variational_energy(scheme, level);
    variational_rules(energy, variational_starts, variational_weights);
    out.variational_alpha = energy.alpha;
    out.variational_r = energy.r;
  }
  for (int r = 0; r < scheme.arity; ++r) {
    const std::string where = fmt::format("{}: rules[{}]", scheme.path, r);
    std::vector<double> w = scheme.variational() ? variational_weights[size_t(r)]
                                                 : evaluate_rule(formulas, scheme.weights[r], where, level);
    int start = scheme.variational() ? variational_starts[size_t(r)] : scheme.starts[r];
    size_t lo = 0, hi = w.size();
    while (lo < hi && w[lo] == 0.0) ++lo;
    while (hi > lo && w[hi - 1] == 0.0) --hi;
    if (lo == hi) throw Error(fmt::format("{}: all weights are zero at level {}", where, level));
    start += int(lo);
    w = std::vector<double>(w.begin() + lo, w.begin() + hi);
    double offset = 0;
    for (size_t t = 0; t < w.size(); ++t) offset += w[t] * (start + int(t));
    out.starts.push_back(start);
    out.weights.push_back(std::move(w));
    out.offsets.push_back(offset);
  }
  if (scheme.ends == CurveEnds::Interpolate) out.end_rules = {{1.0}};
  for (size_t e = 0; e < scheme.end_rules.size(); ++e)
    out.end_rules.push_back(
        evaluate_rule(formulas, scheme.end_rules[e], fmt::format("{}: ends.rules[{}]", scheme.path, e), level));
  return out;
}

CurveMask curve_mask(const CurveScheme& scheme, int level) {
  const CurveRulesAtLevel rules = evaluate_curve_rules(scheme, level);
  return mask_from_rules(rules.arity, rules.starts, rules.weights);
}

}  // namespace subdiv
