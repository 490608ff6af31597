#include "framework/limit/bspline_patch.h"

#include <algorithm>

namespace subdiv {

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
