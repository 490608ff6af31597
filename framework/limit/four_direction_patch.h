#pragma once
// The four-direction quadratic box spline (the Zwart-Powell element: Zwart 1973, "Multivariate
// splines with nondegenerate partitions"; Powell 1974, "Piecewise quadratic surface fitting for
// contour plotting"; de Boor, Höllig & Riemenschneider 1993, "Box splines", II.7) over one
// quadrant of a face, and the check that two steps of a scheme refine a regular quad grid as
// that box spline does.
//
// The element of the directions (1, 0), (0, 1), (1, 1), (1, -1), centred on its control point,
// is piecewise quadratic over the four-direction mesh — for control points at the integers, the
// lines x = k + 1/2, y = k + 1/2, x + y = k, x - y = k — and only C1 across those lines. Its
// refinement mask (1 + x)(1 + y)(1 + xy)(1 + x/y)/4 puts the new point of the square (w, w + e,
// w + e + f, w + f) nearest w, at w + (e + f)/4, at w/2 + (w + e)/4 + (w + f)/4.
//
// A quadrant (face g, corner j) has coordinates (a, b) in [0, 1]^2 as for dual schemes
// (biquadratic_patch.h): (0, 0) at the corner w = g[j], (1, 0) at the middle of edge j, (1, 1)
// at the centre; with control points at the integers, w at 0 and g's other corners at (1, 0),
// (1, 1), (0, 1), the quadrant is (x, y) = (a/2, b/2) in [0, 1/2]^2 and depends on the 3 x 3
// points around w (biquadratic_grid's). The knot lines cut it along its diagonal a = b into
// two triangles, and bound it at a = 1 and b = 1; the face's edges a = 0, b = 0 are not knot
// lines. On the triangle y <= x the nine functions B_pq(x, y) = M(x - p, y - q) are, with the
// element M(X, Y) reduced by its symmetries to 0 <= Y <= X (M = 0 where X + Y >= 2 or X >= 3/2):
//   M = (1 - X^2 - Y^2)/2                      X <= 1/2
//   M = (1 - X^2 - Y^2)/2 + (2X - 1)^2/8       X >= 1/2, X + Y <= 1
//   M = (2 - X - Y)^2/4 - (2Y - 1)^2/8         X + Y >= 1, Y <= 1/2, X - Y <= 1
//   M = (3 - 2X)^2/8                           X - Y >= 1
//   M = (2 - X - Y)^2/4                        Y >= 1/2
// (the convolution M = integral over t in [0, 1] of the Courant hat of (1, 0), (0, 1), (1, 1)
// at (X, Y) - t (1, -1), integrated exactly). On y > x, B_pq(x, y) = B_qp(y, x).
#include <array>

#include "framework/features/feature_options.h"
#include "framework/limit/biquadratic_patch.h"

namespace subdiv {

struct Scheme;

// Weights over the 3 x 3 grid of biquadratic_grid (row by row from (p, q) = (-1, -1), p along
// a) of the position and its derivatives in (a, b), at (a, b) in [0, 1]^2. The second
// derivatives are those of the triangle a >= b (when a >= b) or a < b of the quadrant.
QuadrantRows four_direction_rows(double a, double b);

// True on the quadrant's knot lines a = b, a = 1, b = 1, where the second derivatives of the
// two pieces that meet there differ (the box spline is only C1): they do not exist there.
bool on_four_direction_knot_line(double a, double b);

// True when two steps of the scheme (a mid-edge split: mid_edge_double_origins) map every
// corner (g, j) of a regular closed quad grid to 1/2 of g[j] and 1/4 of g[j + 1] and of g[j - 1]
// — the box spline's refinement above — decided from the engine's rows, not the scheme's name.
bool refines_as_four_direction(const Scheme& scheme, const FeatureOptions& features);

}  // namespace subdiv
