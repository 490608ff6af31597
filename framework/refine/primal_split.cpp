// Primal quad and triangle splits (seed 000 §4: "a triangle is split into 4"; Catmull-Clark's
// topology: new face point joined to the new edge points).
#include <fmt/format.h>

#include "framework/refine/splitter.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// Origins of the vertex block and edge block shared by both primal splits.
ChildOrigins primal_origins(const Level& parent, bool with_face_points) {
  const Index v = parent.vertex_count, e = parent.edge_count(), f = parent.face_count();
  const Index total = v + e + (with_face_points ? f : 0);
  ChildOrigins o;
  o.kind.resize(total);
  o.parent.resize(total);
  o.local.assign(total, 0);
  for (Index i = 0; i < v; ++i) o.kind[i] = OriginKind::Vertex, o.parent[i] = i;
  for (Index i = 0; i < e; ++i) o.kind[v + i] = OriginKind::Edge, o.parent[v + i] = i;
  if (with_face_points)
    for (Index i = 0; i < f; ++i) o.kind[v + e + i] = OriginKind::Face, o.parent[v + e + i] = i;
  return o;
}

}  // namespace

SplitResult split_quad(const Level& parent) {
  const Index V = parent.vertex_count, E = parent.edge_count(), F = parent.face_count();
  const Index child_vertices = V + E + F;
  std::vector<Index> offsets(parent.corner_count() + 1);
  std::vector<Index> corners(4 * size_t(parent.corner_count()));
  ChildOrigins origins = primal_origins(parent, true);
  origins.parent_face.resize(parent.corner_count());
  Index q = 0;
  for (Index f = 0; f < F; ++f) {
    const auto verts = parent.face(f);
    const auto edges = parent.face_edge_list(f);
    const size_t k = verts.size();
    for (size_t i = 0; i < k; ++i, ++q) {
      // Child quad of corner i: (v_i, e_i, face point, e_{i-1}), CCW like its parent.
      Index* quad = corners.data() + 4 * size_t(q);
      quad[0] = verts[i];
      quad[1] = V + edges[i];
      quad[2] = V + E + f;
      quad[3] = V + edges[(i + k - 1) % k];
      offsets[q + 1] = 4 * (q + 1);
      origins.parent_face[q] = f;
    }
  }
  SplitResult result{build_level(child_vertices, offsets, corners), std::move(origins)};
  return result;
}

SplitResult split_triangle(const Level& parent) {
  const Index V = parent.vertex_count, E = parent.edge_count(), F = parent.face_count();
  std::vector<Index> offsets(4 * size_t(F) + 1);
  std::vector<Index> corners(12 * size_t(F));
  ChildOrigins origins = primal_origins(parent, false);
  origins.parent_face.resize(4 * size_t(F));
  for (Index f = 0; f < F; ++f) {
    const auto verts = parent.face(f);
    const auto edges = parent.face_edge_list(f);
    Index* out = corners.data() + 12 * size_t(f);
    // Three corner triangles (v_i, e_i, e_{i-1}), then the middle one (e_0, e_1, e_2).
    for (int i = 0; i < 3; ++i) {
      out[3 * i + 0] = verts[i];
      out[3 * i + 1] = V + edges[i];
      out[3 * i + 2] = V + edges[(i + 2) % 3];
    }
    for (int i = 0; i < 3; ++i) out[9 + i] = V + edges[i];
    for (int t = 0; t < 4; ++t) {
      offsets[4 * f + t + 1] = 3 * (4 * f + t + 1);
      origins.parent_face[4 * f + t] = f;
    }
  }
  return {build_level(V + E, offsets, corners), std::move(origins)};
}


}  // namespace subdiv
