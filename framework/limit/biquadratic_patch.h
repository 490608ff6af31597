#pragma once
// The uniform biquadratic B-spline over one quadrant of a face, and the check that a dual
// scheme refines regular quads as that B-spline does.
//
// A quadrant (face g, corner j) is the quarter of g between its corner w = g[j], the
// middles of its two edges at w and its centre, with coordinates (a, b) in [0, 1]^2: (0, 0)
// at w, (1, 0) at the middle of edge j (towards g[j + 1]), (1, 1) at g's centre. On a
// regular quad grid the control points are the B-spline's Greville points (Doo & Sabin
// 1978; de Boor), two units apart in (a, b), so the quadrant lies in the polynomial piece
// centred on w and depends on the 3 x 3 points around it: with s = a/2, t = b/2 in
// [0, 1/2], P(a, b) = sum_{p,q in -1..1} B_p(s) B_q(t) P_pq, where B_-1(s) = (1/2 - s)^2 / 2,
// B_0(s) = 3/4 - s^2, B_1(s) = (1/2 + s)^2 / 2.
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/features/feature_options.h"
#include "framework/topology/level.h"

namespace subdiv {

struct Scheme;

// The 3 x 3 control points of quadrant (face, corner), row by row from (p, q) = (-1, -1)
// (p along the quadrant's a, q along b), or empty when w is not an interior vertex of
// valence 4 surrounded by quads.
std::optional<std::array<Index, 9>> biquadratic_grid(const Level& level, Index face, int corner);

// Weights over the 9 grid points of the position and its derivatives in (a, b) (also the
// four-direction box spline's, four_direction_patch.h).
struct QuadrantRows {
  std::array<double, 9> position{}, da{}, db{}, daa{}, dab{}, dbb{};
};
QuadrantRows biquadratic_rows(double a, double b);

// True when one step of the scheme maps every corner of a regular closed quad grid (a
// torus) to 9/16, 3/16, 3/16, 1/16 of its face's corners — the tensor product of Chaikin's
// 3/4, 1/4 (Lane & Riesenfeld 1980), i.e. the biquadratic B-spline's refinement — decided
// from the engine's rows, not the scheme's name.
bool refines_as_biquadratic(const Scheme& scheme, const FeatureOptions& features);

// True when `levels` steps of the scheme (linear) map every vertex they make from a closed
// 8 x 8 quad grid (a torus: every vertex of valence 4) — each the corner (g, j) of the grid it
// stands for, as `corners` writes the steps' origins — to weights[k] of g's corner j + k
// (k = 0..3) and nothing else, to 1e-13: a scheme's regular rows checked on the engine's rows.
bool refines_quad_corners_as(const Scheme& scheme, const FeatureOptions& features, int levels,
                             const std::function<ChildOrigins(const Hierarchy&)>& corners,
                             const std::array<double, 4>& weights);

}  // namespace subdiv
