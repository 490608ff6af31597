#include "framework/plugin/mesh_lines.h"

namespace subdiv {

Index edge_beyond(const Level& L, const FeatureContexts& features, Index e, Index end) {
  const auto ring = L.ring_edges(end);
  const int n = int(ring.size());
  const bool feature = features.edges[e].crease_weight > 0.f;
  const VertexContext& vc = features.vertices[end];
  if (feature) {
    if (vc.parent != Context::Crease) return kNone;
    const Index x = ring[vc.parent_crease[0]], y = ring[vc.parent_crease[1]];
    return x == e ? y : y == e ? x : kNone;
  }
  if (L.on_boundary(end) || n != 4 || L.incident_face_count(end) != 4 || vc.parent != Context::Smooth) return kNone;
  for (int i = 0; i < n; ++i)
    if (ring[i] == e) return ring[(i + 2) % 4];
  return kNone;
}

Index vertex_beyond(const Level& L, const FeatureContexts& features, Index e, Index end) {
  const Index next = edge_beyond(L, features, e, end);
  return next == kNone ? kNone : L.other_end(next, end);
}

Index opposite_edge_in_quad(const Level& L, Index f, Index e) {
  const auto edges = L.face_edge_list(f);
  for (int i = 0; i < 4; ++i)
    if (edges[i] == e) return edges[(i + 2) % 4];
  return kNone;
}

Index parallel_edge_across(const Level& L, const FeatureContexts& features, Index f, Index e) {
  if (L.edge_on_boundary(e) || features.edges[e].crease_weight > 0.f) return kNone;
  const Index g = L.edge_faces[2 * e] == f ? L.edge_faces[2 * e + 1] : L.edge_faces[2 * e];
  if (g == kNone || L.face_size(g) != 4) return kNone;
  return opposite_edge_in_quad(L, g, e);
}

}  // namespace subdiv
