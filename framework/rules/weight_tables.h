#pragma once
// Rules ready for stencil building on one level: every weight formula evaluated once for
// each valence n, face size k, point index j and end valences n0, n1 the level can ask
// for, stored densely so the per-vertex work is a table lookup. Engine defaults (dart =
// smooth, crease = the curve scheme's rules, corner = the point stays) are filled in here.
#include <string>
#include <vector>

#include "framework/rules/rule.h"
#include "framework/rules/rule_set.h"

namespace subdiv {

struct CompiledTerm {
  Role role = Role::Self;
  NewPoint new_point = NewPoint::None;
  std::string where;
  // Dense table; a variable the formula does not use has stride 0.
  std::vector<double> table;
  size_t stride_n = 0, stride_k = 0, stride_j = 0, stride_n0 = 0, stride_n1 = 0;
  int max_j = 0;  // the largest point index j tabulated
  // Role::Curve: weights on feature-curve points at offsets curve_start, curve_start+1, ...
  int curve_start = 0;
  std::vector<double> curve_weights;

  double weight(int n, int k, int j, int n0 = 0, int n1 = 0) const {
    return table[n * stride_n + k * stride_k + j * stride_j + n0 * stride_n0 + n1 * stride_n1];
  }
};

struct CompiledRule {
  std::vector<CompiledTerm> terms;
  std::string where;
  bool defined = false;
};

struct WeightTables {
  CompiledRule rules[kElementCount][kContextCount];
  // The curve scheme's rules, one per new point of an old point (rule r of arity m): the
  // defaults for crease vertices (r = 0) and the r-th new point along a crease edge.
  std::vector<CompiledRule> curve_rules;
  int curve_arity = 0;
  int max_n = 0, max_k = 0;

  const CompiledRule& rule(Element e, Context c) const { return rules[int(e)][int(c)]; }
};

// What formulas may refer to besides n, k, j, l, n0, n1: the scheme's numeric parameters
// and named definitions; and the curve scheme for boundaries and creases (may be null).
struct FormulaScope {
  std::map<std::string, double> parameters;
  const std::vector<NamedFormula>* definitions = nullptr;
  const CurveScheme* curve = nullptr;
};

// max_n: the largest valence, max_k: the largest face size on the level; level: l.
WeightTables prepare_weight_tables(const StepRules& step, const FormulaScope& scope, int max_n, int max_k, int level);

}  // namespace subdiv
