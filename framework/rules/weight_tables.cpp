#include "framework/rules/weight_tables.h"

#include <algorithm>
#include <fmt/format.h>

#include "framework/util/error.h"

namespace subdiv {
namespace {

// Sizes and strides of the dense table over the variables a formula uses.
struct TableShape {
  size_t size = 1;
  int count[7] = {1, 1, 1, 1, 1, 1, 1};  // n, k, j, n0, n1, k0, k1
  size_t stride[7] = {0, 0, 0, 0, 0, 0, 0};
};

TableShape table_shape(const FormulaUses& uses, int max_n, int max_k, int max_j) {
  TableShape s;
  const bool used[7] = {uses.n, uses.k, uses.j, uses.n0, uses.n1, uses.k0, uses.k1};
  const int range[7] = {max_n + 1, max_k + 1, max_j + 1, max_n + 1, max_n + 1, max_k + 1, max_k + 1};
  for (int v = 6; v >= 0; --v) {
    if (!used[v]) continue;
    s.count[v] = range[v];
    s.stride[v] = s.size;
    s.size *= size_t(range[v]);
  }
  return s;
}

CompiledTerm compile_term(const Term& term, FormulaSet& formulas, int max_n, int max_k, int level) {
  CompiledTerm out;
  out.role = term.role;
  out.new_point = term.new_point;
  out.where = term.where;
  const int id = formulas.add(term.weight, term.where);
  int max_j = std::max(max_n, max_k);
  if (const RoleInfo* role = registered_role(term.role)) max_j = std::max(max_j, role->max_points(max_n, max_k) - 1);
  out.max_j = max_j;
  const TableShape shape = table_shape(formulas.uses(id), max_n, max_k, max_j);
  out.stride_n = shape.stride[0], out.stride_k = shape.stride[1], out.stride_j = shape.stride[2];
  out.stride_n0 = shape.stride[3], out.stride_n1 = shape.stride[4];
  out.stride_k0 = shape.stride[5], out.stride_k1 = shape.stride[6];
  out.table.resize(shape.size);
  const int* c = shape.count;
  for (int n = 0; n < c[0]; ++n)
    for (int k = 0; k < c[1]; ++k)
      for (int j = 0; j < c[2]; ++j)
        for (int n0 = 0; n0 < c[3]; ++n0)
          for (int n1 = 0; n1 < c[4]; ++n1)
            for (int k0 = 0; k0 < c[5]; ++k0)
              for (int k1 = 0; k1 < c[6]; ++k1)
                out.table[out.stride_n * n + out.stride_k * k + out.stride_j * j + out.stride_n0 * n0 +
                          out.stride_n1 * n1 + out.stride_k0 * k0 + out.stride_k1 * k1] =
                    formulas.evaluate(id, {double(n), double(k), double(j), double(level), double(n0), double(n1),
                                           double(k0), double(k1)});
  return out;
}

CompiledRule compile_rule(const Rule& rule, FormulaSet& formulas, int max_n, int max_k, int level) {
  CompiledRule out;
  out.where = rule.where;
  out.defined = true;
  for (const Term& term : rule.terms) out.terms.push_back(compile_term(term, formulas, max_n, max_k, level));
  return out;
}

}  // namespace

CompiledRule compile_curve_rule(const CurveRuleText& rule, const FormulaScope& scope, int level) {
  static const std::vector<NamedFormula> none;
  FormulaSet formulas(scope.parameters, scope.definitions ? *scope.definitions : none);
  CompiledTerm term;
  term.role = Role::Curve;
  term.where = rule.where;
  term.curve_start = rule.start;
  for (size_t t = 0; t < rule.weights.size(); ++t) {
    const int id = formulas.add(rule.weights[t], fmt::format("{}[{}]", term.where, t));
    term.curve_weights.push_back(formulas.evaluate(id, {0, 0, double(t), double(level)}));
  }
  CompiledRule out;
  out.where = term.where;
  out.defined = true;
  out.terms.push_back(std::move(term));
  return out;
}

CompiledRule stay_rule() {
  CompiledTerm self;
  self.role = Role::Self;
  self.where = "engine default: the point stays";
  self.table = {1.0};
  CompiledRule out;
  out.where = self.where;
  out.defined = true;
  out.terms.push_back(std::move(self));
  return out;
}

WeightTables compile_rule_table(const RuleTable& rules, const FormulaScope& scope, int max_n, int max_k, int level) {
  WeightTables tables;
  tables.max_n = max_n, tables.max_k = max_k;
  static const std::vector<NamedFormula> none;
  FormulaSet formulas(scope.parameters, scope.definitions ? *scope.definitions : none);
  for (int e = 0; e < kElementCount; ++e)
    for (int c = 0; c < kContextCount; ++c)
      if (rules[e][c]) tables.rules[e][c] = compile_rule(*rules[e][c], formulas, max_n, max_k, level);

  for (Element e : {Element::Vertex, Element::Corner}) {
    auto& r = tables.rules[int(e)];
    if (!r[int(Context::Dart)].defined) r[int(Context::Dart)] = r[int(Context::Smooth)];
    if (!r[int(Context::Corner)].defined) r[int(Context::Corner)] = stay_rule();
  }
  return tables;
}

}  // namespace subdiv
