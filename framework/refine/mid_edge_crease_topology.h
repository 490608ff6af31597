#pragma once
// The mid-edge split (Peters & Reif 1997) of a level with interior creases (docs/features.md,
// "Creases in dual schemes"). Child vertex e is parent edge e's new point, shared by both
// sides of a sharp edge, so the sides are glued by construction; each vertex's V-face is cut
// into one face per sector between consecutive sharp edges (features/dual_features.h), as a
// boundary vertex's is, and the edge closing a sector (between the points of two consecutive
// sharp edges) carries their mean sharpness less one. The crease is so the polygon of its
// edges' new points, the mid-edge curve rule, as a boundary is. Corners are not kept: the
// split has no point on a vertex.
//
// Whether to take this split is decided per level by `mid_edge_needs_crease_topology`, which
// reads only the tags: a non-manifold vertex (a pinch, e.g. where a piece's ghost rings end,
// engine/mesh_pieces.h) gets no face, as in the plain split, and the creases elsewhere keep
// their topology. Deciding by the whole level's manifoldness would drop every crease of a
// level for one pinch far away, which made refinement in pieces differ from the whole mesh.
#include "framework/topology/level.h"

namespace subdiv {

// Whether the level has an interior edge of sharpness >= 1.
bool mid_edge_needs_crease_topology(const Level& parent);

// With `full`, the whole child level with its crease tags (uniform decay) and, in `averaged`,
// the tags under Chaikin's decay where they differ (else left empty); otherwise its faces
// only. `skipped_vertices` counts the non-manifold vertices that got no face.
Level mid_edge_crease_split(const Level& parent, bool full, Index* skipped_vertices, std::vector<float>* averaged);

}  // namespace subdiv
