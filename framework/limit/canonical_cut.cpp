#include "framework/limit/canonical_cut.h"

#include <algorithm>
#include <vector>

#include "framework/analysis/surface/local_patch.h"

namespace subdiv {

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
  return build_level(Index(lab.vertices.size()), offsets, corners);
}

}  // namespace subdiv
