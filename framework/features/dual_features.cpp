#include "framework/features/dual_features.h"

namespace subdiv {

int dual_sharp_edge_count(const Level& L, Index v) {
  int count = 0;
  for (Index e : L.ring_edges(v)) count += dual_sharp_edge(L, e);
  return count;
}

bool dual_collapses(const Level& L, Index v) {
  return L.vertex_sharp(v) >= 1.f || (L.on_boundary(v) && L.incident_face_count(v) == 1) ||
         dual_sharp_edge_count(L, v) >= 3;
}

bool dual_needs_feature_topology(const Level& L) {
  for (Index e = 0; e < Index(L.edge_sharpness.size()); ++e)
    if (!L.edge_on_boundary(e) && L.edge_sharpness[e] >= 1.f) return true;
  for (Index v = 0; v < Index(L.vertex_sharpness.size()); ++v)
    if (L.vertex_sharpness[v] >= 1.f && !(L.on_boundary(v) && L.incident_face_count(v) == 1)) return true;
  return false;
}

}  // namespace subdiv
