#include "framework/limit/plugin_split_limit.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <fmt/format.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/local_patch.h"
#include "framework/engine/ghost_rings.h"
#include "framework/engine/refiner.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/point_cut.h"
#include "framework/limit/step_matrix.h"
#include "framework/limit/two_steps.h"
#include "framework/refine/splitter.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr Uv kQuad[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
constexpr Uv kTriangle[3] = {{0, 0}, {1, 0}, {0, 1}};

using Cut = PointCut;

Uv mean(const std::vector<Uv>& xs) {
  Uv s{0, 0};
  for (const Uv& x : xs) s[0] += x[0] / double(xs.size()), s[1] += x[1] / double(xs.size());
  return s;
}

// The position of every edge child along its parent edge: the i-th of c children at
// (i + 1) / (c + 1) from the edge's first vertex.
std::vector<Uv> edge_children(const Level& parent, const std::vector<Uv>& at, const ChildOrigins& o,
                              std::vector<Uv> out) {
  std::vector<int> count(size_t(parent.edge_count()), 0);
  for (size_t v = 0; v < o.kind.size(); ++v)
    if (o.kind[v] == OriginKind::Edge) ++count[size_t(o.parent[v])];
  for (size_t v = 0; v < o.kind.size(); ++v) {
    if (o.kind[v] != OriginKind::Edge) continue;
    const Index e = o.parent[v];
    const Uv a = at[size_t(parent.edge_vertices[size_t(2 * e)])], b = at[size_t(parent.edge_vertices[size_t(2 * e + 1)])];
    const double t = double(o.local[v] + 1) / double(count[size_t(e)] + 1);
    out[v] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
  }
  return out;
}

// Where the first step's children lie in the frame of face f: f's corners, points of f's
// edges along them, f's point at its centroid, and the point of each neighbour across an edge
// of f at that neighbour's centroid with the grid unfolded affinely across the edge.
std::vector<Uv> first_step(const Level& L, Index f, const ChildOrigins& o, bool triangles) {
  const auto fv = L.face(f);
  const auto fe = L.face_edge_list(f);
  const int n = int(fv.size());
  const Uv* frame = triangles ? kTriangle : kQuad;
  std::vector<Uv> at(size_t(L.vertex_count), Uv{kNan, kNan});
  for (int k = 0; k < n; ++k) at[size_t(fv[size_t(k)])] = frame[k];
  std::vector<Uv> out(o.kind.size(), Uv{kNan, kNan});
  for (size_t v = 0; v < o.kind.size(); ++v) {
    if (o.kind[v] == OriginKind::Vertex) out[v] = at[size_t(o.parent[v])];
    if (o.kind[v] != OriginKind::Face) continue;
    const Index g = o.parent[v];
    if (g == f) out[v] = mean(std::vector<Uv>(frame, frame + n));
    for (int k = 0; k < n && g != f; ++k) {
      const Index e = fe[size_t(k)];
      if (L.edge_faces[size_t(2 * e)] != g && L.edge_faces[size_t(2 * e + 1)] != g) continue;
      const Uv A = frame[k], B = frame[(k + 1) % n];
      if (triangles) {
        const Uv C = frame[(k + 2) % 3];
        out[v] = {(2 * A[0] + 2 * B[0] - C[0]) / 3, (2 * A[1] + 2 * B[1] - C[1]) / 3};
      } else {  // the neighbour reflected: far corners 2A - D and 2B - C
        const Uv C = frame[(k + 2) % 4], D = frame[(k + 3) % 4];
        out[v] = {(3 * A[0] + 3 * B[0] - C[0] - D[0]) / 4, (3 * A[1] + 3 * B[1] - C[1] - D[1]) / 4};
      }
    }
  }
  return edge_children(L, at, o, out);  // points of f's own edges
}

// Where a later step's children lie, from where their parents lie.
std::vector<Uv> next_step(const Level& parent, const std::vector<Uv>& at, const ChildOrigins& o) {
  std::vector<Uv> out(o.kind.size(), Uv{kNan, kNan});
  for (size_t v = 0; v < o.kind.size(); ++v) {
    if (o.kind[v] == OriginKind::Vertex) out[v] = at[size_t(o.parent[v])];
    if (o.kind[v] == OriginKind::Face) {
      std::vector<Uv> corners;
      for (Index w : parent.face(o.parent[v])) corners.push_back(at[size_t(w)]);
      out[v] = mean(corners);
    }
  }
  return edge_children(parent, at, o, out);
}

