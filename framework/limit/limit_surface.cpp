#include "framework/limit/limit_surface.h"

#include <cmath>
#include <fmt/format.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/local_patch.h"
#include "framework/engine/ghost_rings.h"
#include "framework/engine/refiner.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/face_domain.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// A face's neighbourhood cut out of a level, with its values and the point inside it.
struct Neighbourhood {
  Level level;
  std::vector<double> values;
  std::vector<Index> original;  // vertex -> vertex of the level it was cut from
  FacePoint point;
};

Neighbourhood cut(const Level& L, std::span<const double> values, int channels, const FacePoint& p, int radius) {
  Extracted e = extract_neighbourhood(L, CentreKind::Face, p.face, radius);
  Neighbourhood n;
  n.level = std::move(e.level);
  n.original = std::move(e.original);
  n.values.resize(n.original.size() * size_t(channels));
  for (size_t v = 0; v < n.original.size(); ++v)
    for (int c = 0; c < channels; ++c)
      n.values[v * size_t(channels) + size_t(c)] = values[size_t(n.original[v]) * size_t(channels) + size_t(c)];
  n.point = p;
  for (size_t f = 0; f < e.face_original.size(); ++f)
    if (e.face_original[f] == p.face) n.point.face = Index(f);
  if (!L.face_hole.empty()) {
    n.level.face_hole.assign(size_t(n.level.face_count()), 0);
    for (size_t f = 0; f < e.face_original.size(); ++f) n.level.face_hole[f] = L.face_hole[size_t(e.face_original[f])];
  }
  return n;
}

// One step of the descent as a matrix: rows the vertices of the new cut, columns those of
// the cut before.
struct StepMatrix {
  Index source_count = 0;
  std::vector<Index> offsets{0}, columns;
  std::vector<double> weights;
};

StepMatrix step_matrix(const StencilTable& table, const std::vector<Index>& rows, Index source_count) {
  StepMatrix m;
  m.source_count = source_count;
  for (Index r : rows) {
    for (Index e = table.offsets[size_t(r)]; e < table.offsets[size_t(r) + 1]; ++e) {
      m.columns.push_back(table.indices[size_t(e)]);
      m.weights.push_back(table.weights[size_t(e)]);
    }
    m.offsets.push_back(Index(m.columns.size()));
  }
  return m;
}

// A derivative row at the last step pulled back to the first cut. The row is for d/du
// scaled by 2^-k, so that every step's factor 2 (the children's coordinates are twice the
// parent's) keeps its entries of order one, and each step removes the row's sum, which is
// zero for a derivative: rounding in the sum would otherwise double at every step.
std::vector<double> pulled_back(std::vector<double> row, const std::vector<StepMatrix>& steps) {
  for (size_t j = steps.size(); j-- > 0;) {
    const StepMatrix& m = steps[j];
    std::vector<double> next(size_t(m.source_count), 0.0);
    for (size_t r = 0; r + 1 < m.offsets.size(); ++r) {
      const double x = 2 * row[r];
      if (x == 0) continue;
      for (Index e = m.offsets[r]; e < m.offsets[r + 1]; ++e) next[size_t(m.columns[size_t(e)])] += x * m.weights[size_t(e)];
    }
    double sum = 0;
    int used = 0;
    for (double x : next) sum += x, used += x != 0 ? 1 : 0;
    if (used > 0)
      for (double& x : next)
        if (x != 0) x -= sum / used;
    row = std::move(next);
  }
  return row;
}

std::vector<double> applied(const std::vector<double>& row, std::span<const double> values, int channels) {
  std::vector<double> out(size_t(channels), 0.0);
  for (size_t v = 0; v < row.size(); ++v)
    if (row[v] != 0)
      for (int c = 0; c < channels; ++c) out[size_t(c)] += row[v] * values[v * size_t(channels) + size_t(c)];
  return out;
}

}  // namespace

