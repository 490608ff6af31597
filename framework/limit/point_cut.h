#pragma once
// A point's face cut out of a level with the faces around it (analysis/surface/local_patch.h),
// the point renumbered into the cut: what an evaluator that follows a point down a split's
// refinement refines at each step. Private to the limit layer.
#include <vector>

#include "framework/limit/face_domain.h"
#include "framework/topology/level.h"

namespace subdiv {

struct PointCut {
  Level level;
  std::vector<Index> original;  // per vertex of the cut: its vertex in the level it was cut from
  FacePoint point;              // the point, its face numbered in the cut
};

// The faces within `radius` rings of p's face.
PointCut cut_around(const Level& level, const FacePoint& p, int radius);

}  // namespace subdiv
