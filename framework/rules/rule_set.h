#pragma once
// The rule data one refinement step uses, and curve schemes as data: what the scheme
// layer loads from JSON and the rules layer compiles into weight tables.
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

// How a curve scheme treats the ends of an open polyline (docs/curves.md).
enum class CurveEnds {
  Interpolate,  // end points stay; missing points beyond an end are extrapolated linearly
  Uniform,      // no end rule: only new points whose rule lies inside the polyline are made
  Rules,        // explicit end rules (end_rules), missing points extrapolated linearly
};

// A non-linear curve scheme (plugins): the points of one polyline, `dim` numbers per point,
// to the points of the next level. `closed`: a closed polygon (the last point joins the
// first); `level`: 0 for the input.
using PolylineRule =
    std::function<std::vector<double>(std::span<const double> points, int dim, bool closed, int level)>;

// A curve scheme of arity m: new point m*i + r = sum_t w[r][t] * old point (i + start[r] + t).
// Weight formulas see j = t, l, the parameters, state and definitions. A file that states
// its mask instead of rules is loaded as the equivalent rules (numbers). A non-linear
// scheme (plugins) has no weights; `nonlinear` maps a polyline to the next level.
struct CurveScheme {
  std::string name, description, path;
  int arity = 2;
  std::vector<int> starts;
  std::vector<std::vector<std::string>> weights;
  std::map<std::string, double> parameters;
  std::vector<ParameterSpec> parameter_specs;  // the same parameters with ranges and descriptions
  CurveEnds ends = CurveEnds::Interpolate;
  // CurveEnds::Rules: rule e gives the e-th new point from an end as weights on the old
  // points 0, 1, ... counted from the same end (mirrored at the other end).
  std::vector<std::vector<std::string>> end_rules;
  // State variables (NamedFormula::next set) first, then the definitions; the same holds
  // for Scheme::definitions.
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
  // A split's own curve scheme ("curve" in a split step): its crease and boundary rules come
  // from this curve, with or without smoothing passes after it; null: the scheme's curve.
  std::shared_ptr<const CurveScheme> curve;
  std::string where;
  // Geometry written in C++ (plugin schemes, rules/code_rules.h): linear code rules give the
  // stencil rows in place of `rules`; a non-linear rule replaces stencils altogether.
  std::shared_ptr<const CodeRules> code;
  std::shared_ptr<const NonlinearRule> nonlinear;
};

}  // namespace subdiv