std::string limit_surface_unsupported(const Scheme& scheme) {
  if (!scheme.linear())
    return fmt::format("scheme '{}' has non-linear rules: its limit is no fixed combination of the control points, "
                       "so it has no limit masks or stencils to evaluate",
                       scheme.name);
  if (scheme_is_level_dependent(scheme))
    return fmt::format("scheme '{}' is non-stationary (its weights depend on the level l): the local subdivision "
                       "matrix changes from level to level and has no fixed eigen-structure to evaluate the limit with",
                       scheme.name);
  const SplitKind split = scheme.split();
  if (split != SplitKind::Quad && split != SplitKind::Triangle)
    return fmt::format("scheme '{}' uses a split whose child faces do not nest inside one parent face (sqrt3, dual, "
                       "mid-edge or a plugin's split): evaluation at (face, u, v) is implemented for the binary quad "
                       "and triangle splits only so far",
                       scheme.name);
  return {};
}

struct LimitSurface::Impl {
  std::shared_ptr<const Scheme> scheme;
  Level base;
  LimitSurfaceOptions options;
  bool triangles = false;
  int radius = 4;
  std::unique_ptr<SchemeLimits> limits;

  static void derive(const CornerDerivatives& rows, const Jacobian& J, const std::vector<StepMatrix>& steps,
                     const std::vector<double>& first_values, int channels, LimitSample& out,
                     std::vector<double>* du_row, std::vector<double>* dv_row);

  FacePoint start(Index face, double u, double v) const {
    const char* why = "";
    if (face < 0 || face >= base.face_count())
      throw Error(fmt::format("face {} does not exist (the mesh has {} faces)", face, base.face_count()));
    if (base.is_hole(face)) throw Error(fmt::format("face {} is a hole: it has no limit surface", face));
    const auto p = base_face_point(base, face, u, v, triangles, &why);
    if (!p) throw Error(fmt::format("face {} at (u, v) = ({}, {}): {}", face, u, v, why));
    return *p;
  }

  // Follows the point down the refinement of its neighbourhood until it is a vertex.
  // The position from the values carried down; the derivatives as rows over the first
  // cut's vertices (`du_row`, `dv_row`), applied to its values.
  LimitSample descend(Neighbourhood n, int channels, std::vector<double>* du_row = nullptr,
                      std::vector<double>* dv_row = nullptr) const {
    std::string mask_error;
    LimitSample out;
    const std::vector<double> first_values = n.values;
    std::vector<StepMatrix> steps;
    CornerDerivatives rows;
    for (int step = 0;; ++step) {
      const int shape = n.level.face_size(n.point.face);
      if (step >= options.max_steps) {
        // The face is 2^-max_steps of the base face: its nearest corner is the point to round-off.
        n.point.st = {std::round(n.point.st[0]), std::round(n.point.st[1])};
        if (triangles && n.point.st[0] + n.point.st[1] > 1) n.point.st[1] = 0;
        if (step >= options.max_steps + 16)
          throw Error(fmt::format("no limit mask for the vertex reached after {} steps{}{}", step,
                                  mask_error.empty() ? "" : ": ", mask_error));
      }
      const int corner = corner_at(n.point, shape, triangles);
      if (corner >= 0 &&
          corner_limit(*limits, n.level, n.values, channels, n.point, corner, step, triangles, out, rows,
                       mask_error)) {
        out.steps = step;
        if (!rows.ds.empty()) derive(rows, n.point.jacobian, steps, first_values, channels, out, du_row, dv_row);
        return out;
      }
      RefineOptions ro;
      ro.levels = 1;
      ro.first_step = step;
      ro.features = options.features;
      ro.threads = 1;
      const Hierarchy h = refine(*scheme, n.level, ro);
      const std::vector<double> child = h.stencils[0].apply(n.values, channels);
      const auto q = child_face_point(n.level, h.levels[1], h.origins[0], n.point, triangles);
      if (!q) throw Error("internal: no child face holds the point (the split is not a binary primal one)");
      const Index parent_count = n.level.vertex_count;
      n = cut(h.levels[1], child, channels, *q, radius);
      steps.push_back(step_matrix(h.stencils[0], n.original, parent_count));
    }
  }
};

