#include "framework/limit/mid_edge_limit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <fmt/format.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/local_patch.h"
#include "framework/engine/ghost_rings.h"
#include "framework/limit/dual_limit.h"
#include "framework/limit/four_direction_patch.h"
#include "framework/limit/mid_edge_nodes.h"
#include "framework/limit/point_cut.h"
#include "framework/limit/step_matrix.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

using Cut = PointCut;

int corner_of(const Level& L, Index f, Index w) {
  const auto fv = L.face(f);
  for (size_t k = 0; k < fv.size(); ++k)
    if (fv[k] == w) return int(k);
  return -1;
}

// The point is the centre of its face: (1/2, 1/2) of a quad, the corner (1, 1) of a sub-face.
bool at_centre(const FacePoint& p) {
  return p.sub_face < 0 ? p.st[0] == 0.5 && p.st[1] == 0.5 : p.st[0] == 1 && p.st[1] == 1;
}


// The nearest corner of the point's quadrant (multiples of 1/2 of a quad, 0 or 1 of a sub-face).
FacePoint nearest_corner(FacePoint p) {
  for (double& x : p.st) x = p.sub_face < 0 ? std::round(2 * x) / 2 : std::round(x);
  return p;
}

// The point of a quad (its own (s, t) in [0, 1]^2) in the quadrant at corner j, if that
// quadrant holds it: (s, t) = c_j + (a/2) e + (b/2) f, e towards corner j + 1, f towards j - 1
// (dual_limit.h), so (a, b) = 2 [e; f] ((s, t) - c_j), exactly for a dyadic point.
std::optional<Uv> in_quadrant(const Uv& st, int j, Jacobian& to_ab) {
  constexpr Uv kCorner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Uv& c = kCorner[j];
  const Uv e{kCorner[(j + 1) % 4][0] - c[0], kCorner[(j + 1) % 4][1] - c[1]};
  const Uv f{kCorner[(j + 3) % 4][0] - c[0], kCorner[(j + 3) % 4][1] - c[1]};
  const Uv d{st[0] - c[0], st[1] - c[1]};
  const Uv ab{2 * (e[0] * d[0] + e[1] * d[1]), 2 * (f[0] * d[0] + f[1] * d[1])};
  if (!(ab[0] >= 0 && ab[0] <= 1 && ab[1] >= 0 && ab[1] <= 1)) return std::nullopt;
  to_ab = {{{2 * e[0], 2 * e[1]}, {2 * f[0], 2 * f[1]}}};
  return ab;
}

// The sample from the four-direction box spline's closed form over the quadrant (a, b) of the
// 3 x 3 labels `grid` (four_direction_patch.h), the rows over the node's `n` labels applied to
// `values`, the derivative rows (through J = d(a, b)/d(u, v), scaled by 2^-k after k double
// steps) pulled back through `path` to the first node and applied to `first_values`. The
// second derivatives: J's chain rule has no second-order term (every step is affine), and
// there are none on a knot line.
struct Descent {
  std::span<const StepMatrix* const> path;
  const std::vector<double>& values;
  const std::vector<double>& first_values;
  int channels = 3, derivatives = 1;
};
LimitSample four_direction_sample(const std::array<Index, 9>& grid, size_t n, const Uv& ab, const Jacobian& J,
                                  const Descent& d, MidEdgeLimit::Rows* rows_out) {
  const QuadrantRows b = four_direction_rows(ab[0], ab[1]);
  auto spread = [&](const std::array<double, 9>& w) {
    std::vector<double> row(n, 0.0);
    for (size_t k = 0; k < 9; ++k) row[size_t(grid[k])] += w[k];
    return row;
  };
  LimitSample out;
  out.position = applied(spread(b.position), d.values, d.channels);
  if (d.derivatives >= 1) {
    FirstDerivativeRows r = first_derivative_rows(spread(b.da), spread(b.db), J, d.path);
    out.du = applied(r.du, d.first_values, d.channels);
    out.dv = applied(r.dv, d.first_values, d.channels);
    out.has_derivatives = true;
    if (rows_out) rows_out->du = std::move(r.du), rows_out->dv = std::move(r.dv);
  }
  if (d.derivatives >= 2 && !on_four_direction_knot_line(ab[0], ab[1])) {
    SecondDerivativeRows r = second_derivative_rows(spread(b.daa), spread(b.dab), spread(b.dbb), J, d.path);
    out.duu = applied(r.duu, d.first_values, d.channels);
    out.duv = applied(r.duv, d.first_values, d.channels);
    out.dvv = applied(r.dvv, d.first_values, d.channels);
    out.has_second_derivatives = true;
    if (rows_out) rows_out->duu = std::move(r.duu), rows_out->duv = std::move(r.duv), rows_out->dvv = std::move(r.dvv);
  }
  return out;
}

}  // namespace

