#pragma once
// Rules ready for stencil building on one level: every weight formula evaluated once for
// each valence n, face size k and point index j the level can ask for, stored densely so
// the per-vertex work is a table lookup. Engine defaults (dart = smooth, crease = the
// curve scheme's rules, corner = the vertex stays) are filled in here.
#include <string>
#include <vector>

#include "framework/rules/rule.h"

namespace subdiv {

struct Scheme;

struct CompiledTerm {
  Role role = Role::Self;
  NewPoint new_point = NewPoint::None;
  std::string where;
  // Dense table over the variables the formula uses; unused ones collapse to size 1.
  std::vector<double> table;
  int size_k = 1, size_j = 1;
  bool uses_n = false, uses_k = false, uses_j = false;
  // Role::Curve: weights on feature-curve points at offsets curve_start, curve_start+1, ...
  int curve_start = 0;
  std::vector<double> curve_weights;

  double weight(int n, int k, int j) const {
    return table[(size_t(uses_n ? n : 0) * size_k + (uses_k ? k : 0)) * size_j + (uses_j ? j : 0)];
  }
};

struct CompiledRule {
  std::vector<CompiledTerm> terms;
  std::string where;
  bool defined = false;
};

struct WeightTables {
  CompiledRule rules[kElementCount][kContextCount];
  int max_n = 0, max_k = 0;

  const CompiledRule& rule(Element e, Context c) const { return rules[int(e)][int(c)]; }
};

// max_n: the largest valence, max_k: the largest face size on the level; level: l.
WeightTables prepare_weight_tables(const Scheme& scheme, int max_n, int max_k, int level);

}  // namespace subdiv
