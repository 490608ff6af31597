#include "framework/limit/point_cut.h"

#include "framework/analysis/surface/local_patch.h"

namespace subdiv {

PointCut cut_around(const Level& level, const FacePoint& p, int radius) {
  Extracted e = extract_neighbourhood(level, CentreKind::Face, p.face, radius);
  PointCut c;
  c.level = std::move(e.level);
  c.original = std::move(e.original);
  c.point = p;
  for (size_t f = 0; f < e.face_original.size(); ++f)
    if (e.face_original[f] == p.face) c.point.face = Index(f);
  return c;
}

}  // namespace subdiv
