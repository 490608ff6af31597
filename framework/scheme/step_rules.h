#pragma once
// The rule data of one refinement step of a surface scheme: its split, its rules by element
// and context, and how its boundaries and creases are refined.
#include <memory>
#include <string>

#include "framework/refine/splitter.h"
#include "framework/rules/code_rules.h"
#include "framework/rules/rule.h"
#include "framework/scheme/curve_scheme.h"

namespace subdiv {

// One step of a scheme level: a split with its rules, or a smoothing pass that moves the
// vertices of an unchanged mesh (refine-then-average schemes: Lane & Riesenfeld 1980, Stam 2001).
struct StepRules {
  bool is_split = true;
  SplitKind split = SplitKind::Quad;
  RuleTable rules;
  // Vertex crease rules by distance from the nearest corner ("crease-ends"; rule.h).
  CreaseEndRules crease_ends;
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
