#pragma once
// One refinement step applied to per-vertex values without a stencil table: each child's
// row is applied as soon as it is known, as OpenSubdiv's PrimvarRefiner does. Smooth
// interior rows come straight from their plans (row_plans.h), other rows from the rule
// interpreter (step_rows.h), so nothing of the size of a table is built or stored.
//
// The result is bit for bit that of build_step_stencils(step).apply(src, channels): the
// same rows, summed in the same order. Rows of new points that other rules read are built
// again where they are read, or, for rules that take no plans, stored for the step.
#include <span>

#include "framework/rules/step_rows.h"

namespace subdiv {

// dst (child count x channels) from src (parent vertex count x channels), child-major.
void apply_step_rows(const StepContext& step, std::span<const double> src, std::span<double> dst, int channels);

}  // namespace subdiv
