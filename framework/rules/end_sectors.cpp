#include "framework/rules/end_sectors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace subdiv {
namespace {

using SizesSeen = std::vector<char>;  // SizesSeen[m]: a sector of m faces is present

void mark(SizesSeen& seen, int m) {
  if (size_t(m) >= seen.size()) seen.resize(size_t(m) + 1, 0);
  seen[size_t(m)] = 1;
}

// The gaps between consecutive feature edges in v's ring (end_sector's sectors).
void mark_sectors(const Level& L, Index v, SizesSeen& seen) {
  if (L.non_manifold_vertex(v)) return;
  if (L.edge_sharpness.empty()) {
    // Only boundary edges are features: a boundary vertex's ring runs from one to the other.
    if (L.on_boundary(v)) mark(seen, L.valence(v) - 1);
    return;
  }
  const auto ring = L.ring_edges(v);
  const int n = int(ring.size());
  int first = -1, previous = -1;
  for (int i = 0; i < n; ++i) {
    if (!L.edge_on_boundary(ring[i]) && !(L.edge_sharpness[ring[i]] > 0.f)) continue;
    if (previous >= 0) mark(seen, i - previous);
    if (first < 0) first = i;
    previous = i;
  }
  if (first >= 0 && previous != first) mark(seen, first + n - previous);
}

}  // namespace

std::vector<int> sector_sizes_present(const Level& L) {
  const SizesSeen seen = tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, L.vertex_count, 1 << 14), SizesSeen{},
      [&L](const tbb::blocked_range<Index>& r, SizesSeen s) {
        for (Index v = r.begin(); v < r.end(); ++v) mark_sectors(L, v, s);
        return s;
      },
      [](SizesSeen a, const SizesSeen& b) {
        if (b.size() > a.size()) a.resize(b.size(), 0);
        for (size_t m = 0; m < b.size(); ++m) a[m] |= b[m];
        return a;
      });
  std::vector<int> sizes;
  for (size_t m = 0; m < seen.size(); ++m)
    if (seen[m]) sizes.push_back(int(m));
  return sizes;
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
