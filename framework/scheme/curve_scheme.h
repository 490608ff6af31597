#pragma once
// A curve scheme as data: the rules of a polyline scheme (and the curves that boundaries and
// creases of a surface scheme follow), as loaded from JSON or registered by a plugin.
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "framework/rules/formula.h"
#include "framework/scheme/parameter_spec.h"

namespace subdiv {

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
  // A variational scheme ("variational" in the file; analysis/curve/variational_curve.h):
  // the fairness energy's coefficients alpha (formulas) and offset r. Its new points solve a
  // linear system per level; `starts` and `weights` stay empty.
  std::vector<std::string> variational_alpha;
  int variational_r = 0;
  bool variational() const { return !variational_alpha.empty(); }
};

}  // namespace subdiv
