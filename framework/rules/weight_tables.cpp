#include "framework/rules/weight_tables.h"

#include <algorithm>
#include <fmt/format.h>

#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

CompiledTerm compile_term(const Term& term, FormulaSet& formulas, int max_n, int max_k, int level) {
  CompiledTerm out;
  out.role = term.role;
  out.new_point = term.new_point;
  out.where = term.where;
  const int id = formulas.add(term.weight, term.where);
  const FormulaUses uses = formulas.uses(id);
  out.uses_n = uses.n, out.uses_k = uses.k, out.uses_j = uses.j;
  const int size_n = uses.n ? max_n + 1 : 1;
  out.size_k = uses.k ? max_k + 1 : 1;
  out.size_j = uses.j ? std::max(max_n, max_k) + 1 : 1;
  out.table.resize(size_t(size_n) * out.size_k * out.size_j);
  for (int n = 0; n < size_n; ++n)
    for (int k = 0; k < out.size_k; ++k)
      for (int j = 0; j < out.size_j; ++j)
        out.table[(size_t(n) * out.size_k + k) * out.size_j + j] =
            formulas.evaluate(id, {double(n), double(k), double(j), double(level)});
  return out;
}

CompiledRule compile_rule(const Rule& rule, FormulaSet& formulas, int max_n, int max_k, int level) {
  CompiledRule out;
  out.where = rule.where;
  out.defined = true;
  for (const Term& term : rule.terms) out.terms.push_back(compile_term(term, formulas, max_n, max_k, level));
  return out;
}

// The curve scheme's rule r as a Role::Curve term, evaluated at this level.
CompiledRule curve_rule(const CurveScheme& curve, int r, int level) {
  FormulaSet formulas(curve.parameters, curve.definitions);
  CompiledTerm term;
  term.role = Role::Curve;
  term.where = fmt::format("{}: rules[{}]", curve.path, r);
  term.curve_start = curve.starts[r];
  for (size_t t = 0; t < curve.weights[r].size(); ++t) {
    const int id = formulas.add(curve.weights[r][t], fmt::format("{}[{}]", term.where, t));
    term.curve_weights.push_back(formulas.evaluate(id, {0, 0, double(t), double(level)}));
  }
  CompiledRule out;
  out.where = term.where;
  out.defined = true;
  out.terms.push_back(std::move(term));
  return out;
}

CompiledRule corner_rule() {
  CompiledTerm self;
  self.role = Role::Self;
  self.where = "engine default corner rule";
  self.table = {1.0};
  CompiledRule out;
  out.where = self.where;
  out.defined = true;
  out.terms.push_back(std::move(self));
  return out;
}

}  // namespace

WeightTables prepare_weight_tables(const Scheme& scheme, int max_n, int max_k, int level) {
  WeightTables tables;
  tables.max_n = max_n, tables.max_k = max_k;
  FormulaSet formulas(scheme.parameter_values(), scheme.definitions);
  for (int e = 0; e < kElementCount; ++e)
    for (int c = 0; c < kContextCount; ++c)
      if (scheme.rules[e][c])
        tables.rules[e][c] = compile_rule(*scheme.rules[e][c], formulas, max_n, max_k, level);

  auto& vertex = tables.rules[int(Element::Vertex)];
  auto& edge = tables.rules[int(Element::Edge)];
  if (!vertex[int(Context::Dart)].defined) vertex[int(Context::Dart)] = vertex[int(Context::Smooth)];
  if (!vertex[int(Context::Corner)].defined) vertex[int(Context::Corner)] = corner_rule();
  if (scheme.curve) {
    if (!vertex[int(Context::Crease)].defined) vertex[int(Context::Crease)] = curve_rule(*scheme.curve, 0, level);
    if (!edge[int(Context::Crease)].defined) edge[int(Context::Crease)] = curve_rule(*scheme.curve, 1, level);
  }
  return tables;
}

}  // namespace subdiv
