#include "framework/limit/dual_limit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <fmt/format.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/local_patch.h"
#include "framework/engine/refiner.h"
#include "framework/features/sharpness.h"
#include "framework/limit/biquadratic_patch.h"
#include "framework/limit/cut_weight_tables.h"
#include "framework/limit/dual_crease_chart.h"
#include "framework/limit/dual_crease_curve.h"
#include "framework/limit/dual_crease_strip.h"
#include "framework/limit/step_matrix.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// A quadrant coordinate as its distance x <= 1/2 from the nearer end, 0 or 1 (`high`): the
// step to a child quadrant maps a to 1 - 2 min(a, 1 - a), which is exactly 2x measured from
// 1, so a point 1e-300 from a vertex keeps every digit (1 - 2a would round to 1).
struct Coord {
  double x = 0;
  bool high = false;
  double value() const { return high ? 1 - x : x; }
  bool upper_half() const { return high || x == 0.5; }
  static Coord of(double a) { return a > 0.5 ? Coord{1 - a, true} : Coord{a, false}; }
  // The coordinate in a child quadrant, measured from the new point at 1/2.
  Coord child() const { return 2 * x > 0.5 ? Coord{1 - 2 * x, false} : Coord{2 * x, true}; }
};
using Coords = std::array<Coord, 2>;
Uv as_uv(const Coords& c) { return {c[0].value(), c[1].value()}; }
Coords coords(const Uv& ab) { return {Coord::of(ab[0]), Coord::of(ab[1])}; }

// A point in quadrant (face, corner) of a cut, with d(a, b)/d(u, v) carried as 2^-k times
// its value after k halvings (step_matrix.h: derivative rows then stay of order one).
struct QuadrantPoint {
  Index face = kNone;
  int corner = 0;
  Coords ab{};
  Jacobian jacobian{{{1, 0}, {0, 1}}};
};

// The current cut: a level around the point's face, and its vertices in the level it was cut from.
struct Cut {
  Level level;
  std::vector<Index> original;
  QuadrantPoint point;
  CreaseRun chart;  // the crease run the point's quadrant is laid out by (dual_crease_chart.h)
};

Cut cut_around(const Level& L, Index face, int radius) {
  Extracted e = extract_neighbourhood(L, CentreKind::Face, face, radius);
  Cut c;
  c.level = std::move(e.level);
  c.original = std::move(e.original);
  for (size_t f = 0; f < e.face_original.size(); ++f)
    if (e.face_original[f] == face) c.point.face = Index(f);
  return c;
}

// A point (u, v) of quad `face` of L in its quadrant: the quad's quarter at the nearest corner,
// or for a half quad (dual_crease_chart.h) the quadrant of a corner off the crease that holds
// it; the Jacobian is d(a, b)/d(u, v) halved once (the first step has scale 2).
QuadrantPoint quad_quadrant(const Level& L, Index face, double u, double v) {
  QuadrantPoint q;
  q.face = face;
  if (const auto run = crease_run(L, face); run && run->length > 0) {
    double best = -1;
    for (int k = 0; k < 4; ++k) {
      if (((k - run->first + 4) % 4) < run->length) continue;
      const QuadrantChart c = half_quad_quadrant(*run, k);
      // (u, v) - origin = a to_a + b to_b, solved by Cramer's rule.
      const double det = c.to_a[0] * c.to_b[1] - c.to_a[1] * c.to_b[0];
      const double du = u - c.origin[0], dv = v - c.origin[1];
      const double a = (du * c.to_b[1] - dv * c.to_b[0]) / det, b = (c.to_a[0] * dv - c.to_a[1] * du) / det;
      const double inside = std::min(std::min(a, 1 - a), std::min(b, 1 - b));
      if (inside <= best) continue;
      best = inside;
      q.corner = k;
      q.ab = coords({std::clamp(a, 0.0, 1.0), std::clamp(b, 0.0, 1.0)});
      q.jacobian = {{{c.to_b[1] / det / 2, -c.to_b[0] / det / 2}, {-c.to_a[1] / det / 2, c.to_a[0] / det / 2}}};
    }
    return q;
  }
  constexpr Uv kCorner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const int k = u <= 0.5 ? (v <= 0.5 ? 0 : 3) : (v <= 0.5 ? 1 : 2);
  const Uv& c = kCorner[k];
  const Uv e{kCorner[(k + 1) % 4][0] - c[0], kCorner[(k + 1) % 4][1] - c[1]};
  const Uv f{kCorner[(k + 3) % 4][0] - c[0], kCorner[(k + 3) % 4][1] - c[1]};
  q.corner = k;
  q.ab = coords({std::clamp(2 * (e[0] * (u - c[0]) + e[1] * (v - c[1])), 0.0, 1.0),
                 std::clamp(2 * (f[0] * (u - c[0]) + f[1] * (v - c[1])), 0.0, 1.0)});
  q.jacobian = {{{e[0], e[1]}, {f[0], f[1]}}};
  return q;
}

