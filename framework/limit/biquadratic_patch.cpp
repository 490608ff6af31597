#include "framework/limit/biquadratic_patch.h"

#include <cmath>

#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/stencil/stencil_table.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// The face around w whose corners run w, x, ... (CCW), and w's position in it.
Index face_from(const Level& level, Index w, Index x, int& at) {
  for (Index f : level.ring_faces(w)) {
    const auto c = level.face(f);
    const int n = int(c.size());
    for (int i = 0; i < n; ++i)
      if (c[size_t(i)] == w && c[size_t((i + 1) % n)] == x) return at = i, f;
  }
  return kNone;
}

// Quadratic B-spline basis on [-1/2, 1/2] with control points at -1, 0, 1, and its
// first and second derivatives.
std::array<double, 3> basis(double s) { return {0.5 * (0.5 - s) * (0.5 - s), 0.75 - s * s, 0.5 * (0.5 + s) * (0.5 + s)}; }
std::array<double, 3> basis_d(double s) { return {s - 0.5, -2 * s, s + 0.5}; }
constexpr std::array<double, 3> kBasisDd{1, -2, 1};

Level quad_torus(int n) {
  std::vector<Index> offsets{0}, corners;
  auto id = [n](int i, int j) { return Index(((i + n) % n) * n + (j + n) % n); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      for (Index v : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}) corners.push_back(v);
      offsets.push_back(Index(corners.size()));
    }
  return build_level(Index(n * n), offsets, corners);
}

}  // namespace

std::optional<std::array<Index, 9>> biquadratic_grid(const Level& level, Index face, int corner) {
  const auto g = level.face(face);
  if (g.size() != 4) return std::nullopt;
  const Index w = g[size_t(corner)];
  if (level.on_boundary(w) || level.valence(w) != 4 || level.incident_face_count(w) != 4) return std::nullopt;
  std::array<Index, 9> P{};
  auto at = [&P](int p, int q) -> Index& { return P[size_t((q + 1) * 3 + (p + 1))]; };
  at(0, 0) = w;
  // The four faces around w, CCW from g: (w, (1,0), (1,1), (0,1)), (w, (0,1), (-1,1), (-1,0)), ...
  constexpr int kDir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  Index x = g[size_t((corner + 1) % 4)];
  for (int k = 0; k < 4; ++k) {
    int i = 0;
    const Index f = face_from(level, w, x, i);
    if (f == kNone || level.face_size(f) != 4) return std::nullopt;
    const auto c = level.face(f);
    const int* d = kDir[k];
    const int* e = kDir[(k + 1) % 4];
    at(d[0], d[1]) = c[size_t((i + 1) % 4)];
    at(d[0] + e[0], d[1] + e[1]) = c[size_t((i + 2) % 4)];
    at(e[0], e[1]) = c[size_t((i + 3) % 4)];
    x = c[size_t((i + 3) % 4)];
  }
  return P;
}

QuadrantRows biquadratic_rows(double a, double b) {
  const double s = 0.5 * a, t = 0.5 * b;
  const auto Bs = basis(s), Bt = basis(t), Ds = basis_d(s), Dt = basis_d(t);
  QuadrantRows r;
  for (int q = 0; q < 3; ++q)
    for (int p = 0; p < 3; ++p) {
      const size_t k = size_t(q * 3 + p);
      r.position[k] = Bs[size_t(p)] * Bt[size_t(q)];
      // d/da = (1/2) d/ds, d2/da2 = (1/4) d2/ds2.
      r.da[k] = 0.5 * Ds[size_t(p)] * Bt[size_t(q)];
      r.db[k] = 0.5 * Bs[size_t(p)] * Dt[size_t(q)];
      r.daa[k] = 0.25 * kBasisDd[size_t(p)] * Bt[size_t(q)];
      r.dab[k] = 0.25 * Ds[size_t(p)] * Dt[size_t(q)];
      r.dbb[k] = 0.25 * Bs[size_t(p)] * kBasisDd[size_t(q)];
    }
  return r;
}

bool refines_quad_corners_as(const Scheme& scheme, const FeatureOptions& features, int levels,
                             const std::function<ChildOrigins(const Hierarchy&)>& corners,
                             const std::array<double, 4>& weights) {
  const Level grid = quad_torus(8);
  RefineOptions ro;
  ro.levels = levels;
  ro.features = features;
  Hierarchy h;
  try {
    h = refine(scheme, grid, ro);
  } catch (const Error&) {
    return false;
  }
  if (!h.linear() || h.stencils.size() != size_t(levels)) return false;
  const ChildOrigins o = corners(h);
  StencilTable table = h.stencils[0];
  for (size_t k = 1; k < h.stencils.size(); ++k) table = compose(table, h.stencils[k]);
  if (Index(o.kind.size()) != grid.corner_count()) return false;
  for (size_t c = 0; c < o.kind.size(); ++c) {
    if (o.kind[c] != OriginKind::Corner) return false;
    const auto f = grid.face(o.parent[c]);
    const int i = int(o.local[c]);
    std::vector<double> row(size_t(grid.vertex_count), 0.0);
    for (Index e = table.offsets[c]; e < table.offsets[c + 1]; ++e)
      row[size_t(table.indices[size_t(e)])] += table.weights[size_t(e)];
    for (size_t k = 0; k < 4; ++k) row[size_t(f[(size_t(i) + k) % 4])] -= weights[k];
    for (double x : row)
      if (std::fabs(x) > 1e-13) return false;
  }
  return true;
}

bool refines_as_biquadratic(const Scheme& scheme, const FeatureOptions& features) {
  return refines_quad_corners_as(scheme, features, 1, [](const Hierarchy& h) { return h.origins[0]; },
                                 {9.0 / 16, 3.0 / 16, 1.0 / 16, 3.0 / 16});
}

}  // namespace subdiv