bool inside_face(const Uv& x, bool triangles) {
  constexpr double eps = 1e-9;
  if (!std::isfinite(x[0]) || !std::isfinite(x[1])) return false;
  if (x[0] < -eps || x[1] < -eps) return false;
  return triangles ? x[0] + x[1] <= 1 + eps : x[0] <= 1 + eps && x[1] <= 1 + eps;
}

// The faces of the last level inside face f: m^2 affine copies of it, or an error saying why not.
std::vector<ChildFace> nested_children(const Level& last, const std::vector<Uv>& at, bool triangles, int m) {
  std::vector<ChildFace> out;
  for (Index g = 0; g < last.face_count(); ++g) {
    ChildFace c;
    c.face = g;
    bool in = true;
    for (Index v : last.face(g)) {
      c.corners.push_back(at[size_t(v)]);
      in = in && inside_face(at[size_t(v)], triangles);
    }
    if (!in) continue;
    if (int(c.corners.size()) != (triangles ? 3 : 4))
      throw Error("the split's faces inside a face are not of its shape");
    if (!triangles) {  // a parallelogram: corner 2 = corner 1 + corner 3 - corner 0
      const Uv& a = c.corners[0];
      const Uv& b = c.corners[1];
      const Uv& d = c.corners[2];
      const Uv& e = c.corners[3];
      if (std::fabs(b[0] + e[0] - a[0] - d[0]) + std::fabs(b[1] + e[1] - a[1] - d[1]) > 1e-9)
        throw Error("the split's faces inside a face are not parallelograms of its frame");
    }
    out.push_back(std::move(c));
  }
  if (int(out.size()) != m * m)
    throw Error(fmt::format("the split makes {} faces inside a face after its period, not the {} of a {}-adic split",
                            out.size(), m * m, m));
  return out;
}

bool extraordinary_corner(const Level& L, Index face, bool triangles) {
  for (Index v : L.face(face))
    if (L.incident_face_count(v) != (triangles ? 6 : 4)) return true;
  return false;
}

int nearest_corner(const FacePoint& p, bool triangles) {
  const Uv* frame = triangles ? kTriangle : kQuad;
  int best = 0;
  double d = std::numeric_limits<double>::infinity();
  for (int k = 0; k < (triangles ? 3 : 4); ++k) {
    const double x = std::hypot(p.st[0] - frame[k][0], p.st[1] - frame[k][1]);
    if (x < d) d = x, best = k;
  }
  return best;
}

}  // namespace

std::string plugin_split_limit_unsupported(const Scheme& scheme, const Level& base) {
  const SplitterInfo& info = splitter_info(scheme.split());
  const double factor = std::pow(info.scale, info.period);
  if (!info.primal || (info.period != 1 && info.period != 2) ||
      (std::fabs(factor - 2) > 1e-9 && std::fabs(factor - 3) > 1e-9))
    return fmt::format("scheme {} uses the plugin split {}, which is not primal with a period of 1 or 2 steps "
                       "scaling the mesh by 2 or 3 (its SplitterInfo: primal {}, scale {}, period {}): no nested "
                       "parameterisation is known for it",
                       subdiv::quoted(scheme.name), subdiv::quoted(info.name), info.primal, info.scale, info.period);
  const bool quads = base.all_faces_have_size(4), triangles = base.all_faces_have_size(3);
  if (!quads && !triangles)
    return fmt::format("scheme {} uses the plugin split {}, and the mesh is not all quads or all triangles: the "
                       "parameterisation of other faces under a plugin's split is not defined",
                       subdiv::quoted(scheme.name), subdiv::quoted(info.name));
  for (Index v = 0; v < base.vertex_count; ++v)
    if (base.on_boundary(v))
      return fmt::format("scheme {} uses the plugin split {}, and the mesh has a boundary: evaluation of plugins' "
                         "splits along boundaries is not done yet; close the mesh",
                         subdiv::quoted(scheme.name), subdiv::quoted(info.name));
  for (float s : base.edge_sharpness)
    if (s > 0) return "the mesh has sharp or semi-sharp edges: evaluation of plugins' splits with creases is not done yet";
  for (float s : base.vertex_sharpness)
    if (s > 0) return "the mesh has sharp vertices: evaluation of plugins' splits with corners is not done yet";
  return {};
}