// The base point in its quadrant: an n-gon's sub-face as it is (base_face_point already gives
// its (a, b) and d(a, b)/d(u, v) = 2), a quad's by quad_quadrant.
QuadrantPoint base_quadrant(const Level& base, const FacePoint& p) {
  if (p.sub_face < 0) return quad_quadrant(base, p.face, p.st[0], p.st[1]);
  QuadrantPoint q;
  q.face = p.face;
  q.corner = p.sub_face;
  q.ab = coords(p.st);
  q.jacobian = {{{1, 0}, {0, 1}}};  // halved once: the first step has scale 2
  return q;
}

StepMatrix identity_step(Index n) {
  StepMatrix m;
  m.source_count = n;
  m.scale = 2;
  for (Index v = 0; v < n; ++v) {
    m.columns.push_back(v);
    m.weights.push_back(1.0);
    m.offsets.push_back(Index(m.columns.size()));
  }
  return m;
}

// One dual step of quadrant (g, j): the new point c of corner (g, j) at (1/2, 1/2); the
// new face around c whose centre is at the quadrant's corner K holds the quarter between c
// and K. Its quadrant at c has (0, 0) at c and (1, 1) at K, oriented like the parent's
// (both frames are counter-clockwise), which fixes which parent axis becomes a'.
//
// c is a smooth point (the corner is not a crease corner, dual_crease_chart.h), so it has
// four faces, counter-clockwise: g's F-face (centre K = (1, 1)), the E-face of edge j - 1
// ((0, 1)), the V-face of g[j] ((0, 0)), the E-face of edge j ((1, 0)). Taking them by
// their order around c rather than by where their corners come from also holds next to a
// crease, where a crease point shared by two faces records only one of them as its origin.
struct ChildStep {
  Index face = kNone;
  int corner = 0;
  Coords ab{};
  Jacobian jacobian{};
};

