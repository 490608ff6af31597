// index_corners: every corner's face, and the corners around each vertex, for both level
// builders.
//
// The corners around a vertex come in corner order (a stable counting sort by vertex), so
// the index is the same whatever the thread count: faces are cut into a few chunks, each
// chunk counts its corners per vertex, the counts are summed per vertex in chunk order and
// scanned over the vertices, and each chunk then places its corners from its own cursors.
// With slot heads asked for, each placed corner also gets the vertex its edge runs to.
// The level builders read this order (rings start from a vertex's first corner; the general
// builder lists a non-manifold vertex's faces in it), so it must not depend on the threads.
#include <algorithm>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "framework/topology/level_rings.h"

namespace subdiv {
namespace {

// Corners (or vertices) per parallel task, and the fewest corners worth a chunk of their own.
constexpr Index kGrain = 1 << 14;
constexpr Index kChunkCorners = 1 << 16;

// Chunks of the counting sort: one per thread, while each has enough corners; each chunk
// holds a count per vertex, so their memory is kept within a few times the corners'
// (a mesh of many isolated vertices gets one chunk).
Index chunk_count(Index corners, Index vertices) {
  const Index threads = Index(std::max(1, tbb::this_task_arena::max_concurrency()));
  const Index by_corners = corners / kChunkCorners;
  const Index by_memory = Index(4 * std::int64_t(corners) / std::max<Index>(vertices, 1));
  return std::max<Index>(1, std::min({threads, by_corners, by_memory}));
}

}  // namespace

CornerIndex index_corners(const Level& level, SlotHeads heads) {
  return index_corners(level, chunk_count(level.corner_count(), level.vertex_count), heads);
}

CornerIndex index_corners(const Level& level, Index chunks, SlotHeads heads) {
  chunks = std::max<Index>(chunks, 1);
  CornerIndex ci;
  const Index corners = level.corner_count(), V = level.vertex_count, faces = level.face_count();
  const Index* face_vertex = level.face_vertices.data();
  const Index* face_offset = level.face_offsets.data();

  // Chunks of whole faces, so that the placing pass below also writes each corner's face.
  // Each chunk's corners per vertex; then, per vertex, where each chunk's first corner goes.
  const auto first_face = [&](Index k) { return Index(std::int64_t(faces) * k / chunks); };
  const auto chunk_begin = [&](Index k) { return face_offset[first_face(k)]; };
  std::vector<ScratchVector<Index>> cursor(static_cast<size_t>(chunks));
  for (auto& counts : cursor) counts.reserve(size_t(V));  // in this thread's heap (util/resize_side_by_side.h)
  tbb::parallel_for(Index(0), chunks, [&](Index k) {
    ScratchVector<Index>& counts = cursor[size_t(k)];
    counts.assign(size_t(V), 0);
    Index* count = counts.data();
    const Index begin = chunk_begin(k), end = chunk_begin(k + 1);
    for (Index c = begin; c < end; ++c) ++count[face_vertex[c]];
  });
  // The exclusive scan of the per-vertex totals, in blocks of vertices: each block's sum,
  // the blocks' offsets in order, then each block's own scan, which also turns each
  // chunk's counts into its cursors. One chunk scans in one block (no sums to take first).
  std::vector<Index*> counts(static_cast<size_t>(chunks));
  for (Index k = 0; k < chunks; ++k) counts[size_t(k)] = cursor[size_t(k)].data();
  grow(ci.vertex_offsets, size_t(V) + 1);
  ci.vertex_offsets[0] = 0;
  const Index block_size = chunks == 1 ? std::max<Index>(V, 1) : kGrain;
  const Index blocks = (V + block_size - 1) / block_size;
  std::vector<Index> block_start(size_t(blocks) + 1, 0);
  const auto block_end = [&](Index b) { return std::min(V, (b + 1) * block_size); };
  if (blocks > 1) {
    tbb::parallel_for(Index(0), blocks, [&](Index b) {
      Index sum = 0;
      const Index begin = b * block_size, end = block_end(b);
      for (Index k = 0; k < chunks; ++k) {
        const Index* count = counts[size_t(k)];
        for (Index v = begin; v < end; ++v) sum += count[v];
      }
      block_start[b + 1] = sum;
    });
    for (Index b = 0; b < blocks; ++b) block_start[b + 1] += block_start[b];
  }
  tbb::parallel_for(Index(0), blocks, [&](Index b) {
    // Locals, so that the stores below are not taken to change the bounds.
    const Index begin = b * block_size, end = block_end(b), n = chunks;
    Index* const* count = counts.data();
    Index* offset = ci.vertex_offsets.data();
    Index next = block_start[b];
    for (Index v = begin; v < end; ++v) {
      for (Index k = 0; k < n; ++k) {
        const Index here = count[k][v];
        count[k][v] = next;
        next += here;
      }
      offset[v + 1] = next;
    }
  });
  grow(ci.face, size_t(corners));
  grow(ci.vertex_corners, size_t(corners));
  if (heads == SlotHeads::kYes) grow(ci.heads, size_t(corners));
  tbb::parallel_for(Index(0), chunks, [&](Index k) {
    Index* place = counts[size_t(k)];
    Index* sorted = ci.vertex_corners.data();
    Index* face = ci.face.data();
    Index* head = ci.heads.data();
    const bool with_heads = heads == SlotHeads::kYes;
    for (Index f = first_face(k), end = first_face(k + 1); f < end; ++f) {
      const Index first = face_offset[f], last = face_offset[f + 1];
      for (Index c = first; c < last; ++c) {
        const Index slot = place[face_vertex[c]]++;
        face[c] = f;
        sorted[slot] = c;
        if (with_heads) head[slot] = face_vertex[c + 1 == last ? first : c + 1];
      }
    }
  });
  return ci;
}

}  // namespace subdiv
