#pragma once
// Helpers shared by the two level builders (level_builder.cpp: the manifold fast path;
// level_general.cpp: non-manifold input and the children of non-manifold levels).
#include <vector>

#include "framework/topology/level.h"
#include "framework/util/bulk_memory.h"
#include "framework/util/scratch_vector.h"

namespace subdiv {

// Corner arrays the builders work with: for every corner, its face; corners around each vertex.
// The per-corner arrays live only while a level is built (TransientVector: on huge pages
// from 2 MB, where a fresh 4 KB page's first touch is dear); vertex_offsets may become the
// level's vertex_face_offsets.
struct CornerIndex {
  TransientVector<Index> face;          // per corner
  ScratchVector<Index> vertex_offsets;  // CSR: corners around each vertex (in corner order)
  TransientVector<Index> vertex_corners;
  // Beside vertex_corners, if asked for: the vertex each corner's edge runs to (the next
  // corner's vertex). Placed with the corners, where the faces are read in order; found
  // afterwards it would take a scattered read per corner.
  TransientVector<Index> heads;
};

inline Index next_corner(const Level& level, Index face, Index corner) {
  return corner + 1 == level.face_offsets[face + 1] ? level.face_offsets[face] : corner + 1;
}
inline Index prev_corner(const Level& level, Index face, Index corner) {
  return corner == level.face_offsets[face] ? level.face_offsets[face + 1] - 1 : corner - 1;
}

// Every corner's face, and the corners around each vertex in corner order, the same for
// any number of threads (corner_index.cpp).
enum class SlotHeads : bool { kNo, kYes };
CornerIndex index_corners(const Level& level, SlotHeads heads = SlotHeads::kNo);
// The same, sorted in `chunks` chunks whatever the threads (for tests: the result must not
// depend on them).
CornerIndex index_corners(const Level& level, Index chunks, SlotHeads heads = SlotHeads::kNo);

// Edges and CCW rings of a level whose faces are set, when every edge and vertex is
// manifold (level_manifold.cpp); false, with the level half built, as soon as one is not.
bool build_manifold_level(Level& level);

// Appends vertex v's ring in CCW order (faces, corners, edges, offsets, boundary flag).
// Needs edge_faces with the manifold conventions around v. Returns false, with the level's
// ring arrays as they were, if v's faces do not form a single fan.
bool build_ordered_ring(Level& level, const CornerIndex& ci, Index v);

// face_edges and edge_vertices from faces, as OpenSubdiv's Vtr::Level::
// completeTopologyFromFaceVertices finds them: an edge joins two vertices whatever the
// direction its faces run it; a face that comes back to an edge it already uses, and an
// edge from a vertex to itself, get an edge of their own. Edges with more than two faces,
// two faces running the same way, or made by those two cases are marked in
// edge_non_manifold.
void identify_edges_general(Level& level);

}  // namespace subdiv
