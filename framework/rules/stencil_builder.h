#pragma once
// Builds the stencil table of one refinement step (the rows of step_rows.h, stored).
#include "framework/rules/step_rows.h"
#include "framework/stencil/stencil_table.h"

namespace subdiv {

StencilTable build_step_stencils(const StepContext& step);

// Origins of a smoothing pass: child vertex v is parent vertex v.
ChildOrigins identity_origins(const Level& level);

}  // namespace subdiv
