#pragma once
// A curve scheme's rules evaluated at one level: the numbers the polyline refiner and the
// symbol analysis work with.
#include <string>
#include <vector>

#include "framework/analysis/curve/curve_mask.h"
#include "framework/scheme/scheme.h"

namespace subdiv {

// Rule r gives new point m*i + r as sum_t weights[r][t] * old point (i + starts[r] + t).
struct CurveRulesAtLevel {
  int arity = 2;
  int level = 0;
  std::vector<int> starts;
  std::vector<std::vector<double>> weights;  // zero weights at either end trimmed
  // Where new point m*i + r sits, in old-point spacings from old point i: the weighted
  // mean of its rule's offsets, sum_t w_t (starts[r] + t). Orders and places new points
  // along an open polyline.
  std::vector<double> offsets;
  CurveEnds ends = CurveEnds::Interpolate;
  // Explicit end rules (CurveEnds::Rules), or the one rule {1} for CurveEnds::Interpolate.
  std::vector<std::vector<double>> end_rules;
  // A variational scheme (alpha not empty; analysis/curve/variational_curve.h): the refiner
  // solves its energy per polyline; the rules above are then its bi-infinite rules (for
  // analysis and the order of new points).
  std::vector<double> variational_alpha;
  int variational_r = 0;
};

// Evaluates every weight formula at level `level` (j = index of the weight in its rule).
// Throws subdiv::Error naming the scheme file and the rule for a non-finite weight, a rule
// whose weights do not sum to 1, or a rule that is all zeros.
CurveRulesAtLevel evaluate_curve_rules(const CurveScheme& scheme, int level);

// The scheme's mask at level `level` (mask_from_rules of the evaluated rules), ready for
// analyse_curve. Stationary schemes have the same mask at every level.
CurveMask curve_mask(const CurveScheme& scheme, int level = 0);

}  // namespace subdiv