ChildStep child_quadrant(const Level& child, const ChildOrigins& o, const QuadrantPoint& p) {
  Index c = kNone;
  for (size_t v = 0; v < o.kind.size(); ++v)
    if (o.kind[v] == OriginKind::Corner && o.parent[v] == p.face && int(o.local[v]) == p.corner &&
        (o.corner_side.empty() || o.corner_side[v] == 0)) {
      c = Index(v);
      break;
    }
  if (c == kNone) throw Error("internal: the corner has no new point (the split is not a dual one)");
  const auto ring = child.ring_faces(c);
  if (ring.size() != 4 || child.on_boundary(c))
    throw Error("internal: the new point of a quadrant's corner is not a smooth point of four faces");
  int f_at = -1;
  for (int k = 0; k < 4; ++k)
    if (o.parent_face[size_t(ring[size_t(k)])] == p.face) f_at = k;
  if (f_at < 0) throw Error("internal: the F-face is not around the corner's new point");
  const int sa = p.ab[0].upper_half() ? 1 : -1, sb = p.ab[1].upper_half() ? 1 : -1;
  // Counter-clockwise from the F-face: (1, 1), (0, 1), (0, 0), (1, 0).
  const int step = sa > 0 ? (sb > 0 ? 0 : 3) : (sb > 0 ? 1 : 2);
  ChildStep s;
  s.face = ring[size_t((f_at + step) % 4)];
  s.corner = -1;
  const auto g = child.face(s.face);
  for (size_t k = 0; k < g.size(); ++k)
    if (g[k] == c) s.corner = int(k);
  // (a', b') = M (a - 1/2, b - 1/2) with det M > 0 (so each is 2 |a - 1/2| or 2 |b - 1/2|,
  // Coord::child); M halved is carried into the Jacobian.
  std::array<std::array<double, 2>, 2> M;
  if (sa * sb > 0) {
    M = {{{double(sa), 0}, {0, double(sb)}}};
    s.ab = {p.ab[0].child(), p.ab[1].child()};
  } else {
    M = {{{0, double(sb)}, {double(sa), 0}}};
    s.ab = {p.ab[1].child(), p.ab[0].child()};
  }
  for (int r = 0; r < 2; ++r)
    for (int q = 0; q < 2; ++q)
      s.jacobian[size_t(r)][size_t(q)] = M[size_t(r)][0] * p.jacobian[0][size_t(q)] + M[size_t(r)][1] * p.jacobian[1][size_t(q)];
  return s;
}

// Where a semi-sharp crease has decayed (its edges no longer sharp for the next split), a
// face laid out by the crease run it was made with is laid out by its own run: none (a closed
// face's quadrants), or a shorter one where a corner of the mesh stopped collapsing (a boundary
// or crease vertex, once the semi-sharp edges that made it a corner are smooth). The point
// moves through the quad's (u, v), with d(a', b')/d(a, b) carried into the Jacobian.
void follow_decay(Cut& cut) {
  const auto own = crease_run(cut.level, cut.point.face);
  if (!own) throw Error("the point's face lies between two creases (its crease corners are not one run)");
  const CreaseRun was = cut.chart;
  if (own->length == was.length && (was.length == 0 || own->first == was.first)) return;
  if (was.length == 0 || own->length >= was.length || cut.level.face_size(cut.point.face) != 4)
    throw Error("a semi-sharp crease changes shape as it decays (its edges or corner decay at different levels): "
                "not evaluated yet");
  QuadrantPoint& q = cut.point;
  const QuadrantChart c = half_quad_quadrant(was, q.corner);
  const Uv ab = as_uv(q.ab);
  const double u = c.origin[0] + ab[0] * c.to_a[0] + ab[1] * c.to_b[0];
  const double v = c.origin[1] + ab[0] * c.to_a[1] + ab[1] * c.to_b[1];
  const QuadrantPoint to = quad_quadrant(cut.level, q.face, u, v);
  // d(a', b')/d(a, b) = 2 (to's halved Jacobian) [to_a to_b].
  Jacobian J{};
  for (size_t r = 0; r < 2; ++r)
    for (size_t x = 0; x < 2; ++x) {
      const double d0 = 2 * (to.jacobian[r][0] * c.to_a[0] + to.jacobian[r][1] * c.to_a[1]);
      const double d1 = 2 * (to.jacobian[r][0] * c.to_b[0] + to.jacobian[r][1] * c.to_b[1]);
      J[r][x] = d0 * q.jacobian[0][x] + d1 * q.jacobian[1][x];
    }
  q.corner = to.corner;
  q.ab = to.ab;
  q.jacobian = J;
  cut.chart = *own;
}

Coords nearest_corner(const Coords& ab) { return {Coord{0, ab[0].high}, Coord{0, ab[1].high}}; }

