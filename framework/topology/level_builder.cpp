// Builds a Level's edges and CCW vertex rings from polygons. Manifold input (the common
// case) takes the parallel fast path (level_manifold.cpp); anything else is handed to the
// general builder (level_general.cpp), which marks non-manifold elements as OpenSubdiv's
// Vtr does.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include "framework/topology/level.h"
#include "framework/topology/level_rings.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// Whether a face repeats a vertex: small faces pairwise, large ones sorted (a hostile file's
// face of 10^5 corners must not take 10^10 steps).
bool repeats_vertex(std::span<const Index> verts) {
  if (verts.size() > 16) {
    std::vector<Index> sorted(verts.begin(), verts.end());
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
  }
  for (size_t i = 0; i < verts.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (verts[i] == verts[j]) return true;
  return false;
}

// The faces as given to build_level, before they are copied into the level.
struct Faces {
  Index vertex_count;
  std::span<const Index> offsets, vertices;
  Index count() const { return Index(offsets.size()) - 1; }
  std::span<const Index> face(Index f) const {
    return {vertices.data() + offsets[f], size_t(offsets[f + 1] - offsets[f])};
  }
};

// Throws if no builder can take face f: fewer than 3 corners or more than kMaxFaceSize, or
// a vertex out of range.
void check_face(const Faces& faces, Index f) {
  auto verts = faces.face(f);
  if (verts.size() < 3) throw Error(fmt::format("face {} has {} vertices; a face needs at least 3", f, verts.size()));
  if (verts.size() > size_t(kMaxFaceSize))
    throw Error(fmt::format("face {} has {} vertices; faces may have at most {} (as in OpenSubdiv); split it", f,
                            verts.size(), kMaxFaceSize));
  for (Index v : verts)
    if (v < 0 || v >= faces.vertex_count)
      throw Error(fmt::format("face {} names vertex {}, but the mesh has {} vertices", f, v, faces.vertex_count));
}

// Range and size checks (the first bad face in order is reported, whatever the threads);
// returns false if a face repeats a vertex (the general path's job).
// A face of 3 or more corners with fewer than 3 distinct vertices ((a, a, b, b), (a, a, a))
// is kept: OpenSubdiv's Vtr refines it (its edges from a vertex to itself and the edge it
// runs twice are non-manifold), and so does the general path, to the same result
// (tests/unit/osd/osd_shapes_test.cpp, catmark_nonman_edges and loop_nonman_edges).
bool check_faces(const Faces& faces) {
  std::atomic<Index> first_bad{faces.count()};
  std::atomic<bool> simple{true};
  tbb::parallel_for(tbb::blocked_range<Index>(0, faces.count(), 1 << 14), [&](const tbb::blocked_range<Index>& r) {
    const Index* offset = faces.offsets.data();
    const std::uint32_t vertex_count = std::uint32_t(faces.vertex_count);
    bool repeats = false;
    for (Index f = r.begin(); f < r.end(); ++f) {
      const Index n = offset[f + 1] - offset[f];
      const Index* v = faces.vertices.data() + offset[f];
      bool bad = n < 3 || n > kMaxFaceSize;
      // Without early exits (one unsigned test catches negative indices too).
      for (Index i = 0; i < n && !bad; ++i) bad = std::uint32_t(v[i]) >= vertex_count;
      if (bad) {
        Index seen = first_bad.load();
        while (f < seen && !first_bad.compare_exchange_weak(seen, f)) {}
        break;
      }
      // Triangles and quads, the common faces, pairwise without a loop.
      if (n == 3) repeats = repeats || v[0] == v[1] || v[1] == v[2] || v[2] == v[0];
      else if (n == 4) repeats = repeats || v[0] == v[1] || v[0] == v[2] || v[0] == v[3] || v[1] == v[2] || v[1] == v[3] || v[2] == v[3];
      else repeats = repeats || repeats_vertex({v, size_t(n)});
    }
    if (repeats) simple = false;
  });
  if (first_bad < faces.count()) check_face(faces, first_bad);
  return simple;
}

}  // namespace

Level build_level(Index vertex_count, std::span<const Index> face_offsets,
                  std::span<const Index> face_vertices) {
  Level level;
  level.vertex_count = vertex_count;
  static const Index kNoFaces[] = {0};
  if (face_offsets.empty()) face_offsets = kNoFaces;
  // The copy (serial memory traffic) beside the parallel check of the caller's arrays; the
  // memory reserved in this thread (util/resize_side_by_side.h says why).
  level.face_offsets.reserve(face_offsets.size());
  level.face_vertices.reserve(face_vertices.size());
  bool simple = true;
  tbb::parallel_invoke(
      [&] {
        level.face_offsets.assign(face_offsets.begin(), face_offsets.end());
        level.face_vertices.assign(face_vertices.begin(), face_vertices.end());
      },
      [&] { simple = check_faces(Faces{vertex_count, face_offsets, face_vertices}); });
  if (simple && build_manifold_level(level)) return level;
  // Not manifold: start again from the faces, identifying edges as OpenSubdiv does.
  Level general;
  general.vertex_count = vertex_count;
  general.face_offsets = std::move(level.face_offsets);
  general.face_vertices = std::move(level.face_vertices);
  identify_edges_general(general);
  complete_general_level(general);
  return general;
}

Index find_edge(const Level& level, Index a, Index b) {
  for (Index e : level.ring_edges(a))
    if (level.other_end(e, a) == b) return e;
  return kNone;
}

long euler_characteristic(const Level& level) {
  return long(level.vertex_count) - level.edge_count() + level.face_count();
}

bool Level::all_faces_have_size(int k) const {
  return tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, face_count(), 1 << 16), true,
      [&](const tbb::blocked_range<Index>& r, bool all) {
        for (Index f = r.begin(); f < r.end() && all; ++f) all = face_size(f) == k;
        return all;
      },
      [](bool a, bool b) { return a && b; });
}

int Level::max_face_size() const {
  return tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, face_count(), 1 << 16), 0,
      [&](const tbb::blocked_range<Index>& r, int m) {
        for (Index f = r.begin(); f < r.end(); ++f) m = std::max(m, face_size(f));
        return m;
      },
      [](int a, int b) { return std::max(a, b); });
}

int Level::max_valence() const {
  return tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, vertex_count, 1 << 16), 0,
      [&](const tbb::blocked_range<Index>& r, int m) {
        for (Index v = r.begin(); v < r.end(); ++v) m = std::max(m, valence(v));
        return m;
      },
      [](int a, int b) { return std::max(a, b); });
}

}  // namespace subdiv