void LimitSurface::Impl::derive(const CornerDerivatives& rows, const Jacobian& J, const std::vector<StepMatrix>& steps,
                                const std::vector<double>& first_values, int channels, LimitSample& out,
                                std::vector<double>* du_row, std::vector<double>* dv_row) {
  const int k = int(steps.size());
  std::vector<double> u(rows.ds.size()), v(rows.ds.size());
  for (size_t i = 0; i < u.size(); ++i) {
    u[i] = std::ldexp(J[0][0] * rows.ds[i] + J[1][0] * rows.dt[i], -k);
    v[i] = std::ldexp(J[0][1] * rows.ds[i] + J[1][1] * rows.dt[i], -k);
  }
  u = pulled_back(std::move(u), steps);
  v = pulled_back(std::move(v), steps);
  out.du = applied(u, first_values, channels);
  out.dv = applied(v, first_values, channels);
  out.has_derivatives = true;
  if (du_row) *du_row = std::move(u);
  if (dv_row) *dv_row = std::move(v);
}

LimitSurface::LimitSurface(std::shared_ptr<const Scheme> scheme, Level base, const LimitSurfaceOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (!scheme) throw Error("no scheme given for the limit surface");
  if (const std::string why = limit_surface_unsupported(*scheme); !why.empty()) throw Error(why);
  impl_->scheme = std::move(scheme);
  impl_->base = std::move(base);
  impl_->options = options;
  impl_->triangles = impl_->scheme->split() == SplitKind::Triangle;
  // Children near the cut's rim follow the rim's artificial boundary; with a reach of r
  // parent rings, 2 r + 2 rings keep the face's own neighbourhood right from level to level.
  const SchemeRun run{impl_->scheme.get(), 1};
  double loss = 1;
  for (double x : ring_loss_per_level(std::span<const SchemeRun>(&run, 1))) loss = std::max(loss, x);
  impl_->radius = std::max(4, 2 * int(std::ceil(loss)) + 2);
  LimitOptions lo;
  lo.features = options.features;
  impl_->limits = std::make_unique<SchemeLimits>(*impl_->scheme, lo);
}

LimitSurface::~LimitSurface() = default;
LimitSurface::LimitSurface(LimitSurface&&) noexcept = default;
LimitSurface& LimitSurface::operator=(LimitSurface&&) noexcept = default;

const Level& LimitSurface::base() const { return impl_->base; }

std::string LimitSurface::check(Index face, double u, double v) const {
  try {
    impl_->start(face, u, v);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

LimitSample LimitSurface::evaluate(Index face, double u, double v, std::span<const double> values, int channels) const {
  if (channels < 1 || values.size() < size_t(impl_->base.vertex_count) * size_t(channels))
    throw Error(fmt::format("limit evaluation needs {} values per vertex for {} vertices, got {}", channels,
                            impl_->base.vertex_count, values.size()));
  return impl_->descend(cut(impl_->base, values, channels, impl_->start(face, u, v), impl_->radius), channels);
}

LimitStencil LimitSurface::stencil(Index face, double u, double v) const {
  const FacePoint p = impl_->start(face, u, v);
  // The evaluation is linear in the values: evaluate the unit vectors of the face's
  // neighbourhood (the only vertices it reads) as channels.
  Neighbourhood n = cut(impl_->base, {}, 0, p, impl_->radius);
  const size_t m = n.original.size();
  n.values.assign(m * m, 0.0);
  for (size_t k = 0; k < m; ++k) n.values[k * m + k] = 1.0;
  const std::vector<Index> original = n.original;
  std::vector<double> du, dv;
  const LimitSample s = impl_->descend(std::move(n), int(m), &du, &dv);
  LimitStencil out;
  out.has_derivatives = s.has_derivatives;
  for (size_t k = 0; k < m; ++k) {
    const bool used = s.position[k] != 0 || (s.has_derivatives && (du[k] != 0 || dv[k] != 0));
    if (!used) continue;
    out.vertices.push_back(original[k]);
    out.position.push_back(s.position[k]);
    if (s.has_derivatives) out.du.push_back(du[k]), out.dv.push_back(dv[k]);
  }
  return out;
}

}  // namespace subdiv
