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
// Steps past the second after which a neighbourhood that has not repeated is taken never to.
constexpr int kMaxStationarySteps = 8;

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

// The child face the dual split makes inside face f (its F-face), or kNone.
Index child_face_inside(const ChildOrigins& o, const Level& child, Index f) {
  for (Index g = 0; g < child.face_count(); ++g)
    if (o.parent_face[size_t(g)] == f) return g;
  return kNone;
}

// Whether a corner of face f lies on the boundary or on an infinitely sharp edge.
bool touches_crease(const Level& L, Index f) {
  for (Index v : L.face(f))
    for (Index e : L.ring_edges(v))
      if (L.edge_on_boundary(e) || L.edge_sharp(e) >= kInfinitelySharp) return true;
  return false;
}

// Whether the neighbourhood of b's centre within `radius` is a's, for one of b's starts
// (the dual split keeps a face's size, not necessarily which corner comes first); sets
// b.start to it.
bool same_neighbourhood(const Patch& a, Patch& b, int radius) {
  const std::vector<double> want = label_neighbourhood(a.level, CentreKind::Face, a.centre, a.start, radius).signature;
  Labelling scratch;
  for (int start = 0; start < b.level.face_size(b.centre); ++start)
    if (matches_neighbourhood(scratch, b.level, CentreKind::Face, b.centre, start, radius, want)) {
      b.start = start;
      return true;
    }
  return false;
}

// Face rings between the analysed rings and the cut of a level, so that no crease point the
// analysis reads finds the cut's corners: a crease point looks for its corners as far as the
// scheme's rules by distance from a corner reach (at most kMaxCreaseLength - 1 crease edges),
// on the level its passes run on, which has twice the crease edges of the level they start
// from (about one crease edge per face ring around the centre).
int crease_end_margin(const Scheme& scheme) {
  int reach = 0;
  for (const StepRules& step : scheme.steps) reach = std::max(reach, step.crease_ends.search_reach());
  return (reach + 1) / 2 + 2;
}

// Refines the sector face's patch until its neighbourhood within the rings the analysis
// labels repeats from one level to the next. Two steps are not enough: a side of three or
// more faces makes a sector face at the crease vertex, and both of that vertex's child crease
// points again have the side's faces plus that sector face around them, so the crease points
// with the extra face double in number every level while the faces halve in size — only a
// growing number of rings around the centre has its final shape (for a side of three faces,
// the 1-ring after two steps, the 3-ring after three). Each level is cut to the faces within
// `rings` of the centre plus crease_end_margin: the cut ends the crease in corners there, but
// no point the analysis reads takes a rule by distance from a corner, so the crease looks
// infinite, as the configuration says.
Patch refine_until_stationary(const Scheme& scheme, const LocalConfig& config, Patch p, int rings,
                              const FeatureOptions& features) {
  const int radius = rings - 1;  // what the analysis labels (its max ring + 2)
  const int keep = rings + crease_end_margin(scheme);
  RefineOptions ro;
  ro.levels = splitter_info(scheme.split()).period;  // a split that turns the mesh repeats after its period
  ro.features = features;
  for (int level = 0; level < kMaxStationarySteps; ++level) {
    const Extracted e = extract_neighbourhood(p.level, CentreKind::Face, p.centre, keep);
    Patch cut;
    cut.level = e.level;
    cut.centre_kind = CentreKind::Face;
    cut.start = p.start;
    cut.xy.resize(size_t(2 * e.level.vertex_count));
    for (Index v = 0; v < e.level.vertex_count; ++v)
      for (int c = 0; c < 2; ++c) cut.xy[size_t(2 * v + c)] = p.xy[size_t(2 * e.original[size_t(v)] + c)];
    cut.centre = Index(std::find(e.face_original.begin(), e.face_original.end(), p.centre) - e.face_original.begin());
    const Hierarchy h = refine(scheme, cut.level, ro);
    Patch next;
    next.level = h.levels.back();
    next.xy = cut.xy;
    next.centre = cut.centre;
    for (size_t s = 0; s < h.stencils.size() && next.centre != kNone; ++s) {
      next.xy = h.stencils[s].apply(next.xy, 2);
      next.centre = child_face_inside(h.origins[s], h.levels[s + 1], next.centre);
    }
    next.centre_kind = CentreKind::Face;
    // A split whose boundary or crease does not refine (mid-edge: the polygon of edge
    // midpoints keeps its edges) leaves the face behind, off the crease: there is no
    // neighbourhood of the sector's face that repeats, and the analysis keeps the last one.
    if (next.centre == kNone || !touches_crease(next.level, next.centre)) return cut;
    if (same_neighbourhood(cut, next, radius)) return cut;
    p = std::move(next);
  }
  throw Error(fmt::format("{}: the sector's face's neighbourhood within {} rings does not repeat after {} more steps",
                          config.describe(), radius, kMaxStationarySteps));
}


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
                            "points and gains a corner at each corner between two crease edges every level), so no "
                            "neighbourhood of the crease vertex repeats",
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
  out.centre = child_face_inside(h.origins[1], out.level, best);
  if (out.centre == kNone) throw Error(fmt::format("{}: the sector's face has no child face", config.describe()));
  out.start = 0;
  return refine_until_stationary(scheme, config, std::move(out), rings, features);
}

}  // namespace subdiv
