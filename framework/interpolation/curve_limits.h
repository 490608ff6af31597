#pragma once
// Limit points of polylines and closed polygons under a linear, stationary curve scheme,
// as a table over the control points: the limit operator L of progressive interpolation
// (progressive.h) for curves.
//
// The limit point of control point j is the limit curve at the centre of j's basis
// function (analysis/curve_basis.h): sum_d phi(c + d) P_{j-d}. That is the limit point of
// the vertex for primal schemes ((1, 4, 1)/6 for the cubic B-spline, the vertex itself for
// interpolatory ones), and the value (1, 6, 1)/8 of the quadratic B-spline for Chaikin, the
// curve counterpart of the V-face centroid used for dual surface schemes.
//   - Closed polygons: that row, indices taken around the polygon.
//   - Open polylines, ends "interpolate" (or explicit end rules whose first rule keeps the
//     end point): the end points are their own limit; vertices within a few mask widths of
//     an end, where the end rules change the curve, are followed numerically: a window of
//     the polyline is refined until the point at j's parameter lies in the uniform part of
//     the curve, the uniform limit row is taken there and carried back through the window's
//     stencils (exact up to round-off).
//   - Ends "uniform" (open polylines shrink) and other end rules have no limit point at the
//     end vertices: refused with a message, as are non-stationary schemes.
#include "framework/curve/curve_level.h"
#include "framework/scheme/curve_scheme.h"
#include "framework/stencil/stencil_table.h"

namespace subdiv {

// One row per vertex of the level (vertices on no polyline: the identity).
StencilTable curve_limit_stencils(const CurveScheme& scheme, const CurveLevel& level);

}  // namespace subdiv
