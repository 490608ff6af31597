#pragma once
// Two refinement steps as one matrix, for splits that nest only every second step (√3's
// triadic split, mid-edge's quadrants): rows some vertices of level 2, columns the vertices
// of level 0.
#include <vector>

#include "framework/limit/step_matrix.h"

namespace subdiv {

struct Hierarchy;

// `scale`: the factor by which two steps scale the parameter (3 for √3, 2 for mid-edge).
StepMatrix two_step_matrix(const Hierarchy& h, const std::vector<Index>& rows, Index source_count, int scale);

}  // namespace subdiv
