#pragma once
// The control mesh refined uniformly with the scheme's own rules, for constructions that
// need more of it than the base mesh gives (the approximating patches, which are one per
// quad and read no semi-sharp tags: an n-gon becomes quads after one step of a quad split,
// a semi-sharp tag of sharpness s has decayed after ceil(s) steps, DeRose, Kass & Truong
// 1998), and where a point (face, u, v) of the base mesh lies on the refined level: in
// Bfr's parameterisation each child face of a binary split is a dyadic piece of its
// parent's domain (limit/face_domain.h), so the refined level's faces tile the base faces'
// domains and its limit is the base mesh's. Private to the limit layer.
#include <memory>
#include <span>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/features/feature_options.h"
#include "framework/limit/face_domain.h"
#include "framework/topology/level.h"

namespace subdiv {

struct Scheme;

// Uniform steps of a quad split after which every face of `base` is a quad and no edge or
// vertex sharpness lies strictly between 0 and infinitely sharp: 0 when the base has both
// already, else at least 1 for a face that is not a quad and ceil(s) for the largest
// semi-sharp s.
int steps_to_quads_without_semi_sharp(const Level& base);

class RefinedControlMesh {
public:
  // `steps` uniform steps of `scheme` (a binary quad split) from `base` with its positions
  // (xyz per vertex); 0 keeps the base mesh.
  RefinedControlMesh(const Scheme& scheme, const Level& base, std::span<const double> positions,
                     const FeatureOptions& features, int steps);

  int steps() const { return int(hierarchy_.levels.size()) - 1; }
  const Level& level() const { return hierarchy_.levels.back(); }
  std::span<const double> positions() const { return positions_; }
  // The base face a face of the refined level lies in.
  Index base_face(Index face) const { return base_face_[size_t(face)]; }

  // The face of the refined level holding the base point (face, u, v), the point's (s, t)
  // in it and d(s, t)/d(u, v). (face, u, v) must lie in the base face's domain
  // (LimitSurface::check); throws subdiv::Error otherwise.
  FacePoint locate(Index face, double u, double v) const;

private:
  Hierarchy hierarchy_;
  std::vector<double> positions_;
  std::vector<Index> base_face_;
  // Per step: the child faces of each parent face, grouped (offsets per parent face).
  std::vector<std::vector<Index>> child_offsets_, children_;
};

}  // namespace subdiv