// The 3 x 3 points around the quadrant's corner w when the surface over the quadrant is the
// biquadratic B-spline's patch: w and its eight neighbours interior, of valence 4, untagged,
// with no sharp edge (so every new point of the four faces around w, and of their children
// around the quadrant, takes the smooth rule at every level). Boundaries and creases further
// away do not reach the quadrant: each new point reads only its own face's corners. Holes
// change no rule (only which faces are kept), so they do not matter here.
std::optional<std::array<Index, 9>> smooth_biquadratic_grid(const Level& L, Index face, int corner) {
  const auto grid = biquadratic_grid(L, face, corner);
  if (!grid) return std::nullopt;
  for (Index v : *grid) {
    if (L.on_boundary(v) || L.vertex_sharp(v) != 0 || L.incident_face_count(v) != 4) return std::nullopt;
    for (Index e : L.ring_edges(v))
      if (L.edge_sharp(e) != 0) return std::nullopt;
  }
  return grid;
}

// A quad between two infinitely sharp creases, never refined across: the ruled surface
// between the two crease curves (dual_crease_strip.h), with its derivatives.
LimitSample strip_sample(const Cut& cut, CreaseStrip strip, const FacePoint& p, const std::vector<double>& values,
                         int channels, int derivatives, DualLimit::Rows* rows_out) {
  const auto rows = crease_strip_limit(cut.level, cut.point.face, strip, p.st[0], p.st[1]);
  if (!rows) throw Error(fmt::format("face {} lies between two creases that end inside the surface", p.face));
  LimitSample out;
  out.position = applied((*rows)[0], values, channels);
  if (derivatives >= 1) {
    out.du = applied((*rows)[1], values, channels);
    out.dv = applied((*rows)[2], values, channels);
    out.has_derivatives = true;
    if (rows_out) rows_out->du = (*rows)[1], rows_out->dv = (*rows)[2];
  }
  if (derivatives >= 2) {
    out.duu = applied((*rows)[3], values, channels);
    out.duv = applied((*rows)[4], values, channels);
    out.dvv = applied((*rows)[5], values, channels);
    out.has_second_derivatives = true;
    if (rows_out) rows_out->duu = (*rows)[3], rows_out->duv = (*rows)[4], rows_out->dvv = (*rows)[5];
  }
  return out;
}

}  // namespace

std::optional<FacePoint> dual_child_point(const Level& parent, const Level& child, const ChildOrigins& o,
                                          const FacePoint& p) {
  constexpr Uv kCorner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  if (p.sub_face < 0 && parent.face_size(p.face) != 4) return std::nullopt;
  // The point in its quadrant, with the true d(a, b)/d(u, v).
  QuadrantPoint q;
  q.face = p.face;
  if (p.sub_face >= 0) {
    q.corner = p.sub_face, q.ab = coords(p.st), q.jacobian = p.jacobian;
  } else {
    const QuadrantPoint b = base_quadrant(parent, p);  // its Jacobian: 2 [e; f] halved once
    q.corner = b.corner, q.ab = b.ab;
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c)
        q.jacobian[size_t(r)][size_t(c)] =
            2 * (b.jacobian[size_t(r)][0] * p.jacobian[0][size_t(c)] + b.jacobian[size_t(r)][1] * p.jacobian[1][size_t(c)]);
  }
  const ChildStep s = child_quadrant(child, o, q);  // its Jacobian: M J, the true one 2 M J
  FacePoint out;
  out.face = s.face;
  if (child.face_size(s.face) != 4) {
    out.sub_face = s.corner;
    out.st = as_uv(s.ab);
    for (auto& row : out.jacobian) row = {0, 0};
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) out.jacobian[size_t(r)][size_t(c)] = 2 * s.jacobian[size_t(r)][size_t(c)];
    return out;
  }
  // A quad laid out by a crease run (dual_crease_chart.h): (u, v) = origin + a to_a + b to_b.
  if (const auto run = made_on_crease_run(parent, child, o, s.face); run && run->length > 0) {
    const QuadrantChart c = half_quad_quadrant(*run, s.corner);
    const Uv ab = as_uv(s.ab);
    out.st = {c.origin[0] + ab[0] * c.to_a[0] + ab[1] * c.to_b[0], c.origin[1] + ab[0] * c.to_a[1] + ab[1] * c.to_b[1]};
    for (int r = 0; r < 2; ++r)
      for (int k = 0; k < 2; ++k)  // d(u, v)/d(a, b) = [to_a to_b], times the true 2 M J
        out.jacobian[size_t(r)][size_t(k)] =
            2 * (c.to_a[size_t(r)] * s.jacobian[0][size_t(k)] + c.to_b[size_t(r)] * s.jacobian[1][size_t(k)]);
    return out;
  }
  // A quad's quadrant j: (u, v) = c_j + (a/2) e + (b/2) f, e towards corner j + 1, f towards j - 1.
  const int j = s.corner;
  const Uv& c = kCorner[j];
  const Uv e{kCorner[(j + 1) % 4][0] - c[0], kCorner[(j + 1) % 4][1] - c[1]};
  const Uv f{kCorner[(j + 3) % 4][0] - c[0], kCorner[(j + 3) % 4][1] - c[1]};
  const Uv ab = as_uv(s.ab);
  out.st = {c[0] + 0.5 * (ab[0] * e[0] + ab[1] * f[0]), c[1] + 0.5 * (ab[0] * e[1] + ab[1] * f[1])};
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 2; ++k)  // d(u, v)/d(a, b) = [e f] / 2, times the true 2 M J
      out.jacobian[size_t(r)][size_t(k)] = e[size_t(r)] * s.jacobian[0][size_t(k)] + f[size_t(r)] * s.jacobian[1][size_t(k)];
  return out;
}

