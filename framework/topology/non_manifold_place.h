#pragma once
// Where a level stops being manifold, in words a message can show: commands that need a
// manifold mesh (adaptive refinement, the limit surface of a sequence, Tutte's embedding,
// a plugin's split) name the first place and how to repair it, instead of only saying "not
// manifold" about a mesh of a million faces.
#include <string>

#include "framework/topology/level.h"

namespace subdiv {

// The first non-manifold edge (in edge order), or else the first non-manifold vertex, as
// "<place>; <fix>" with faces and vertices counted from 0, for example
//   "face 0 repeats vertex 1 (its edge 1-1 joins the vertex to itself) (faces and vertices
//    counted from 0); remove the repeat from the face"
// and likewise a face written twice, an edge with three or more faces, two faces of
// opposite orientation, and a vertex where separate fans of faces meet.
// Empty for a manifold level.
std::string non_manifold_place(const Level& level);

}  // namespace subdiv
