#pragma once
// Rules ready for stencil building on one level: every weight formula evaluated once for
// each valence n, face size k, point index j and end valences n0, n1 the level can ask
// for, stored densely so the per-vertex work is a table lookup. Engine defaults (dart =
// smooth, crease = the curve scheme's rules, corner = the point stays) are filled in here.
#include <string>
#include <vector>

#include <map>

#include "framework/rules/formula.h"
#include "framework/rules/rule.h"

namespace subdiv {

// An edge rule's sector variables (formula.h): per end, b = 1 when the end is a feature vertex
// whose sector holds the edge, m the sector's number of faces, e the edge's index in it.
struct SectorVariables {
  int b[2] = {0, 0}, m[2] = {0, 0}, e[2] = {0, 0};
};

struct CompiledTerm {
  Role role = Role::Self;
  NewPoint new_point = NewPoint::None;
  std::string where;
  // Dense table; a variable the formula does not use has stride 0.
  std::vector<double> table;
  size_t stride_n = 0, stride_k = 0, stride_j = 0, stride_n0 = 0, stride_n1 = 0, stride_k0 = 0, stride_k1 = 0;
  // Face rules' corner variables (formula.h): corner index ci < max_k, boundary flag cb and
  // the face's counts of extraordinary corners ex and feature edges fe, each <= max_k.
  size_t stride_ci = 0, stride_cb = 0, stride_ex = 0, stride_fe = 0;
  // Edge rules' sector variables: b0, b1 (0 or 1), and per end the sector's size m and the
  // edge's index e in it as one slot, sector_slot[m] + e (0 <= e <= m). Only the sizes present
  // on the level get slots (LevelValences::sector_sizes): a formula of j, m and e is then
  // quadratic in the largest sector, not cubic.
  size_t stride_b0 = 0, stride_b1 = 0, stride_s0 = 0, stride_s1 = 0;
  std::vector<int> sector_slot;
  // Tabulated over the level's sector sizes (it reads m or e, or is an end's sector): the
  // table depends on LevelValences::sector_sizes.
  bool reads_sector_sizes = false;
  // Every weight is 0 where neither end has a sector (b0 = b1 = 0): a term of the rule next to
  // boundaries and creases only, which the smooth kernels leave out.
  bool zero_without_sectors = true;
  int max_j = 0;  // the largest point index j tabulated
  // When not empty, the end valences n0, n1 are tabulated only at the valences present on
  // the level (LevelValences::valences): end_slot[n] is valence n's place in the table.
  std::vector<int> end_slot;
  // Role::Curve: weights on feature-curve points at offsets curve_start, curve_start+1, ...
  int curve_start = 0;
  std::vector<double> curve_weights;
  int step = 0;  // Role::CreasePoint: crease edges along the crease, signed

