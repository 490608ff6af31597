#include "framework/limit/four_direction_patch.h"

#include <cmath>
#include <utility>

#include "framework/engine/refiner.h"
#include "framework/limit/mid_edge_limit.h"
#include "framework/scheme/scheme.h"
#include "framework/stencil/stencil_table.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// B_pq on the triangle 0 <= y <= x <= 1/2 (the header's pieces expanded), in eighths:
// 8 B_pq = c + cx x + cy y + cxx x^2 + cxy x y + cyy y^2. B_-1,-1 and B_-1,1 are zero there.
struct Piece {
  int p, q;
  double c, cx, cy, cxx, cxy, cyy;
};
constexpr Piece kPieces[] = {
    {0, 0, 4, 0, 0, -4, 0, -4},   // (1 - x^2 - y^2)/2
    {1, 0, 1, 4, 0, 0, 0, -4},    // X = 1 - x: (1 - X^2 - y^2)/2 + (2X - 1)^2/8
    {-1, 0, 1, -4, 0, 4, 0, 0},   // X = 1 + x: (3 - 2X)^2/8
    {0, 1, 1, 0, 4, -2, -4, 2},   // (X, Y) = (1 - y, x): (1 + y - x)^2/4 - (2x - 1)^2/8
    {0, -1, 1, 0, -4, -2, 4, 2},  // (X, Y) = (1 + y, x): (1 - x - y)^2/4 - (2x - 1)^2/8
    {1, 1, 0, 0, 0, 2, 4, 2},     // (X, Y) = (1 - y, 1 - x): (x + y)^2/4
    {1, -1, 0, 0, 0, 2, -4, 2},   // (X, Y) = (1 + y, 1 - x): (x - y)^2/4
};

size_t grid_index(int p, int q) { return size_t((q + 1) * 3 + (p + 1)); }

// One composed row of the two steps as (vertex, weight) sums, compared with the expected
// weights to 1e-13.
bool row_is(const StencilTable& table, size_t row, Index vertices,
            const std::array<std::pair<Index, double>, 3>& expected) {
  std::vector<double> w(size_t(vertices), 0.0);
  for (Index e = table.offsets[row]; e < table.offsets[row + 1]; ++e)
    w[size_t(table.indices[size_t(e)])] += table.weights[size_t(e)];
  for (const auto& [v, x] : expected) w[size_t(v)] -= x;
  for (double x : w)
    if (std::fabs(x) > 1e-13) return false;
  return true;
}

}  // namespace

QuadrantRows four_direction_rows(double a, double b) {
  // On a < b the mirror image: B_pq(x, y) = B_qp(y, x), so the triangle's functions are
  // evaluated at (y, x) and put at the transposed grid point with the derivatives swapped.
  const bool mirrored = a < b;
  const double x = 0.5 * (mirrored ? b : a), y = 0.5 * (mirrored ? a : b);
  QuadrantRows r;
  for (const Piece& c : kPieces) {
    const double value = (c.c + c.cx * x + c.cy * y + c.cxx * x * x + c.cxy * x * y + c.cyy * y * y) / 8;
    const double dx = (c.cx + 2 * c.cxx * x + c.cxy * y) / 8, dy = (c.cy + c.cxy * x + 2 * c.cyy * y) / 8;
    const double dxx = c.cxx / 4, dxy = c.cxy / 8, dyy = c.cyy / 4;
    const size_t k = mirrored ? grid_index(c.q, c.p) : grid_index(c.p, c.q);
    // d/da = (1/2) d/dx (or d/dy, mirrored), d2/da2 = (1/4) d2/dx2.
    r.position[k] = value;
    r.da[k] = 0.5 * (mirrored ? dy : dx);
    r.db[k] = 0.5 * (mirrored ? dx : dy);
    r.daa[k] = 0.25 * (mirrored ? dyy : dxx);
    r.dab[k] = 0.25 * dxy;
    r.dbb[k] = 0.25 * (mirrored ? dxx : dyy);
  }
  return r;
}

bool on_four_direction_knot_line(double a, double b) { return a == b || a == 1 || b == 1; }

bool refines_as_four_direction(const Scheme& scheme, const FeatureOptions& features) {
  const Level grid = quad_torus(8);
  RefineOptions ro;
  ro.levels = 2;
  ro.features = features;
  Hierarchy h;
  try {
    h = refine(scheme, grid, ro);
  } catch (const Error&) {
    return false;
  }
  if (!h.linear() || h.stencils.size() != 2) return false;
  const ChildOrigins o = mid_edge_double_origins(h.levels[0], h.levels[1], h.origins[0], h.levels[2], h.origins[1]);
  const StencilTable table = compose(h.stencils[0], h.stencils[1]);
  if (o.kind.size() != size_t(grid.corner_count())) return false;
  for (size_t c = 0; c < o.kind.size(); ++c) {
    if (o.kind[c] != OriginKind::Corner) return false;
    const auto f = grid.face(o.parent[c]);
    const int j = int(o.local[c]);
    if (!row_is(table, c, grid.vertex_count,
                {{{f[size_t(j)], 0.5}, {f[size_t((j + 1) % 4)], 0.25}, {f[size_t((j + 3) % 4)], 0.25}}}))
      return false;
  }
  return true;
}

}  // namespace subdiv
