#pragma once
// A scheme as data: what the JSON file says, validated. Formulas are kept as text and
// compiled when a mesh is refined (rules/weight_tables), so a Scheme is immutable and can
// be shared between threads.
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "framework/refine/splitter.h"
#include "framework/rules/code_rules.h"
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

// A non-linear curve scheme (plugins): the points of one polyline, `dim` numbers per point,
// to the points of the next level. `closed`: a closed polygon (the last point joins the
// first); `level`: 0 for the input.
using PolylineRule =
    std::function<std::vector<double>(std::span<const double> points, int dim, bool closed, int level)>;

// A curve scheme of arity m: new point m*i + r = sum_t w[r][t] * old point (i + start[r] + t).
// A non-linear scheme has no weights; `nonlinear` maps a polyline to the next level.
struct CurveScheme {
  std::string name, description, path;
  int arity = 2;
  std::vector<int> starts;
  std::vector<std::vector<std::string>> weights;
  std::map<std::string, double> parameters;
  std::vector<NamedFormula> definitions;
  std::shared_ptr<const PolylineRule> nonlinear;
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
  // Geometry written in C++ (plugin schemes, rules/code_rules.h): linear code rules give the
  // stencil rows in place of `rules`; a non-linear rule replaces stencils altogether.
  std::shared_ptr<const CodeRules> code;
  std::shared_ptr<const NonlinearRule> nonlinear;
};

struct Scheme {
  std::string name, description, path;
  int required_face_size = 0;  // 0: any polygon
  std::vector<ParameterSpec> parameters;
  std::vector<NamedFormula> definitions;  // after choice parameters selected their cases
  std::vector<StepRules> steps;           // one level: a split, then any smoothing passes
  std::shared_ptr<const CurveScheme> curve;  // boundary and crease curves

  SplitKind split() const { return steps.front().split; }
  // False when a step is non-linear: the engine then applies it directly, without stencils.
  bool linear() const {
    for (const auto& step : steps)
      if (step.nonlinear) return false;
    return true;
  }

  // Numeric parameter values by name, as formulas see them.
  std::map<std::string, double> parameter_values() const;
};

}  // namespace subdiv
