#include "framework/limit/bspline_patch.h"

#include <algorithm>

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
std::array<double, 4> cubic_basis_second_derivative(double s) { return {1 - s, 3 * s - 2, 1 - 3 * s, s}; }

}  // namespace

BsplineWeights bspline_weights(const Uv& st, int derivatives) {
  const auto bs = cubic_basis(st[0]), bt = cubic_basis(st[1]);
  const auto ds = cubic_basis_derivative(st[0]), dt = cubic_basis_derivative(st[1]);
  BsplineWeights w;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const size_t k = size_t(j * 4 + i), a = size_t(i), b = size_t(j);
      w.position[k] = bs[a] * bt[b];
      w.ds[k] = ds[a] * bt[b];
      w.dt[k] = bs[a] * dt[b];
    }
  if (derivatives < 2) return w;
  const auto dss = cubic_basis_second_derivative(st[0]), dtt = cubic_basis_second_derivative(st[1]);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const size_t k = size_t(j * 4 + i), a = size_t(i), b = size_t(j);
      w.dss[k] = dss[a] * bt[b];
      w.dst[k] = ds[a] * dt[b];
      w.dtt[k] = bs[a] * dtt[b];
    }
  return w;
}

BicubicLabels bicubic_labels(const std::array<Index, 16>& grid) {
  BicubicLabels b;
  b.grid = grid;
  std::array<std::uint8_t, 16> cells;
  for (size_t k = 0; k < 16; ++k) cells[k] = std::uint8_t(k);
  std::sort(cells.begin(), cells.end(), [&](std::uint8_t x, std::uint8_t y) { return grid[x] < grid[y]; });
  for (size_t l = 0; l < 16; ++l) b.cell[l] = cells[l], b.label[l] = grid[cells[l]];
  return b;
}

CornerRows bspline_rows(const std::array<Index, 16>& grid, const Uv& st, Index labels) {
  const BsplineWeights w = bspline_weights(st);
  CornerRows r;
  for (auto* row : {&r.position, &r.ds, &r.dt, &r.dss, &r.dst, &r.dtt}) row->assign(size_t(labels), 0.0);
  for (size_t k = 0; k < 16; ++k) {
    const size_t l = size_t(grid[k]);
    r.position[l] = w.position[k];
    r.ds[l] = w.ds[k];
    r.dt[l] = w.dt[k];
    r.dss[l] = w.dss[k];
    r.dst[l] = w.dst[k];
    r.dtt[l] = w.dtt[k];
  }
  return r;
}

}  // namespace subdiv
