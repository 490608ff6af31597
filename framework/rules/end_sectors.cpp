#include "framework/rules/end_sectors.h"

#include "framework/util/distinct_values.h"

namespace subdiv {
namespace {

// The gaps between consecutive feature edges in v's ring (end_sector's sectors).
template <class Add>
void report_sectors(const Level& L, Index v, Add add) {
  if (L.non_manifold_vertex(v)) return;
  if (L.edge_sharpness.empty()) {
    // Only boundary edges are features: a boundary vertex's ring runs from one to the other.
    if (L.on_boundary(v)) add(L.valence(v) - 1);
    return;
  }
  const auto ring = L.ring_edges(v);
  const int n = int(ring.size());
  int first = -1, previous = -1;
  for (int i = 0; i < n; ++i) {
    if (!L.edge_on_boundary(ring[i]) && !(L.edge_sharpness[ring[i]] > 0.f)) continue;
    if (previous >= 0) add(i - previous);
    if (first < 0) first = i;
    previous = i;
  }
  if (first >= 0 && previous != first) add(first + n - previous);
}

}  // namespace

std::vector<int> sector_sizes_present(const Level& L) {
  return distinct_values(L.vertex_count, Index(1 << 14), [&L](Index v, auto add) { report_sectors(L, v, add); });
}

EndSector end_sector(const Level& L, const FeatureContexts& F, Index e, Index end) {
  auto feature = [&](Index edge) { return F.edge_sharpness[edge] > 0.f; };
  if (feature(e) || L.non_manifold_vertex(end)) return {};
  const auto ring = L.ring_edges(end);
  const int n = int(ring.size());
  int features = 0, at = -1;
  for (int i = 0; i < n; ++i) {
    features += feature(ring[i]);
    if (ring[i] == e) at = i;
  }
  if (features < 2 || at < 0) return {};
  // A boundary vertex's ring runs from one boundary edge to the other, so no walk crosses its
  // gap: both ends of the gap are feature edges.
  int first = at, last = at;
  while (!feature(ring[first])) first = (first + n - 1) % n;
  while (!feature(ring[last])) last = (last + 1) % n;
  return {first, (last - first + n) % n, (at - first + n) % n};
}

SectorVariables sector_variables(const EndSector& at_a, const EndSector& at_b) {
  SectorVariables s;
  s.b[0] = at_a.faces > 0, s.m[0] = at_a.faces, s.e[0] = at_a.index;
  s.b[1] = at_b.faces > 0, s.m[1] = at_b.faces, s.e[1] = at_b.index;
  return s;
}

}  // namespace subdiv
