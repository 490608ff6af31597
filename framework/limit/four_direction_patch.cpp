#include "framework/limit/four_direction_patch.h"

#include "framework/limit/mid_edge_limit.h"

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
  return refines_quad_corners_as(
      scheme, features, 2,
      [](const Hierarchy& h) {
        return mid_edge_double_origins(h.levels[0], h.levels[1], h.origins[0], h.levels[2], h.origins[1]);
      },
      {0.5, 0.25, 0, 0.25});
}

}  // namespace subdiv
