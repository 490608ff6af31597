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
  std::string choice;                           // choice parameters: the chosen value
  std::vector<std::string> choices;
};

// How a curve scheme treats the ends of an open polyline (docs/curves.md).
enum class CurveEnds {
  Interpolate,  // end points stay; missing points beyond an end are extrapolated linearly
  Uniform,      // no end rule: only new points whose rule lies inside the polyline are made
  Rules,        // explicit end rules (end_rules), missing points extrapolated linearly
};

// A curve scheme of arity m: new point m*i + r = sum_t w[r][t] * old point (i + start[r] + t).
// Weight formulas see j = t, l, the parameters, state and definitions. A file that states
// its mask instead of rules is loaded as the equivalent rules (numbers).
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
};

struct Scheme {
  std::string name, description, path;
  SplitKind split = SplitKind::Quad;
  int required_face_size = 0;  // 0: any polygon
  std::vector<ParameterSpec> parameters;
  std::vector<NamedFormula> definitions;  // after choice parameters selected their cases
  RuleTable rules;
  std::shared_ptr<const CurveScheme> curve;  // boundary and crease curves

  // Numeric parameter values by name, as formulas see them.
  std::map<std::string, double> parameter_values() const;
};

}  // namespace subdiv