std::string dual_head_unsupported(const Level& base) {
  // The head hands the tail each point in its child face's own (u, v), read by the tail in
  // the layout of the face's own crease run: that is the run the face was made with unless a
  // semi-sharp crease decays under the head.
  for (Index e = 0; e < base.edge_count(); ++e)
    if (!base.edge_on_boundary(e) && base.edge_sharp(e) >= 1.f && base.edge_sharp(e) < kInfinitelySharp)
      return fmt::format("edge {} has sharpness {}: a dual split in a sequence's head is followed next to boundaries "
                         "and infinitely sharp creases, not semi-sharp ones",
                         e, base.edge_sharp(e));
  if (std::string why = dual_limit_unsupported(base); !why.empty()) return why;
  for (Index f = 0; f < base.face_count(); ++f)
    if (!crease_run(base, f))
      return fmt::format("face {} lies between two creases: a dual split in a sequence's head follows faces with "
                         "their crease corners in one run",
                         f);
  for (Index v = 0; v < base.vertex_count; ++v)
    if (const VertexRefusal r = faces_refused_at(base, v); !r.what.empty())
      return fmt::format("{}: a dual split in a sequence's head is followed only where the faces at every vertex are "
                         "evaluated ({})",
                         r.what, r.why);
  return {};
}

std::string dual_limit_unsupported(const Level& base) { return dual_crease_unsupported(base); }

namespace {

// Per base face: a vertex at one of its corners that keeps it from evaluation
// (faces_refused_at), or kNone.
std::vector<Index> refused_at(const Level& base) {
  std::vector<Index> out(size_t(base.face_count()), kNone);
  for (Index v = 0; v < base.vertex_count; ++v) {
    if (faces_refused_at(base, v).what.empty()) continue;
    for (Index f : base.ring_faces(v))
      if (out[size_t(f)] == kNone) out[size_t(f)] = v;
  }
  return out;
}

}  // namespace

void DualLimit::check_face(Index f) const {
  if (f < 0 || size_t(f) >= refused_at_.size() || refused_at_[size_t(f)] == kNone) return;
  const VertexRefusal r = faces_refused_at(base_, refused_at_[size_t(f)]);
  throw Error(fmt::format("scheme {} is a dual scheme and face {} has a corner at {}: {}; the faces without a corner "
                          "at such a vertex are evaluated",
                          subdiv::quoted(scheme_.name), f, r.what, r.why));
}

