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

}  // namespace subdiv
