#include "framework/limit/refined_control_mesh.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "framework/features/sharpness.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

bool semi_sharp(float s) { return s > 0.f && s < kInfinitelySharp; }

}  // namespace

int steps_to_quads_without_semi_sharp(const Level& base) {
  float largest = 0.f;
  for (Index e = 0; e < base.edge_count(); ++e)
    if (semi_sharp(base.edge_sharp(e))) largest = std::max(largest, base.edge_sharp(e));
  for (Index v = 0; v < base.vertex_count; ++v)
    if (semi_sharp(base.vertex_sharp(v))) largest = std::max(largest, base.vertex_sharp(v));
  int steps = int(std::ceil(largest));
  for (Index f = 0; f < base.face_count() && steps == 0; ++f)
    if (base.face_size(f) != 4) steps = 1;
  return steps;
}

RefinedControlMesh::RefinedControlMesh(const Scheme& scheme, const Level& base, std::span<const double> positions,
                                       const FeatureOptions& features, int steps)
    : positions_(positions.begin(), positions.end()) {
  RefineOptions options;
  options.levels = steps;
  options.features = features;
  if (steps > 0) {
    hierarchy_ = refine(scheme, base, options);
    for (int s = 0; s < steps; ++s) positions_ = apply_step(hierarchy_, s, positions_, 3);
  } else {
    hierarchy_.levels.push_back(base);
  }
  base_face_.resize(size_t(level().face_count()));
  for (Index f = 0; f < level().face_count(); ++f) {
    Index g = f;
    for (int s = steps; s > 0; --s) g = hierarchy_.origins[size_t(s - 1)].parent_face[size_t(g)];
    base_face_[size_t(f)] = g;
  }
  for (int s = 0; s < steps; ++s) {
    const ChildOrigins& o = hierarchy_.origins[size_t(s)];
    const Index parents = hierarchy_.levels[size_t(s)].face_count();
    std::vector<Index> offsets(size_t(parents) + 1, 0), children(o.parent_face.size());
    for (size_t g = 0; g < o.parent_face.size(); ++g) ++offsets[size_t(o.parent_face[g]) + 1];
    for (size_t f = 0; f < size_t(parents); ++f) offsets[f + 1] += offsets[f];
    std::vector<Index> next(offsets.begin(), offsets.end() - 1);
    for (size_t g = 0; g < o.parent_face.size(); ++g) children[size_t(next[size_t(o.parent_face[g])]++)] = Index(g);
    child_offsets_.push_back(std::move(offsets));
    children_.push_back(std::move(children));
  }
}

FacePoint RefinedControlMesh::locate(Index face, double u, double v) const {
  const char* why = "";
  std::optional<FacePoint> p = base_face_point(hierarchy_.levels[0], face, u, v, false, &why);
  for (int s = 0; p && s < steps(); ++s) {
    const std::vector<Index>& offsets = child_offsets_[size_t(s)];
    const std::span<const Index> candidates(children_[size_t(s)].data() + offsets[size_t(p->face)],
                                            size_t(offsets[size_t(p->face) + 1] - offsets[size_t(p->face)]));
    const std::vector<ChildFace> children = child_faces(hierarchy_.levels[size_t(s)], hierarchy_.levels[size_t(s) + 1],
                                                        hierarchy_.origins[size_t(s)], *p, false, candidates);
    p = subdiv::locate(children, *p, false, nullptr);
    why = "no child face of the refined level holds it";
  }
  if (!p) throw Error(fmt::format("face {}, (u, v) = ({}, {}): {}", face, u, v, why));
  return *p;
}

}  // namespace subdiv
