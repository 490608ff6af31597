#pragma once
// Transition faces as triangles and quads (adaptive_refine.h, AdaptiveTransitions::Triangles):
// a coarse face next to finer ones is written by the stitcher as one polygon (its own corners
// and the finer vertices along its edges); renderers and tools that take triangles and quads
// only get it tessellated instead, as OpenSubdiv's feature-adaptive refinement draws such a
// face with a transition pattern (Nießner, Loop, Meyer & DeRose 2012, "Feature-adaptive GPU
// rendering of Catmull-Clark subdivision surfaces": one pattern each for 1, 2 adjacent,
// 2 opposite, 3 and 4 split edges of a quad, rotated).
//
// The tessellation adds no vertex: every new face is made of the polygon's own vertices, so
// the points are exactly the polygon output's and the faces tile the polygon:
// - a quad or triangle with at most one finer vertex per edge: a fixed pattern (see the .cpp;
//   for 1, 2 adjacent, 2 opposite and 3 split edges of a quad OpenSubdiv 2's transition
//   patterns, OSD_TRANSITION_PATTERN0-2 and 4; for 4 split edges OpenSubdiv draws 4 quads
//   around the face's centre, a point the mesh does not have, and here 4 corner triangles and
//   the quad of the edges' midpoints);
// - a face whose edges hold more (a neighbour two or more levels finer):
//   triangles zipped between two chains of its boundary, each triangle with corners on two
//   different sides of the face, so none is degenerate.
// Every new face keeps its polygon's face_level and base_face, and each corner its (u, v),
// corner flag and face-varying values, so face-varying data and cell arrays follow.
#include "framework/limit/adaptive_refine.h"

namespace subdiv {

// Rewrites every transition polygon of `mesh` (a face with corners that are not corners of
// its level's face) as triangles and quads, in place; other faces are left as they are.
void tessellate_transitions(AdaptiveMesh& mesh);

}  // namespace subdiv
