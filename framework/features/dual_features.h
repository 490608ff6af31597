#pragma once
// Which parent elements a dual split treats as features (docs/features.md, "Creases in dual
// schemes"). Shared by the split (refine/dual_crease_topology.cpp), which glues the two sides
// of a sharp edge and collapses corners, and by the corner rule (rules/step_rows.cpp), which
// must give each glued or collapsed point the same position from whichever corner makes it.
#include "framework/topology/level.h"

namespace subdiv {

// A sharp edge for the dual split's topology: a boundary or non-manifold edge, or an edge of
// sharpness >= 1 (it takes the full crease rule this level, as in a primal scheme). An edge of
// 0 < s < 1 keeps the smooth topology and its corners blend the two rules.
inline bool dual_sharp_edge(const Level& L, Index e) {
  return L.edge_on_boundary(e) || L.non_manifold_edge(e) || L.edge_sharp(e) >= 1.f;
}

// The number of v's edges that are sharp for the dual split.
int dual_sharp_edge_count(const Level& L, Index v);

// A corner of the dual split: a vertex with three or more sharp edges, a tagged vertex of
// sharpness >= 1, or a boundary vertex with one face (in every --boundary mode, as the plain
// dual split keeps it). All its face-corner points are one child vertex at the vertex.
bool dual_collapses(const Level& L, Index v);

// Whether the split must take the feature topology (refine/dual_crease_topology.h) rather than
// the plain one: a level with an interior edge of sharpness >= 1 or a vertex of
// sharpness >= 1 that is not a boundary vertex with one face. (Boundaries alone give the same
// faces either way: the plain split is the feature split without interior features.) A
// non-manifold level takes it too: the feature split skips non-manifold vertices locally.
bool dual_needs_feature_topology(const Level& L);

}  // namespace subdiv