PluginSplitLimit::PluginSplitLimit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options,
                                   SchemeLimits& limits)
    : scheme_(scheme), base_(base), options_(options), limits_(limits) {
  const SplitterInfo& info = splitter_info(scheme.split());
  period_ = info.period;
  factor_ = int(std::lround(std::pow(info.scale, info.period)));
  triangles_ = base.all_faces_have_size(3);
  // The next cut, `radius` rings of faces 1/m the size, must lie where `loss` rings of the
  // period's steps leave the cut right: radius / m + 1 <= radius - loss. A split that does
  // not state its reach gets a generous cut.
  double loss = 2;
  try {
    const SchemeRun run{&scheme, period_};
    loss = 0;
    for (double x : ring_loss_per_level(std::span<const SchemeRun>(&run, 1))) loss += std::max(x, 0.0);
  } catch (const Error&) {
    loss = 2;
  }
  radius_ = std::max(5, int(std::ceil(double(factor_) / (factor_ - 1) * (loss + 1))) + 1);
}

std::vector<Index> PluginSplitLimit::reads(const FacePoint& p) const { return cut_around(base_, p, radius_).original; }

LimitSample PluginSplitLimit::evaluate(const FacePoint& p0, const std::vector<double>& first_values, int channels,
                                       int derivatives, Rows* rows_out) const {
  Cut cut = cut_around(base_, p0, radius_);
  std::deque<StepMatrix> owned;
  std::vector<const StepMatrix*> path;
  std::vector<double> values = first_values;
  // Below round-off: m^-k < 2^-53 (k = 54 for m = 2, 34 for m = 3).
  const int round_off = factor_ == 2 ? 54 : 34;
  int stop = round_off;
  const int give_up = 24 * round_off;
  std::string mask_error;
  for (int step = 0;; ++step) {
    const int size = cut.level.face_size(cut.point.face);
    if (factor_ == 3 && extraordinary_corner(cut.level, cut.point.face, triangles_))
      stop = std::max(stop, step + round_off);
    int k = corner_at(cut.point, size, triangles_);
    if (k < 0 && step >= stop) k = nearest_corner(cut.point, triangles_);
    if (k >= 0) {
      CornerRows rows;
      FacePoint corner = cut.point;
      if (corner_rows(limits_, cut.level, corner, k, 0, triangles_, rows, mask_error)) {
        LimitSample out;
        out.steps = step;
        out.position = applied(rows.position, values, channels);
        if (derivatives >= 1 && !rows.ds.empty()) {
          const auto& J = cut.point.jacobian;  // m^-k times d(s, t)/d(u, v)
          FirstDerivativeRows d = first_derivative_rows(rows.ds, rows.dt, J, path);
          out.du = applied(d.du, first_values, channels);
          out.dv = applied(d.dv, first_values, channels);
          out.has_derivatives = true;
          if (rows_out) rows_out->du = std::move(d.du), rows_out->dv = std::move(d.dv);
        }
        return out;
      }
    }
    if (step >= give_up)
      throw Error(fmt::format("internal: the point's vertex has no limit mask after {} steps{}{}", step,
                              mask_error.empty() ? "" : ": ", mask_error));
    RefineOptions ro;
    ro.levels = period_;
    ro.features = options_.features;
    const Hierarchy h = refine(scheme_, cut.level, ro);
    std::vector<Uv> at = first_step(cut.level, cut.point.face, h.origins[0], triangles_);
    for (int s = 1; s < period_; ++s) at = next_step(h.levels[size_t(s)], at, h.origins[size_t(s)]);
    const std::vector<ChildFace> children = nested_children(h.levels[size_t(period_)], at, triangles_, factor_);
    std::optional<FacePoint> q = locate(children, cut.point, triangles_, nullptr);
    if (!q) throw Error("internal: no face of the plugin's split holds the point");
    for (auto& r : q->jacobian)
      for (double& x : r) x /= factor_;
    Cut next = cut_around(h.levels[size_t(period_)], *q, radius_);
    StepMatrix m = period_ == 2 ? two_step_matrix(h, next.original, cut.level.vertex_count, factor_)
                                : step_matrix(h.stencils[0], next.original, cut.level.vertex_count);
    m.scale = factor_;
    owned.push_back(std::move(m));
    path.push_back(&owned.back());
    std::vector<double> moved(size_t(owned.back().rows()) * size_t(channels));
    owned.back().apply(values, moved, channels);
    values.swap(moved);
    cut = std::move(next);
  }
}

}  // namespace subdiv
