#include "framework/scheme/step_tables.h"

#include <fmt/format.h>

namespace subdiv {
namespace {

// The curve a step's boundaries and creases follow: a split that names its own curve
// follows it; otherwise the scheme's curve, in one-step schemes only.
const CurveScheme* feature_curve(const Scheme& scheme, const StepRules& step) {
  if (step.curve) return step.curve.get();
  return step.curve_rules_apply ? scheme.curve.get() : nullptr;
}

void add_curve_rules(WeightTables& tables, const CurveScheme& curve, int level) {
  const FormulaScope scope{curve.parameters, &curve.definitions};
  tables.curve_arity = curve.arity;
  for (int r = 0; r < curve.arity; ++r)
    tables.curve_rules.push_back(
        compile_curve_rule({curve.starts[r], curve.weights[r], fmt::format("{}: rules[{}]", curve.path, r)}, scope, level));
}

// In schemes with smoothing passes the curve scheme describes the result of the whole
// level: the split's features follow its own (linear) smooth rules unless it names its own
// curve, and a smoothing pass without a stated crease rule leaves feature vertices where
// they are.
void default_crease_rules(WeightTables& tables, const StepRules& step) {
  for (Element e : {Element::Vertex, Element::Edge, Element::Corner}) {
    auto& r = tables.rules[int(e)];
    if (r[int(Context::Crease)].defined) continue;
    r[int(Context::Crease)] = step.is_split || e != Element::Vertex ? r[int(Context::Smooth)] : stay_rule();
  }
}

}  // namespace

WeightTables step_weight_tables(const Scheme& scheme, const StepRules& step, int max_n, int max_k, int level,
                                const std::map<std::string, double>* parameters, const LevelValences* present) {
  WeightTables tables = compile_rule_table(
      step.rules, {parameters ? *parameters : scheme.parameter_values(), &scheme.definitions, present}, max_n, max_k,
      level);
  if (!step.crease_ends.empty())
    tables.crease_ends = compile_crease_end_rules(
        step.crease_ends, {parameters ? *parameters : scheme.parameter_values(), &scheme.definitions, present}, max_n,
        max_k, level);
  if (const CurveScheme* curve = feature_curve(scheme, step)) add_curve_rules(tables, *curve, level);
  if (!step.curve_rules_apply && !step.curve) default_crease_rules(tables, step);
  return tables;
}

bool has_feature_rules(const Scheme& scheme) {
  if (scheme.curve) return true;
  for (const StepRules& step : scheme.steps) {
    if (step.curve || (step.code && step.code->handles_features)) return true;
    for (const auto& by_context : step.rules)
      if (by_context[int(Context::Crease)]) return true;
  }
  return false;
}

}  // namespace subdiv