ChildOrigins mid_edge_double_origins(const Level& level0, const Level& level1, const ChildOrigins& step1,
                                     const Level& level2, const ChildOrigins& step2) {
  ChildOrigins o;
  o.kind.assign(size_t(level2.vertex_count), OriginKind::Vertex);
  o.parent.assign(size_t(level2.vertex_count), kNone);
  o.local.assign(size_t(level2.vertex_count), 0);
  for (Index v = 0; v < level2.vertex_count; ++v) {
    if (step2.kind[size_t(v)] != OriginKind::Edge) continue;
    const Index e1 = step2.parent[size_t(v)];
    // The first step's edge lies in the F-face of one base face g, between the middles of two
    // of g's edges, which meet at g's corner j.
    Index g = kNone;
    for (int side = 0; side < 2; ++side) {
      const Index f1 = level1.edge_faces[size_t(2 * e1 + side)];
      if (f1 != kNone && step1.parent_face[size_t(f1)] != kNone) g = step1.parent_face[size_t(f1)];
    }
    const Index a1 = level1.edge_vertices[size_t(2 * e1)], b1 = level1.edge_vertices[size_t(2 * e1 + 1)];
    if (g == kNone || step1.kind[size_t(a1)] != OriginKind::Edge || step1.kind[size_t(b1)] != OriginKind::Edge) continue;
    const Index ea = step1.parent[size_t(a1)], eb = step1.parent[size_t(b1)];
    Index w = kNone;
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 2; ++k)
        if (level0.edge_vertices[size_t(2 * ea + i)] == level0.edge_vertices[size_t(2 * eb + k)])
          w = level0.edge_vertices[size_t(2 * ea + i)];
    const int j = w == kNone ? -1 : corner_of(level0, g, w);
    if (j < 0) continue;
    o.kind[size_t(v)] = OriginKind::Corner;
    o.parent[size_t(v)] = g;
    o.local[size_t(v)] = LocalIndex(j);
  }
  o.parent_face.assign(size_t(level2.face_count()), kNone);
  for (Index f = 0; f < level2.face_count(); ++f) {
    const Index f1 = step2.parent_face.empty() ? kNone : step2.parent_face[size_t(f)];
    if (f1 != kNone) o.parent_face[size_t(f)] = step1.parent_face[size_t(f1)];
  }
  return o;
}

std::string mid_edge_limit_unsupported(const Level& base) {
  for (Index v = 0; v < base.vertex_count; ++v)
    if (base.on_boundary(v))
      return "the mesh has a boundary: mid-edge evaluation at (face, u, v) is not done there yet (the split keeps a "
             "boundary's edges as long as they were, so the faces two steps make along it are not quadrants of the "
             "base faces); close the mesh, tagging the faces that close it as holes to leave them out";
  for (float s : base.edge_sharpness)
    if (s > 0) return "the mesh has sharp or semi-sharp edges: evaluation of mid-edge schemes with creases is not done yet";
  for (float s : base.vertex_sharpness)
    if (s > 0) return "the mesh has sharp vertices: evaluation of mid-edge schemes with corners is not done yet";
  for (Index v = 0; v < base.vertex_count; ++v)
    if (base.incident_face_count(v) == 2)
      return fmt::format("interior vertex {} has valence 2: the mid-edge split's face for it would have two sides, so "
                         "the faces two steps make there are not quadrants of the base faces; not evaluated yet",
                         v);
  // Holes remove faces, not rules: the cuts drop their tags (canonical_cut.h).
  return {};
}

MidEdgeLimit::MidEdgeLimit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options,
                           SchemeLimits& limits, bool closed_form)
    : base_(base), options_(options) {
  four_direction_ = closed_form && refines_as_four_direction(scheme, options.features);
  // Two steps lose `loss` rings of the cut; the next cut, `radius` rings of faces half the
  // size, must lie in what is left: radius / 2 + 1 <= radius - loss.
  const SchemeRun run{&scheme, 2};
  double loss = 0;
  for (double x : ring_loss_per_level(std::span<const SchemeRun>(&run, 1))) loss += std::max(x, 0.0);
  radius_ = std::max(5, int(std::ceil(2 * (loss + 1))) + 1);
  nodes_ = std::make_unique<MidEdgeNodes>(scheme, options.features, radius_, limits);
  entries_.resize(size_t(base.face_count()));
}

