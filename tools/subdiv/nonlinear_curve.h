#pragma once
// `subdiv refine` for non-linear curve schemes (plugins): no stencils; each polyline is
// mapped to the next level by the scheme's own function.
#include "curve_refine.h"
#include "framework/scheme/scheme.h"

namespace subdiv::cli {

void refine_nonlinear_curves(const CurveRefineRequest& request, const CurveScheme& scheme);

}  // namespace subdiv::cli
