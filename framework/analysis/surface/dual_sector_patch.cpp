#include "framework/analysis/surface/dual_sector_patch.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

const double kPi = std::acos(-1.0);

// Ring positions (rays) bounding the first sector: 0 and the next sharp ray, or the
// boundary's last ray.
int sector_end(const LocalConfig& c) {
  int end = c.boundary ? c.valence - 1 : c.valence;
  for (int r : c.sharp)
    if (r > 0) end = std::min(end, r);
  return end;
}

// Child vertices made at the centre vertex: corner points of its faces (Doo-Sabin's split),
// points of its edges (mid-edge's).
bool is_centre_corner(const Level& parent, const ChildOrigins& o, Index child, Index centre) {
  const Index p = o.parent[size_t(child)];
  switch (o.kind[size_t(child)]) {
    case OriginKind::Corner: return parent.face(p)[o.local[size_t(child)]] == centre;
    case OriginKind::Edge: return parent.edge_vertices[size_t(2 * p)] == centre || parent.edge_vertices[size_t(2 * p + 1)] == centre;
    default: return false;
  }
}

double direction_of(double x, double y) { return std::atan2(y, x); }


}  // namespace

int first_sector_faces(const LocalConfig& c) { return sector_end(c); }

Patch make_dual_sector_patch(const Scheme& scheme, const LocalConfig& config, int rings, const FeatureOptions& features) {
  LocalConfig primal = config;
  primal.centre = CentreKind::Vertex;
  const int faces = sector_end(config);
  if (config.corner || (config.sharp.size() > 2) || (config.boundary && !config.sharp.empty()))
    throw Error(fmt::format("{}: a corner's points collapse into one (the corner stays); there is no face to analyse",
                            config.describe()));
  if (faces < 2)
    throw Error(fmt::format("{}: a sector of {} face{} makes no face of its own (its F-face holds both crease "
                            "points); analyse at least two faces between the sharp edges",
                            config.describe(), faces, faces == 1 ? "" : "s"));
  const Patch p = make_vertex_patch(PatchCells::Quads, primal, rings + 1);
  // Two steps: after one, the sector face's boundary or crease corners have the F-faces of
  // the old faces beside them; from the second step on they have the sector faces of the
  // first step's crease points, and the neighbourhood repeats.
  RefineOptions ro;
  ro.levels = 2;
  ro.features = features;
  const Hierarchy h = refine(scheme, p.level, ro);
  const Level& P = p.level;
  const Level& C = h.levels[1];
  const ChildOrigins& o = h.origins.front();
  const std::vector<double> xy = h.stencils.front().apply(p.xy, 2);

  // The sector's face: among the child faces lying in the sector's angle (from ray 0 to the
  // sector's last ray, CCW), the one with the most points made at the centre (the sector's
  // V-face, or for a sector of two faces the E-face between them).
  const auto ring = P.ring_edges(p.centre);
  auto ray_angle = [&](int r) {
    const Index q = P.other_end(ring[size_t((p.start + r) % int(ring.size()))], p.centre);
    return direction_of(p.xy[size_t(2 * q)] - p.xy[size_t(2 * p.centre)], p.xy[size_t(2 * q + 1)] - p.xy[size_t(2 * p.centre + 1)]);
  };
  const double from = ray_angle(0);
  auto ccw_from_ray0 = [&](double a) { return std::fmod(a - from + 4 * kPi, 2 * kPi); };
  const double span = ccw_from_ray0(ray_angle(faces % int(ring.size())));
  Index best = kNone;
  int best_count = 0;
  for (Index g = 0; g < C.face_count(); ++g) {
    int at_centre = 0;
    double cx = 0, cy = 0;
    for (Index v : C.face(g)) {
      at_centre += is_centre_corner(P, o, v, p.centre);
      cx += xy[size_t(2 * v)] - p.xy[size_t(2 * p.centre)], cy += xy[size_t(2 * v + 1)] - p.xy[size_t(2 * p.centre + 1)];
    }
    const double a = ccw_from_ray0(direction_of(cx, cy));
    if (at_centre < 2 || a <= 0 || a >= span) continue;
    if (at_centre > best_count) best = g, best_count = at_centre;
  }
  if (best == kNone) throw Error(fmt::format("{}: the dual split made no face for the sector", config.describe()));
  Patch out;
  out.level = h.levels[2];
  out.xy = h.stencils[1].apply(xy, 2);
  out.centre_kind = CentreKind::Face;
  out.centre = kNone;
  const auto& inside = h.origins[1].parent_face;
  for (Index g = 0; g < out.level.face_count() && out.centre == kNone; ++g)
    if (inside[size_t(g)] == best) out.centre = g;
  if (out.centre == kNone) throw Error(fmt::format("{}: the sector's face has no child face", config.describe()));
  out.start = 0;
  return out;
}

}  // namespace subdiv
