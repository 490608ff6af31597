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
#include "framework/scheme/curve_scheme.h"
#include "framework/scheme/parameter_spec.h"
#include "framework/scheme/step_rules.h"

namespace subdiv {

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
