// Primal quad and triangle splits (seed 000 §4: "a triangle is split into 4"; Catmull-Clark's
// topology: new face point joined to the new edge points).
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/refine/primal_topology.h"
#include "framework/refine/splitter.h"
#include "framework/util/error.h"
#include "framework/util/bulk_memory.h"
#include "framework/util/resize_side_by_side.h"

namespace subdiv {
namespace {

// Origins of the vertex block and edge block shared by both primal splits.
ChildOrigins primal_origins(const Level& parent, bool with_face_points) {
  const Index v = parent.vertex_count, e = parent.edge_count(), f = parent.face_count();
  const Index total = v + e + (with_face_points ? f : 0);
  ChildOrigins o;
  // Sized side by side (local stays 0), filled in parallel.
  resize_side_by_side(Sized{o.kind, size_t(total)}, Sized{o.parent, size_t(total)}, Sized{o.local, size_t(total)});
  // One straight loop per block of children (they vectorise; a kind test per child did not).
  const auto fill = [&](OriginKind kind, Index first, Index count) {
    tbb::parallel_for(tbb::blocked_range<Index>(0, count, 1 << 14), [&](const tbb::blocked_range<Index>& r) {
      OriginKind* kinds = o.kind.data() + first;
      Index* parents = o.parent.data() + first;
      for (Index i = r.begin(); i < r.end(); ++i) kinds[i] = kind, parents[i] = i;
    });
  };
  fill(OriginKind::Vertex, 0, v);
  fill(OriginKind::Edge, v, e);
  if (with_face_points) fill(OriginKind::Face, v + e, f);
  o.runs.emplace();
  auto declare = [&](OriginKind kind, Index first, Index count) {
    if (count > 0) o.runs->first[int(kind)] = first, o.runs->count[int(kind)] = count;
  };
  declare(OriginKind::Vertex, 0, v);
  declare(OriginKind::Edge, v, e);
  if (with_face_points) declare(OriginKind::Face, v + e, f);
  return o;
}

// Which parent face each child face lies in: quad children follow parent corners.
std::vector<Index> quad_parent_faces(const Level& parent) {
  std::vector<Index> out;
  resize_bulk(out, size_t(parent.corner_count()));
  tbb::parallel_for(tbb::blocked_range<Index>(0, parent.face_count(), 1 << 12), [&](const tbb::blocked_range<Index>& r) {
    for (Index f = r.begin(); f < r.end(); ++f)
      std::fill(out.begin() + parent.face_offsets[f], out.begin() + parent.face_offsets[f + 1], f);
  });
  return out;
}

ChildOrigins triangle_origins(const Level& parent) {
  ChildOrigins origins = primal_origins(parent, false);
  resize_bulk(origins.parent_face, 4 * size_t(parent.face_count()));
  tbb::parallel_for(tbb::blocked_range<Index>(0, parent.face_count(), 1 << 14), [&](const tbb::blocked_range<Index>& r) {
    Index* parent_face = origins.parent_face.data();
    for (Index f = r.begin(); f < r.end(); ++f)
      for (int t = 0; t < 4; ++t) parent_face[4 * size_t(f) + t] = f;
  });
  return origins;
}

ChildOrigins quad_origins(const Level& parent) {
  ChildOrigins origins = primal_origins(parent, true);
  origins.parent_face = quad_parent_faces(parent);
  return origins;
}

}  // namespace

SplitResult split_quad(const Level& parent) { return {quad_split_topology(parent), quad_origins(parent)}; }
SplitResult split_quad_faces(const Level& parent) { return {quad_split_faces(parent), quad_origins(parent)}; }
SplitResult split_triangle(const Level& parent) { return {triangle_split_topology(parent), triangle_origins(parent)}; }
SplitResult split_triangle_faces(const Level& parent) {
  return {triangle_split_faces(parent), triangle_origins(parent)};
}

}  // namespace subdiv
