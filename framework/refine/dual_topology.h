#pragma once
// Child topology of the dual splits (dual_split.cpp) built from the parent's arrays, as
// primal_topology.h does for the primal ones. Faces, in order: F-faces (one per parent face,
// same corners), then (dual) E-faces, one per interior manifold edge, then V-faces, one per
// manifold vertex with a cycle of at least three corners (dual) or edges (mid-edge).
// Child vertices: dual, one per parent corner; mid-edge, one per parent edge.
//
// The full topology is numbered exactly as build_level numbers the same polygons (edges in
// the order of their first corner, rings from the lowest corner or from the boundary), so
// the direct way and the generic one give the same level; the tests compare every array.
#include <string>

#include "framework/topology/level.h"

namespace subdiv {

// The non-manifold parent elements that got no face (they have no cycle around them).
struct DualSkipped {
  Index edges = 0, vertices = 0;
};

// With `full`, the whole child level; otherwise its faces only (vertex_count, face_offsets,
// face_vertices), for a last level that nothing refines further. The full level is built
// directly when the parent is manifold and every interior vertex has three faces or more (a
// vertex with two makes no V-face: its two E-faces meet along an edge the direct numbering
// does not foresee); otherwise build_level completes the faces.
Level dual_split_topology(const Level& parent, bool full, DualSkipped* skipped);
Level mid_edge_split_topology(const Level& parent, bool full, DualSkipped* skipped);

}  // namespace subdiv
