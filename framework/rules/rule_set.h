#pragma once
// The rule data one refinement step uses, and curve schemes as data: what the scheme
// layer loads from JSON and the rules layer compiles into weight tables.
#include <map>
#include <string>
#include <vector>

#include "framework/refine/splitter.h"
#include "framework/rules/formula.h"
#include "framework/rules/rule.h"

namespace subdiv {

// A curve scheme of arity m: new point m*i + r = sum_t w[r][t] * old point (i + start[r] + t).
struct CurveScheme {
  std::string name, description, path;
  int arity = 2;
  std::vector<int> starts;
  std::vector<std::vector<std::string>> weights;
  std::map<std::string, double> parameters;
  std::vector<NamedFormula> definitions;
};

// One step of a scheme level: a split with its rules, or a smoothing pass that moves the
// vertices of an unchanged mesh (refine-then-average schemes, seed 002 and seed 003).
struct StepRules {
  bool is_split = true;
  SplitKind split = SplitKind::Quad;
  RuleTable rules;
  // Whether crease/boundary defaults come from the curve scheme: true for single-step
  // schemes; in schemes with smoothing passes the passes shape the features instead.
  bool curve_rules_apply = true;
  std::string where;
};

}  // namespace subdiv
