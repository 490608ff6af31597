#pragma once
// Two mid-edge steps as one dual step, for a sequence's head (sequence_head.h). One mid-edge
// step (Peters & Reif 1997, "The simplest subdivision scheme for smoothing polyhedra") turns
// the grid by 45 degrees, so its faces straddle the old edges; two nest as a dual split does
// (mid_edge_limit.h): the second step's point on the first step's edge between the middles of
// face g's edges j - 1 and j is the point of corner (g, j), and the F-face of the first step's
// F-face of g is g's F-face. These origins let dual_child_point (dual_limit.h) carry a point
// through the pair. On closed meshes without creases (mid_edge_limit_unsupported).
#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

// The origins of `grand` (two mid-edge steps below `parent`, through `middle`) as a dual
// split's: each vertex the corner (face, index) it stands for, each F-face its face.
ChildOrigins mid_edge_pair_origins(const Level& parent, const Level& middle, const Level& grand,
                                   const ChildOrigins& first, const ChildOrigins& second);

}  // namespace subdiv
