#pragma once
// A scheme as data: what the JSON file says, validated. Formulas are kept as text and
// compiled when a mesh is refined (rules/weight_tables), so a Scheme is immutable and can
// be shared between threads.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "framework/refine/splitter.h"
#include "framework/rules/formula.h"
#include "framework/rules/rule.h"

namespace subdiv {

struct ParameterSpec {
  std::string name, description;
  bool is_choice = false;
  double value = 0, minimum = 0, maximum = 0;  // numeric parameters
  bool has_minimum = false, has_maximum = false;
  bool minimum_exclusive = false, maximum_exclusive = false;
  std::string choice;                           // choice parameters: the chosen value
  std::vector<std::string> choices;
};

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

struct Scheme {
  std::string name, description, path;
  int required_face_size = 0;  // 0: any polygon
  std::vector<ParameterSpec> parameters;
  std::vector<NamedFormula> definitions;  // after choice parameters selected their cases
  std::vector<StepRules> steps;           // one level: a split, then any smoothing passes
  std::shared_ptr<const CurveScheme> curve;  // boundary and crease curves

  SplitKind split() const { return steps.front().split; }

  // Numeric parameter values by name, as formulas see them.
  std::map<std::string, double> parameter_values() const;
};

}  // namespace subdiv
