#pragma once
// Points along a feature curve (boundary or crease polyline) for curve-scheme rules.
// Where the curve ends before the mask does, missing points are extrapolated linearly
// from the last two (P_{m+d} = P_m + d (P_m - P_{m-1})), which keeps linear precision.
#include "framework/features/feature_context.h"
#include "framework/rules/row_builder.h"

namespace subdiv {

// Adds weight * (point `steps` edges away from v along the curve, leaving v through
// ring edge `edge`) to the row.
void add_curve_point(RowBuilder& row, const Level& level, const FeatureContexts& features,
                     Index v, Index edge, int steps, double weight);

// How far crease vertex v lies from the nearest corner its crease reaches: `distance` crease
// edges (1..max_distance) along ring edge `edges[side]`; distance 0 when no corner lies within
// max_distance on either side (a closed loop, a crease ending at a dart, a long crease). On a
// tie, side 0. `length`: the crease's length in edges when corners lie within max_distance on
// both sides (a + b), else 0.
struct CornerDistance {
  int distance = 0;
  int side = 0;
  int length = 0;
};
CornerDistance distance_to_corner(const Level& level, const FeatureContexts& features, Index v,
                                  const std::array<Index, 2>& edges, int max_distance);

}  // namespace subdiv
