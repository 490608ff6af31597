#pragma once
// Refining single polylines and closed polygons with a curve scheme, linear or not. This is
// how non-linear curve schemes from plugins (CurveScheme::nonlinear) are applied; the
// polyline refinement of `subdiv refine` (framework/curve) can call refine_polyline() for
// them.
#include <span>
#include <vector>

#include "framework/scheme/scheme.h"

namespace subdiv {

// `points` holds `dim` numbers per point. Refines `levels` times, the first step at level
// `first_level`. A non-linear scheme is applied through its rule (open or closed); a linear
// one through its rules, with indices taken around the polygon (closed polygons only: open
// ends need end rules, which the curve layer owns). Throws subdiv::Error for an open
// polyline with a linear scheme, a polygon of fewer than 3 points, or a rule that returns a
// wrong number of values or non-finite ones.
std::vector<double> refine_polyline(const CurveScheme& scheme, std::span<const double> points, int dim, bool closed,
                                    int levels, int first_level = 0);

}  // namespace subdiv
