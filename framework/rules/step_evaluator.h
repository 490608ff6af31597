#pragma once
// One refinement step applied to per-vertex values without a stencil table: each child's
// row is applied as soon as it is known, as OpenSubdiv's PrimvarRefiner does. Smooth
// interior rows come straight from their plans (row_plans.h), other rows from the rule
// interpreter (step_rows.h), so nothing of the size of a table is built or stored.
//
// New points a rule uses (Catmull-Clark's vertex and edge rules read the new face points)
// are read back from the output, computed first in the rules' dependency order, instead of
// being expanded into parent vertices: fewer terms, and neighbourhoods that never list the
// faces' corners. The values are those of build_step_stencils(step).apply(src, channels)
// up to round-off, and bit for bit the same for schemes whose rules use no new points
// (the rows are then the same, summed in the same order). Any thread count gives the same
// bits.
#include <span>

#include "framework/rules/step_rows.h"

namespace subdiv {

// dst (child count x channels) from src (parent vertex count x channels), child-major.
void apply_step_rows(const StepContext& step, std::span<const double> src, std::span<double> dst, int channels);

}  // namespace subdiv