DualLimit::~DualLimit() = default;

DualLimit::DualLimit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options, int radius,
                     SchemeLimits& limits)
    : scheme_(scheme),
      base_(base),
      options_(options),
      radius_(radius),
      limits_(limits),
      tables_(cut_weight_tables(scheme)),
      refused_at_(refused_at(base)) {
  biquadratic_ = refines_as_biquadratic(scheme, options.features);
  bool creased = false;
  for (Index f = 0; f < base.face_count() && !creased; ++f) {
    const auto run = crease_run(base, f);
    creased = !run || run->length > 0;
  }
  if (creased)
    if (const std::string why = crease_middles_kept(scheme, options.features, &chaikin_crease_, &middles_kept_);
        !why.empty())
      throw Error(fmt::format("scheme {} is a dual scheme and the mesh has boundaries or sharp creases, which are "
                              "evaluated for schemes whose crease is Chaikin's curve at every level; {}",
                              subdiv::quoted(scheme.name), why));
}

std::vector<Index> DualLimit::reads(const FacePoint& p) const {
  check_face(p.face);
  return cut_around(base_, p.face, radius_).original;
}

LimitSample DualLimit::evaluate(const FacePoint& p0, const std::vector<double>& first_values, int channels,
                                int derivatives, Rows* rows_out) const {
  check_face(p0.face);
  Cut cut = cut_around(base_, p0.face, radius_);
  cut.point.corner = 0;
  {
    const QuadrantPoint q = base_quadrant(base_, p0);
    cut.point.corner = q.corner, cut.point.ab = q.ab, cut.point.jacobian = q.jacobian;
    if (const auto run = crease_run(base_, p0.face)) cut.chart = *run;
  }
  // A face between two semi-sharp creases is followed along them (strip_child) until they
  // decay: the point is then in the face's quad (u, v), d(u, v)/d(base u, v) carried in
  // q.jacobian scaled as the quadrants' (2^-k after k steps).
  std::optional<CreaseStrip> strip = crease_strip(cut.level, cut.point.face);
  Uv strip_uv = p0.st;
  if (strip && !strip->lasting) cut.point.jacobian = {{{0.5, 0}, {0, 0.5}}};
  if (strip && strip->lasting) {
    if (!chaikin_crease_)
      throw Error(fmt::format("scheme {} is a dual scheme and face {} lies between two creases, which is evaluated "
                              "for schemes whose crease is Chaikin's curve (its cuts 3/4, 1/4) only",
                              subdiv::quoted(scheme_.name), p0.face));
    return strip_sample(cut, *strip, p0, first_values, channels, derivatives, rows_out);
  }
  std::deque<StepMatrix> owned;
  std::vector<const StepMatrix*> path;
  owned.push_back(identity_step(cut.level.vertex_count));
  path.push_back(&owned.back());
  std::vector<double> values = first_values;
  const int limit_steps = options_.max_steps + 40;
  // One step of the descent: the cut around `face` of the refined level, the step's matrix and
  // the values moved.
  auto descend = [&](const Hierarchy& h, Index face) {
    Cut next = cut_around(h.levels[1], face, radius_);
    owned.push_back(step_matrix(h.stencils[0], next.original, cut.level.vertex_count));
    path.push_back(&owned.back());
    std::vector<double> moved(size_t(owned.back().rows()) * size_t(channels));
    owned.back().apply(values, moved, channels);
    values.swap(moved);
    return next;
  };
  auto refined = [&] {
    RefineOptions ro;
    ro.levels = 1;
    ro.features = options_.features;
    ro.evaluation.weight_tables = tables_.get();
    return refine(scheme_, cut.level, ro);
  };
  for (int step = 0;; ++step) {
    QuadrantPoint& q = cut.point;
    if (strip) {
      if (const auto run = crease_run(cut.level, q.face)) {
        // The creases (or one of them) have decayed: the face is read in its quadrants.
        const QuadrantPoint to = quad_quadrant(cut.level, q.face, strip_uv[0], strip_uv[1]);
        Jacobian J = jacobian_product(to.jacobian, q.jacobian);
        for (auto& row : J)
          for (double& x : row) x *= 2;  // the quadrant's (a, b) over the face's (u, v)
        q.corner = to.corner, q.ab = to.ab, q.jacobian = J;
        cut.chart = *run;
        strip.reset();
      } else {
        strip = crease_strip(cut.level, q.face);
        if (!strip || strip->lasting || step >= limit_steps)
          throw Error("a face between two creases changes shape as they decay: not evaluated yet");
        const Hierarchy h = refined();
        const StripStep s = strip_child(h.levels[1], h.origins[0], q.face, *strip, strip_uv[0], strip_uv[1]);
        Jacobian J = jacobian_product(s.jacobian, q.jacobian);
        for (auto& row : J)
          for (double& x : row) x /= 2;  // carried as the quadrants' scale, 2^-k after k steps
        Cut next = descend(h, s.face);
        next.point.jacobian = J;
        strip_uv = s.uv;
        cut = std::move(next);
        continue;
      }
    }
    follow_decay(cut);
    if (step == options_.max_steps) q.ab = nearest_corner(q.ab);
    if (biquadratic_) {
      if (const auto grid = smooth_biquadratic_grid(cut.level, q.face, q.corner)) {
        const Uv ab = as_uv(q.ab);
        const QuadrantRows b = biquadratic_rows(ab[0], ab[1]);
        const size_t n = size_t(cut.level.vertex_count);
        auto spread = [&](const std::array<double, 9>& w) {
          std::vector<double> row(n, 0.0);
          for (size_t k = 0; k < 9; ++k) row[size_t((*grid)[k])] += w[k];
          return row;
        };
        LimitSample out;
        out.steps = step;
        out.position = applied(spread(b.position), values, channels);
        const auto& J = q.jacobian;
        if (derivatives >= 1) {
          const auto da = spread(b.da), db = spread(b.db);
          auto row = [&](int d) {
            std::vector<double> r(n);
            for (size_t i = 0; i < n; ++i) r[i] = J[0][size_t(d)] * da[i] + J[1][size_t(d)] * db[i];
            return pulled_back(std::move(r), path);
          };
          std::vector<double> u = row(0), v = row(1);
          out.du = applied(u, first_values, channels);
          out.dv = applied(v, first_values, channels);
          out.has_derivatives = true;
          if (rows_out) rows_out->du = std::move(u), rows_out->dv = std::move(v);
        }
        if (derivatives >= 2) {
          const auto daa = spread(b.daa), dab = spread(b.dab), dbb = spread(b.dbb);
          auto row = [&](size_t x, size_t y) {
            std::vector<double> r(n);
            for (size_t i = 0; i < n; ++i)
              r[i] = J[0][x] * J[0][y] * daa[i] + (J[0][x] * J[1][y] + J[1][x] * J[0][y]) * dab[i] + J[1][x] * J[1][y] * dbb[i];
            return pulled_back(std::move(r), path, 2);
          };
          std::vector<double> uu = row(0, 0), uv = row(0, 1), vv = row(1, 1);
          out.duu = applied(uu, first_values, channels);
          out.duv = applied(uv, first_values, channels);
          out.dvv = applied(vv, first_values, channels);
          out.has_second_derivatives = true;
          if (rows_out) rows_out->duu = std::move(uu), rows_out->duv = std::move(uv), rows_out->dvv = std::move(vv);
        }
        return out;
      }
    }
    const bool centre = q.ab[0].high && q.ab[0].x == 0 && q.ab[1].high && q.ab[1].x == 0;
    // The centre (1, 1) of a half face's quadrant: the middle of its crease run, where an
    // infinitely sharp crease's limit is the mean of the run's two middle points (Chaikin's
    // curve at a knot) or the corner it turns at (dual_crease_chart.h).
    // A point on the crease itself (a = 1 or b = 1 on the side reaching a crease corner): the
    // crease curve's closed form there (dual_crease_chart.h), rather than descending ~53 steps.
    if (const auto run = crease_run(cut.level, q.face);
        chaikin_crease_ && run && run->length > 0 && crease_run_infinitely_sharp(cut.level, q.face, *run)) {
      for (int side = 0; side < 2; ++side) {
        const Coord& on = q.ab[size_t(side)];
        if (!(on.high && on.x == 0)) continue;
        const auto w = crease_side_limit(cut.level, q.face, *run, q.corner, side == 0, q.ab[size_t(1 - side)].value());
        if (w.empty()) continue;
        std::vector<double> row(size_t(cut.level.vertex_count), 0.0);
        for (const auto& [v, x] : w) row[size_t(v)] += x;
        LimitSample out;
        out.steps = step;
        out.position = applied(row, values, channels);
        return out;
      }
    }
    if (centre) {
      const auto run = crease_run(cut.level, q.face);
      if (run && run->length > 0 && crease_run_infinitely_sharp(cut.level, q.face, *run)) {
        std::vector<double> row(size_t(cut.level.vertex_count), 0.0);
        const auto corners = cut.level.face(q.face);
        std::vector<std::pair<Index, double>> weights;
        if (middles_kept_ || run->length != 2) {
          for (const auto& [k, w] : crease_run_middle(*run, int(corners.size())))
            weights.emplace_back(corners[size_t(k)], w);
        } else {
          // The crease points move after the split: the crease curve's own limit mask at the
          // middle (dual_crease_curve.h), once the window is clear of corners.
          RefineOptions ro;
          ro.levels = 1;
          ro.features = options_.features;
          ro.evaluation.weight_tables = tables_.get();
          const auto mask =
              crease_middle_limit(cut.level, refine(scheme_, cut.level, ro), q.face, *run, crease_end_reach(scheme_));
          if (mask) weights = *mask;
        }
        for (const auto& [v, w] : weights) row[size_t(v)] += w;
        LimitSample out;
        out.steps = step;
        out.position = applied(row, values, channels);
        if (!weights.empty()) return out;
      }
    }
    // The centre of a face: its limit mask, where its neighbourhood is the mask's. A quad's
    // centre is left to the closed form when there is one (its F-faces' neighbourhoods
    // become regular), which gives the derivatives too.
    const bool closed_form_ahead = biquadratic_ && cut.level.face_size(q.face) == 4;
    if (centre && !closed_form_ahead) {
      LocalConfig config;
      config.centre = CentreKind::Face;
      config.valence = cut.level.face_size(q.face);
      const auto mask = limits_.mask(config);
      if (!mask->ok)
        throw Error(fmt::format("no limit mask at the centre of a {}-sided face: {}", config.valence, mask->error));
      Labelling lab;
      if (matches_neighbourhood(lab, cut.level, CentreKind::Face, q.face, 0, mask->radius, mask->signature)) {
        std::vector<double> row(size_t(cut.level.vertex_count), 0.0);
        for (size_t l = 0; l < mask->position.size(); ++l) row[size_t(lab.vertices[l])] += mask->position[l];
        LimitSample out;
        out.steps = step;
        out.position = applied(row, values, channels);
        return out;
      }
    }
    if (step >= limit_steps)
      throw Error(fmt::format("internal: the point reached no face centre with a known neighbourhood in {} steps",
                              step));
    const Hierarchy h = refined();
    const ChildStep s = child_quadrant(h.levels[1], h.origins[0], q);
    const auto run = made_on_crease_run(cut.level, h.levels[1], h.origins[0], s.face);
    if (!run) throw Error("internal: a new face has its crease points in two runs");
    Cut next = descend(h, s.face);
    next.point.corner = s.corner, next.point.ab = s.ab, next.point.jacobian = s.jacobian;
    next.chart = *run;
    cut = std::move(next);
  }
}

}  // namespace subdiv
