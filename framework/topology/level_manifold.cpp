// The manifold fast path of build_level: edges and CCW vertex rings from polygons, in
// parallel stages over corners and vertices (the role of OpenSubdiv's Vtr::Level::
// completeTopologyFromFaceVertices for manifold meshes).
//
// Every corner's edge is found once by its twin (the corner that runs the same edge
// backwards), which also gives the ring walk its next corner without searching a face.
// Edges are numbered as a serial pass in corner order would number them (an edge belongs
// to the lower of its two corners), so the level does not depend on the thread count.
#include <algorithm>
#include <atomic>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/topology/level.h"
#include "framework/topology/level_rings.h"
#include "framework/util/parallel_ranges.h"
#include "framework/util/resize_side_by_side.h"

namespace subdiv {
namespace {

// Elements per parallel task.
constexpr Index kGrain = 1 << 14;

// What the stages share: the corners around each vertex, with the vertex each one's edge
// runs to (the twin search then reads one vertex's slots, not the faces) and, per corner,
// its twin.
struct Corners {
  CornerIndex index;
  TransientVector<Index> twin;  // per corner: the corner that runs its edge backwards, or kNone (boundary)
  // Per vertex: its corner whose edge leaves along the boundary, or kNone (see number_edges).
  ScratchVector<Index> boundary_corner;
};

// Twins of every corner; false when an edge is not manifold: two corners run it the same
// way (a third face or faces of opposite orientation) or three run it. (No face runs an
// edge both ways here: faces that repeat a vertex went to the general builder.)
// Each pair is found once, from its lower vertex, which sets both corners (the other
// vertex's thread writes neither); corners whose pair no one finds keep kNone. A vertex's
// slots running to the same vertex twice are refused at that vertex, so a twin found is
// the only one.
bool find_twins(const Level& level, Corners& k) {
  const CornerIndex& ci = k.index;
  const Index corners = Index(ci.face.size());
  k.twin.resize(size_t(corners));
  parallel_ranges(corners, kGrain, [&](Index begin, Index end) { std::fill(k.twin.begin() + begin, k.twin.begin() + end, kNone); });
  std::atomic<bool> manifold{true};
  parallel_ranges(level.vertex_count, kGrain, [&](Index begin, Index end) {
    const Index* offset = ci.vertex_offsets.data();
    const Index* head = k.index.heads.data();
    const Index* corner = ci.vertex_corners.data();
    Index* twin = k.twin.data();
    for (Index v = begin; v < end && manifold.load(std::memory_order_relaxed); ++v) {
      const Index first = offset[v], last = offset[v + 1];
      for (Index i = first; i < last; ++i) {
        const Index to = head[i];
        if (std::count(head + first, head + last, to) != 1) manifold = false;
        if (to < v) continue;
        for (Index j = offset[to]; j < offset[to + 1]; ++j) {
          if (head[j] != v) continue;
          twin[corner[i]] = corner[j];
          twin[corner[j]] = corner[i];
          break;
        }
      }
    }
  });
  return manifold;
}

// An edge belongs to the lower corner of its pair (or its only corner).
bool owns_edge(const Corners& k, Index c) { return k.twin[c] == kNone || k.twin[c] > c; }

// Edge ids follow the owning corners in order: each chunk of corners counts its owners and
// the counts are summed in chunk order; returns where each chunk's edges start (the last
// entry is the edge count).
std::vector<Index> first_edges(const Level& level, const Corners& k) {
  const Index corners = level.corner_count();
  const Index chunks = (corners + kGrain - 1) / kGrain;
  std::vector<Index> first_edge(size_t(chunks) + 1, 0);
  tbb::parallel_for(Index(0), chunks, [&](Index chunk) {
    const Index begin = chunk * kGrain, end = std::min(corners, begin + kGrain);
    Index owned = 0;
    for (Index c = begin; c < end; ++c) owned += owns_edge(k, c);
    first_edge[chunk + 1] = owned;
  });
  for (Index chunk = 0; chunk < chunks; ++chunk) first_edge[chunk + 1] += first_edge[chunk];
  return first_edge;
}

// Sizes every array the stages below fill, side by side (util/resize_side_by_side.h: their
// zero-fill was a sixth of the builder's time on one thread, all of it serial). A manifold level
// with `edges` edges has 2 * edges ring edges: every corner gives one, and every boundary
// vertex one more, as many as the boundary edges (sizes for a level whose fans meet at no
// vertex; build_rings gives up before writing otherwise).
void size_level(Level& level, Index edges) {
  const size_t corners = size_t(level.corner_count()), V = size_t(level.vertex_count);
  resize_side_by_side(Sized{level.face_edges, corners}, Sized{level.edge_vertices, 2 * size_t(edges)},
                      Sized{level.edge_faces, 2 * size_t(edges)}, Sized{level.vertex_faces, corners},
                      Sized{level.vertex_face_corner, corners}, Sized{level.vertex_edges, 2 * size_t(edges)},
                      Sized{level.vertex_ring_offsets, V + 1}, Sized{level.vertex_on_boundary, V});
}

// face_edges, edge_vertices, edge_faces: each chunk numbers its owning corners' edges from
// its first edge, and gives each edge to its owner's twin too; boundary corners per vertex.
void number_edges(Level& level, Corners& k, const std::vector<Index>& first_edge) {
  const Index corners = level.corner_count();
  const Index chunks = Index(first_edge.size()) - 1;
  k.boundary_corner.resize(size_t(level.vertex_count));
  parallel_ranges(level.vertex_count, kGrain, [&](Index begin, Index end) {
    std::fill(k.boundary_corner.begin() + begin, k.boundary_corner.begin() + end, kNone);
  });
  tbb::parallel_for(Index(0), chunks, [&](Index chunk) {
    const Index begin = chunk * kGrain, end = std::min(corners, begin + kGrain);
    Index e = first_edge[chunk];
    for (Index c = begin; c < end; ++c) {
      if (!owns_edge(k, c)) continue;
      const Index f = k.index.face[c], twin = k.twin[c];
      level.face_edges[c] = e;
      if (twin != kNone) level.face_edges[twin] = e;  // no other chunk writes there: twin is not an owner
      // A boundary edge marks the vertex it leaves, for its ring start. Two chunks write
      // the same vertex only where two boundaries leave it (two fans: the walk refuses it).
      if (twin == kNone) std::atomic_ref<Index>(k.boundary_corner[level.face_vertices[c]]).store(c, std::memory_order_relaxed);
      level.edge_vertices[2 * e] = level.face_vertices[c];
      level.edge_vertices[2 * e + 1] = level.face_vertices[next_corner(level, f, c)];
      level.edge_faces[2 * e] = f;
      level.edge_faces[2 * e + 1] = twin == kNone ? kNone : k.index.face[twin];
      ++e;
    }
  });
}

// Walks v's corners CCW from `start` into its ring slots: the next face CCW lies across
// the edge entering v, and the twin of that edge's corner is v's corner in that face.
// False if the walk does not visit every corner of v once (more than one fan).
bool walk_ring(Level& level, const Corners& k, Index v, Index start, Index edge_slot) {
  const CornerIndex& ci = k.index;
  const Index count = ci.vertex_offsets[v + 1] - ci.vertex_offsets[v];
  Index face_slot = ci.vertex_offsets[v];
  Index c = start;
  for (Index visited = 0; visited < count; ++visited) {
    const Index f = ci.face[c];
    level.vertex_faces[face_slot] = f;
    level.vertex_face_corner[face_slot++] = LocalIndex(c - level.face_offsets[f]);
    level.vertex_edges[edge_slot++] = level.face_edges[c];
    const Index entering = prev_corner(level, f, c);
    const Index next = k.twin[entering];
    const bool last = visited + 1 == count;
    if (next == kNone) {
      level.vertex_edges[edge_slot++] = level.face_edges[entering];
      if (!last) return false;
    } else if (next == start && !last) {
      return false;
    }
    c = next;
  }
  return true;
}

// Vertex rings (offsets, faces, corners, edges) and boundary flags, in fixed blocks of
// vertices: each block counts its boundary vertices, the counts are summed in block order
// (a boundary vertex has one ring edge more than faces), then each block writes its ring
// offsets and walks its rings. A ring starts at the vertex's boundary corner, if any, else
// at its first corner. A vertex where two fans meet is found by the walk: from either start
// it comes back, or to the boundary, before it has visited every corner.
bool build_rings(Level& level, const Corners& k) {
  const CornerIndex& ci = k.index;
  const Index V = level.vertex_count;
  const Index blocks = (V + kGrain - 1) / kGrain;
  std::vector<Index> boundary_before(size_t(blocks) + 1, 0);
  tbb::parallel_for(Index(0), blocks, [&](Index b) {
    Index boundary = 0;
    for (Index v = b * kGrain; v < std::min(V, (b + 1) * kGrain); ++v) {
      level.vertex_on_boundary[v] = k.boundary_corner[v] != kNone;
      boundary += level.vertex_on_boundary[v];
    }
    boundary_before[b + 1] = boundary;
  });
  for (Index b = 0; b < blocks; ++b) boundary_before[b + 1] += boundary_before[b];
  level.vertex_ring_offsets[0] = 0;
  std::atomic<bool> fans{true};
  tbb::parallel_for(Index(0), blocks, [&](Index b) {
    Index boundary = boundary_before[b];  // boundary vertices before v
    for (Index v = b * kGrain; v < std::min(V, (b + 1) * kGrain) && fans.load(std::memory_order_relaxed); ++v) {
      const Index ring_begin = ci.vertex_offsets[v] + boundary;
      boundary += level.vertex_on_boundary[v];
      level.vertex_ring_offsets[v + 1] = ci.vertex_offsets[v + 1] + boundary;
      const Index first = ci.vertex_offsets[v] < ci.vertex_offsets[v + 1] ? ci.vertex_corners[ci.vertex_offsets[v]] : kNone;
      const Index start = level.vertex_on_boundary[v] ? k.boundary_corner[v] : first;
      if (!walk_ring(level, k, v, start, ring_begin)) fans = false;
    }
  });
  return fans;
}

}  // namespace

bool build_manifold_level(Level& level) {
  Corners k;
  k.index = index_corners(level, SlotHeads::kYes);
  if (!find_twins(level, k)) return false;
  const std::vector<Index> first_edge = first_edges(level, k);
  size_level(level, first_edge.back());
  number_edges(level, k, first_edge);
  if (!build_rings(level, k)) return false;
  level.vertex_face_offsets = std::move(k.index.vertex_offsets);  // a ring face per corner
  return true;
}

}  // namespace subdiv