MidEdgeLimit::~MidEdgeLimit() = default;

const MidEdgeLimit::Entry& MidEdgeLimit::entry(Index face) const {
  {
    std::lock_guard lock(entry_mutex_);
    if (entries_[size_t(face)]) return *entries_[size_t(face)];
  }
  FacePoint p;
  p.face = face;
  const Cut cut = cut_around(base_, p, radius_);
  auto e = std::make_unique<Entry>();
  std::vector<Index> order;
  e->node = nodes_->intern(cut.level, cut.point.face, order);
  for (Index v : order) e->vertices.push_back(cut.original[size_t(v)]);
  std::lock_guard lock(entry_mutex_);
  if (!entries_[size_t(face)]) entries_[size_t(face)] = std::move(e);
  return *entries_[size_t(face)];
}

std::vector<Index> MidEdgeLimit::reads(const FacePoint& p) const { return entry(p.face).vertices; }

LimitSample MidEdgeLimit::evaluate(const FacePoint& p0, const std::vector<double>& first_values, int channels,
                                   int derivatives, Rows* rows_out) const {
  int id = entry(p0.face).node;
  FacePoint point = p0;
  std::vector<const StepMatrix*> path;
  std::vector<double> values = first_values;
  const int limit_steps = options_.max_steps + 40;
  int tangent_steps = 0;  // steps taken past a quad's centre whose grid was not regular yet
  for (int step = 0;; ++step) {
    const MidEdgeNode& node = nodes_->expanded(id);
    point.face = node.face;
    if (step == options_.max_steps) point = nearest_corner(point);
    if (four_direction_ && point.sub_face < 0 && node.level.face_size(node.face) == 4)
      for (int j = 0; j < 4; ++j) {
        Jacobian to_ab;
        const std::optional<Uv> ab = in_quadrant(point.st, j, to_ab);
        const std::array<Index, 9>* grid = ab ? nodes_->quadrant_grid(id, j) : nullptr;
        if (!grid) continue;
        // d(a, b)/d(u, v) scaled by 2^-k after k double steps, as the tangents' below.
        Jacobian J = jacobian_product(to_ab, point.jacobian);
        for (auto& r : J)
          for (double& x : r) x = std::ldexp(x, -step);
        LimitSample out = four_direction_sample(*grid, size_t(node.level.vertex_count), *ab, J,
                                                Descent{path, values, first_values, channels, derivatives}, rows_out);
        out.steps = step;
        return out;
      }
    if (at_centre(point)) {
      std::string error;
      const MidEdgeNode* c = nodes_->centre(id, error);
      if (!c && !error.empty())
        throw Error(fmt::format("no limit mask at the centre of a {}-sided face: {}", node.level.face_size(node.face),
                                error));
      // A quad's centre has derivatives: where its grid is not regular yet, go on (the point
      // stays the centre of the quad's F-face) a few steps.
      const bool tangents = c && derivatives >= 1 && !c->ds.empty();
      if (c && (tangents || derivatives == 0 || node.level.face_size(node.face) != 4 || ++tangent_steps > 12)) {
        LimitSample out;
        out.steps = step;
        out.position = applied(c->position, values, channels);
        if (tangents) {
          // d(s, t)/d(u, v) is 2^k times a number of order one after k double steps; the rows
          // start at 2^-k times their size and each step's factor 2 restores it (step_matrix.h).
          auto J = point.jacobian;
          for (auto& row : J)
            for (double& x : row) x = std::ldexp(x, -step);  // exact: a power of two
          FirstDerivativeRows d = first_derivative_rows(c->ds, c->dt, J, path);
          out.du = applied(d.du, first_values, channels);
          out.dv = applied(d.dv, first_values, channels);
          out.has_derivatives = true;
          if (rows_out) rows_out->du = std::move(d.du), rows_out->dv = std::move(d.dv);
        }
        return out;
      }
    }
    if (step >= limit_steps)
      throw Error(fmt::format("internal: the point reached no face centre with a known neighbourhood in {} double "
                              "mid-edge steps", step));
    const std::optional<FacePoint> q = dual_child_point(node.level, node.steps.levels[2], node.origins, point);
    if (!q) throw Error("internal: no face two mid-edge steps make holds the point");
    const MidEdgeNode::Child& child = nodes_->child(id, q->face);
    path.push_back(&child.matrix);
    std::vector<double> moved(size_t(child.matrix.rows()) * size_t(channels));
    child.matrix.apply(values, moved, channels);
    values.swap(moved);
    id = child.node;
    point = *q;
  }
}

}  // namespace subdiv
