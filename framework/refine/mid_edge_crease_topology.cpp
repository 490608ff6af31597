#include "framework/refine/mid_edge_crease_topology.h"

#include "framework/features/dual_features.h"
#include "framework/features/sharpness.h"

namespace subdiv {
namespace {

// Appends a face with consecutive repeats (cyclically) dropped, if 3 or more corners remain.
void add_face(std::vector<Index>& offsets, std::vector<Index>& verts, const std::vector<Index>& face) {
  std::vector<Index> kept;
  for (size_t i = 0; i < face.size(); ++i)
    if (face[i] != face[(i + 1) % face.size()]) kept.push_back(face[i]);
  if (kept.size() < 3) return;
  verts.insert(verts.end(), kept.begin(), kept.end());
  offsets.push_back(Index(verts.size()));
}

// The faces of v's sectors: its ring edges from one sharp edge to the next, both included; a
// boundary vertex's last sharp ring edge (the boundary) closes the fan instead of opening one.
void add_sector_faces(const Level& L, Index v, std::vector<Index>& offsets, std::vector<Index>& verts) {
  const auto ring = L.ring_edges(v);
  const Index n = Index(ring.size());
  std::vector<Index> cuts;
  for (Index j = 0; j < n; ++j)
    if (dual_sharp_edge(L, ring[j])) cuts.push_back(j);
  if (cuts.empty()) return add_face(offsets, verts, std::vector<Index>(ring.begin(), ring.end()));
  const bool boundary = L.on_boundary(v);
  for (size_t s = 0; s < cuts.size(); ++s) {
    if (boundary && s + 1 == cuts.size()) break;
    const Index first = cuts[s], last = s + 1 < cuts.size() ? cuts[s + 1] : cuts[0] + n;
    std::vector<Index> face;
    for (Index j = first; j <= last; ++j) face.push_back(ring[j % n]);
    add_face(offsets, verts, face);
  }
}

// The edge closing a sector at v, between the points of two consecutive sharp edges, is a
// crease edge of the child: it carries the mean of their child sharpness at v (features/
// sharpness.h; a boundary edge counts as infinitely sharp), uniform decay in the child and
// Chaikin's in `averaged`.
void tag_closing_edges(const Level& L, Level& C, std::vector<float>& averaged) {
  C.edge_sharpness.assign(size_t(C.edge_count()), 0.f);
  averaged.assign(C.edge_sharpness.size(), 0.f);
  for (Index v = 0; v < L.vertex_count; ++v) {
    if (L.non_manifold_vertex(v)) continue;
    std::vector<Index> sharp;
    for (Index e : L.ring_edges(v))
      if (dual_sharp_edge(L, e)) sharp.push_back(e);
    for (size_t i = 0; sharp.size() >= 2 && i < sharp.size(); ++i) {
      const Index a = sharp[i], b = sharp[(i + 1) % sharp.size()];
      const Index e = find_edge(C, a, b);
      if (e == kNone || C.edge_on_boundary(e)) continue;
      auto mean = [&](CreaseMethod m) { return 0.5f * (child_edge_sharpness(L, a, v, m) + child_edge_sharpness(L, b, v, m)); };
      C.edge_sharpness[e] = mean(CreaseMethod::Uniform);
      averaged[e] = mean(CreaseMethod::Chaikin);
    }
  }
  if (averaged == C.edge_sharpness) averaged.clear();
}

}  // namespace

bool mid_edge_needs_crease_topology(const Level& L) {
  for (Index e = 0; e < Index(L.edge_sharpness.size()); ++e)
    if (!L.edge_on_boundary(e) && L.edge_sharpness[e] >= 1.f) return true;
  return false;
}

Level mid_edge_crease_split(const Level& L, bool full, Index* skipped_vertices, std::vector<float>* averaged) {
  std::vector<Index> offsets{0}, verts;
  for (Index f = 0; f < L.face_count(); ++f) {
    const auto edges = L.face_edge_list(f);
    verts.insert(verts.end(), edges.begin(), edges.end());
    offsets.push_back(Index(verts.size()));
  }
  for (Index v = 0; v < L.vertex_count; ++v) {
    if (L.non_manifold_vertex(v)) {
      ++*skipped_vertices;
      continue;
    }
    if (L.incident_face_count(v) > 0) add_sector_faces(L, v, offsets, verts);
  }
  if (!full) {
    Level C;
    C.vertex_count = L.edge_count();
    C.face_offsets.assign(offsets.begin(), offsets.end());
    C.face_vertices.assign(verts.begin(), verts.end());
    return C;
  }
  Level C = build_level(L.edge_count(), offsets, verts);
  tag_closing_edges(L, C, *averaged);
  return C;
}

}  // namespace subdiv