  double weight(int n, int k, int j, int n0 = 0, int n1 = 0, int k0 = 0, int k1 = 0) const {
    if (!end_slot.empty()) n0 = end_slot[size_t(n0)], n1 = end_slot[size_t(n1)];
    return table[n * stride_n + k * stride_k + j * stride_j + n0 * stride_n0 + n1 * stride_n1 + k0 * stride_k0 +
                 k1 * stride_k1];
  }
  bool reads_sectors() const { return stride_b0 || stride_b1 || stride_s0 || stride_s1; }
  // An edge rule's weight with its ends' sector variables (n = 2).
  double edge_weight(int k, int j, int n0, int n1, int k0, int k1, const SectorVariables& s) const {
    if (!end_slot.empty()) n0 = end_slot[size_t(n0)], n1 = end_slot[size_t(n1)];
    size_t sectors = s.b[0] * stride_b0 + s.b[1] * stride_b1;
    if (stride_s0) sectors += size_t(sector_slot[size_t(s.m[0])] + s.e[0]) * stride_s0;
    if (stride_s1) sectors += size_t(sector_slot[size_t(s.m[1])] + s.e[1]) * stride_s1;
    return table[2 * stride_n + k * stride_k + j * stride_j + n0 * stride_n0 + n1 * stride_n1 + k0 * stride_k0 +
                 k1 * stride_k1 + sectors];
  }
  // A face rule's corner-role weight: n the corner's valence, k the face size.
  double corner_weight(int n, int k, int j, int ci, int cb, int ex, int fe) const {
    return table[n * stride_n + k * stride_k + j * stride_j + ci * stride_ci + cb * stride_cb + ex * stride_ex +
                 fe * stride_fe];
  }
};

struct CompiledRule {
  std::vector<CompiledTerm> terms;
  std::string where;
  bool defined = false;
};

// Whether an edge rule reads its ends' sectors (variables or roles), which are then found per edge.
inline bool reads_sectors(const CompiledRule& rule) {
  for (const CompiledTerm& t : rule.terms)
    if (t.reads_sectors() || t.role == Role::EndSector0 || t.role == Role::EndSector1) return true;
  return false;
}

struct WeightTables {
  CompiledRule rules[kElementCount][kContextCount];
  // The curve scheme's rules, one per new point of an old point (rule r of arity m): the
  // defaults for crease vertices (r = 0) and the r-th new point along a crease edge.
  std::vector<CompiledRule> curve_rules;
  int curve_arity = 0;
  // Vertex crease rules by distance from the nearest corner (rule.h: CreaseEndTable); an entry
  // is defined where the scheme states one. Empty: the `crease` rule everywhere.
  CreaseEndTable<CompiledRule> crease_ends;
  int max_n = 0, max_k = 0;

  const CompiledRule& rule(Element e, Context c) const { return rules[int(e)][int(c)]; }
};

// What a level asks of its tables, when known (engine/step_preparation.cpp).
struct LevelValences {
  // The valences present, ascending: a formula of the end valences n0, n1 is tabulated at
  // these pairs only, not at every pair up to the largest valence (cubic in it with j: a
  // 300-triangle fan took 24 s).
  std::vector<int> valences;
  // The sizes m of the sectors present (rules/end_sectors.h), ascending: the sector variables
  // m0, m1, e0, e1 are tabulated at these sizes only, and at m = 0 (an end without a sector).
  // Tabulated up to the largest valence, a formula of j, m and e took 109 M evaluations at a
  // 300-valent vertex.
  std::vector<int> sector_sizes;
};

// What formulas may refer to besides n, k, j, l, n0, n1, k0, k1: numeric parameters and named
// definitions; and the level's valences when known (otherwise every valence up to max_n).
struct FormulaScope {
  std::map<std::string, double> parameters;
  const std::vector<NamedFormula>* definitions = nullptr;
  const LevelValences* present = nullptr;
};

// Whether any of the tables' terms is tabulated over the level's sector sizes, which the
// caller then finds (rules/end_sectors.h: a pass over the rings of a tagged level) and
// compiles with; the other schemes never pay for it.
bool reads_sector_sizes(const WeightTables& tables);

// A rule table's formulas evaluated for every n < max_n + 1 (the largest valence) and
// k < max_k + 1 (the largest face size) at level l, with the engine's defaults for
// vertices and face corners: dart = smooth, corner = the point stays.
WeightTables compile_rule_table(const RuleTable& rules, const FormulaScope& scope, int max_n, int max_k, int level);

// The crease-end rules, compiled like compile_rule_table's (entry D undefined where none is stated).
CreaseEndTable<CompiledRule> compile_crease_end_rules(const CreaseEndRules& rules, const FormulaScope& scope, int max_n,
                                                   int max_k, int level);

// Rule r of a curve scheme of arity `starts.size()`: new point m*i + r = sum_t w[r][t] *
// old point (i + start[r] + t), as a Role::Curve rule; `where` names it in messages.
struct CurveRuleText {
  int start = 0;
  std::vector<std::string> weights;
  std::string where;
};
CompiledRule compile_curve_rule(const CurveRuleText& rule, const FormulaScope& scope, int level);

// The rule that keeps a point where it is.
CompiledRule stay_rule();

}  // namespace subdiv
