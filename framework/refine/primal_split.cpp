// Primal quad and triangle splits (Loop 1987: a triangle is split into 4; Catmull & Clark 1978's
// topology: new face point joined to the new edge points).
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "framework/refine/primal_topology.h"
#include "framework/refine/splitter.h"
#include "framework/util/error.h"
#include "framework/util/bulk_memory.h"
#include "framework/util/resize_side_by_side.h"

namespace subdiv {
namespace {

// The origin arrays of a primal split of `parent`, reserved (quad: with face points, a
// child face per parent corner; triangle: four child faces per parent face).
void reserve_origins(const Level& parent, bool quad, ChildOrigins& o) {
  const size_t total = size_t(parent.vertex_count) + size_t(parent.edge_count()) + (quad ? size_t(parent.face_count()) : 0);
  reserve_bulk(o.kind, total);
  reserve_bulk(o.parent, total);
  reserve_bulk(o.local, total);
  reserve_bulk(o.parent_face, quad ? size_t(parent.corner_count()) : 4 * size_t(parent.face_count()));
}

// Origins of the vertex block and edge block shared by both primal splits.
void primal_origins(const Level& parent, bool with_face_points, ChildOrigins& o) {
  const Index v = parent.vertex_count, e = parent.edge_count(), f = parent.face_count();
  const Index total = v + e + (with_face_points ? f : 0);
  // Sized side by side (not filled: util/scratch_vector.h), written in parallel.
  resize_side_by_side(Sized{o.kind, size_t(total)}, Sized{o.parent, size_t(total)}, Sized{o.local, size_t(total)});
  // One straight loop per block of children (they vectorise; a kind test per child did not).
  const auto fill = [&](OriginKind kind, Index first, Index count) {
    tbb::parallel_for(tbb::blocked_range<Index>(0, count, 1 << 14), [&](const tbb::blocked_range<Index>& r) {
      OriginKind* kinds = o.kind.data() + first;
      Index* parents = o.parent.data() + first;
      LocalIndex* locals = o.local.data() + first;
      for (Index i = r.begin(); i < r.end(); ++i) kinds[i] = kind, parents[i] = i, locals[i] = 0;
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
}

// Which parent face each child face lies in: quad children follow parent corners; a
// triangle's four children follow each other.
void quad_parent_faces(const Level& parent, ScratchVector<Index>& parent_face) {
  resize_bulk(parent_face, size_t(parent.corner_count()));
  tbb::parallel_for(tbb::blocked_range<Index>(0, parent.face_count(), 1 << 12), [&](const tbb::blocked_range<Index>& r) {
    for (Index f = r.begin(); f < r.end(); ++f)
      std::fill(parent_face.begin() + parent.face_offsets[f], parent_face.begin() + parent.face_offsets[f + 1], f);
  });
}

void triangle_parent_faces(const Level& parent, ScratchVector<Index>& parent_face) {
  resize_bulk(parent_face, 4 * size_t(parent.face_count()));
  tbb::parallel_for(tbb::blocked_range<Index>(0, parent.face_count(), 1 << 14), [&](const tbb::blocked_range<Index>& r) {
    Index* to = parent_face.data();
    for (Index f = r.begin(); f < r.end(); ++f)
      for (int t = 0; t < 4; ++t) to[4 * size_t(f) + t] = f;
  });
}

void quad_origins(const Level& parent, ChildOrigins& o) {
  primal_origins(parent, true, o);
  quad_parent_faces(parent, o.parent_face);
}

void triangle_origins(const Level& parent, ChildOrigins& o) {
  primal_origins(parent, false, o);
  triangle_parent_faces(parent, o.parent_face);
}

// The child level and the origins side by side: neither needs the other, and the child's
// largest array (face_vertices, 64 MB for a million quads) is zero-filled by one thread
// (std::vector::resize). The origins run as a task; the child is built in this thread, so
// its arrays, like the origins' (reserved here), come from this thread's heap
// (util/resize_side_by_side.h says why).
template <class Topology, class Origins>
SplitResult side_by_side(const Level& parent, bool quad, Topology topology, Origins origins) {
  SplitResult result;
  reserve_origins(parent, quad, result.origins);
  tbb::task_group origin_task;
  origin_task.run([&] { origins(parent, result.origins); });
  try {
    result.child = topology(parent);
  } catch (...) {
    origin_task.wait();
    throw;
  }
  origin_task.wait();
  return result;
}

}  // namespace

SplitResult split_quad(const Level& parent) { return side_by_side(parent, true, quad_split_topology, quad_origins); }
SplitResult split_quad_faces(const Level& parent) { return side_by_side(parent, true, quad_split_faces, quad_origins); }
SplitResult split_triangle(const Level& parent) {
  return side_by_side(parent, false, triangle_split_topology, triangle_origins);
}
SplitResult split_triangle_faces(const Level& parent) {
  return side_by_side(parent, false, triangle_split_faces, triangle_origins);
}

ChildOrigins quad_split_origins(const Level& parent) {
  ChildOrigins o;
  primal_origins(parent, true, o);
  return o;
}

ChildOrigins triangle_split_origins(const Level& parent) {
  ChildOrigins o;
  primal_origins(parent, false, o);
  return o;
}

void add_quad_parent_faces(const Level& parent, ChildOrigins& o) { quad_parent_faces(parent, o.parent_face); }
void add_triangle_parent_faces(const Level& parent, ChildOrigins& o) { triangle_parent_faces(parent, o.parent_face); }

}  // namespace subdiv
