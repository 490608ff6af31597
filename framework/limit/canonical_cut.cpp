#include "framework/limit/canonical_cut.h"

#include <algorithm>
#include <vector>

#include "framework/analysis/surface/local_patch.h"

namespace subdiv {

void carry_sharpness(Level& L, const Level& cut, const Labelling& lab) {
  if (!cut.edge_sharpness.empty()) {
    L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
    for (Index e = 0; e < L.edge_count(); ++e) {
      const Index a = lab.vertices[size_t(L.edge_vertices[size_t(2 * e)])];
      const Index b = lab.vertices[size_t(L.edge_vertices[size_t(2 * e + 1)])];
      L.edge_sharpness[size_t(e)] = cut.edge_sharp(find_edge(cut, a, b));
    }
  }
  if (!cut.vertex_sharpness.empty()) {
    L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
    for (Index v = 0; v < L.vertex_count; ++v) L.vertex_sharpness[size_t(v)] = cut.vertex_sharp(lab.vertices[size_t(v)]);
  }
}

Level canonical_cut(const Level& cut, const Labelling& lab, Index face, Index& canonical_face) {
  std::vector<std::vector<Index>> faces;
  for (Index f = 0; f < cut.face_count(); ++f) {
    std::vector<Index> labels;
    for (Index v : cut.face(f)) labels.push_back(lab.label_of[size_t(v)]);
    if (f != face) std::rotate(labels.begin(), std::min_element(labels.begin(), labels.end()), labels.end());
    faces.push_back(std::move(labels));
  }
  std::vector<Index> order(faces.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = Index(i);
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return faces[size_t(a)] < faces[size_t(b)]; });
  std::vector<Index> offsets{0}, corners;
  for (Index f : order) {
    if (f == face) canonical_face = Index(offsets.size()) - 1;
    corners.insert(corners.end(), faces[size_t(f)].begin(), faces[size_t(f)].end());
    offsets.push_back(Index(corners.size()));
  }
  Level L = build_level(Index(lab.vertices.size()), offsets, corners);
  // Sharpness goes with the cut (the signature has it); hole tags do not (a hole removes
  // faces, not rules).
  carry_sharpness(L, cut, lab);
  return L;
}

}  // namespace subdiv
