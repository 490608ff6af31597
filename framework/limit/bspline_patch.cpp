#include "framework/limit/bspline_patch.h"

namespace subdiv {

namespace {

// The uniform cubic B-spline basis on [0, 1] (control points at -1, 0, 1, 2) and its
// derivative.
std::array<double, 4> cubic_basis(double s) {
  const double r = 1 - s;
  return {r * r * r / 6, (3 * s * s * s - 6 * s * s + 4) / 6, (-3 * s * s * s + 3 * s * s + 3 * s + 1) / 6, s * s * s / 6};
}
std::array<double, 4> cubic_basis_derivative(double s) {
  const double r = 1 - s;
  return {-r * r / 2, (3 * s * s - 4 * s) / 2, (-3 * s * s + 2 * s + 1) / 2, s * s / 2};
}

}  // namespace

CornerRows bspline_rows(const std::array<Index, 16>& grid, const Uv& st, Index labels) {
  const auto bs = cubic_basis(st[0]), bt = cubic_basis(st[1]);
  const auto ds = cubic_basis_derivative(st[0]), dt = cubic_basis_derivative(st[1]);
  CornerRows r;
  r.position.assign(size_t(labels), 0.0);
  r.ds.assign(size_t(labels), 0.0);
  r.dt.assign(size_t(labels), 0.0);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const size_t l = size_t(grid[size_t(j * 4 + i)]);
      r.position[l] = bs[size_t(i)] * bt[size_t(j)];
      r.ds[l] = ds[size_t(i)] * bt[size_t(j)];
      r.dt[l] = bs[size_t(i)] * dt[size_t(j)];
    }
  return r;
}

}  // namespace subdiv
