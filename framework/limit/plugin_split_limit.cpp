#include "framework/limit/plugin_split_limit.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <fmt/format.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/local_patch.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/engine/ghost_rings.h"
#include "framework/engine/refiner.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/cut_weight_tables.h"
#include "framework/limit/plugin_period_children.h"
#include "framework/limit/point_cut.h"
#include "framework/limit/step_matrix.h"
#include "framework/limit/two_steps.h"
#include "framework/refine/splitter.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr Uv kQuad[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
constexpr Uv kTriangle[3] = {{0, 0}, {1, 0}, {0, 1}};

using Cut = PointCut;

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

PluginSplitLimit::~PluginSplitLimit() = default;

PluginSplitLimit::PluginSplitLimit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options,
                                   SchemeLimits& limits)
    : scheme_(scheme), base_(base), options_(options), limits_(limits), tables_(cut_weight_tables(scheme)) {
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
  NoLimitMask mask_error;
  for (int step = 0;; ++step) {
    const int size = cut.level.face_size(cut.point.face);
    if (factor_ == 3 && extraordinary_corner(cut.level, cut.point.face, triangles_))
      stop = std::max(stop, step + round_off);
    int k = corner_at(cut.point, size, triangles_);
    if (k < 0 && step >= stop) k = nearest_corner(cut.point, triangles_);
    if (k >= 0) {
      CornerRows rows;
      FacePoint corner = cut.point;
      if (corner_rows(limits_, cut.level, corner, k, 0, triangles_, rows, mask_error,
                      analysis_parameter_scale(scheme_))) {
        if (derivatives >= 1 && !rows.no_derivatives.empty())
          throw Error(not_c1_derivatives(scheme_, rows.no_derivatives));
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
    if (step >= give_up && !mask_error.failure.empty()) throw Error(no_limit_mask(scheme_, period_ * step, mask_error));
    if (step >= give_up)
      throw Error(fmt::format("internal: the point's vertex has no limit mask after {} steps{}{}", step,
                              mask_error.verdict.empty() ? "" : ": ", mask_error.verdict));
    RefineOptions ro;
    ro.levels = period_;
    ro.features = options_.features;
    ro.evaluation.weight_tables = tables_.get();
    const Hierarchy h = refine(scheme_, cut.level, ro);
    std::vector<ChildrenOf> children_of;
    for (int s = 0; s < period_; ++s) children_of.emplace_back(h.levels[size_t(s)], h.origins[size_t(s)]);
    const std::vector<ChildFace> children =
        period_children(h, 0, period_, cut.point.face, triangles_, factor_, children_of);
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
