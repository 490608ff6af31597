#pragma once
// The uniform bicubic B-spline patch (de Boor; Stam 1998 section 3 for Catmull-Clark's
// regular faces) of a 4 x 4 grid of control points, as rows over a node's labels: the
// closed form limit_nodes.h finds for regular regions.
#include <array>
#include <cstdint>

#include "framework/limit/corner_limit.h"

namespace subdiv {

// The patch at (s, t) in [0, 1]^2, control points at -1, 0, 1, 2 in each direction; `grid`
// holds their labels row by row from (-1, -1). Position, first and second derivative rows
// of `labels` entries.
CornerRows bspline_rows(const std::array<Index, 16>& grid, const Uv& st, Index labels);

// The same weights per control point (row by row from (-1, -1)) in fixed arrays: what
// bspline_rows places at the grid's labels, for callers that cannot afford the rows'
// allocations (the evaluation of a point in a regular face). With `derivatives` below 2 the
// second-derivative arrays are left unset (a point without them does not pay for them).
struct BsplineWeights {
  std::array<double, 16> position, ds, dt, dss, dst, dtt;
};
inline BsplineWeights bspline_weights(const Uv& st, int derivatives = 2);

// A patch's 16 control points among a node's labels: `grid` the label of each cell (row by
// row from (-1, -1)); `label` the same labels in increasing order and `cell` the cell of
// each, the order in which a sum over the node's labels meets them.
struct BicubicLabels {
  std::array<Index, 16> grid{}, label{};
  std::array<std::uint8_t, 16> cell{};
};
BicubicLabels bicubic_labels(const std::array<Index, 16>& grid);

namespace bspline_detail {

// The uniform cubic B-spline basis on [0, 1] (control points at -1, 0, 1, 2) and its
// derivative.
inline std::array<double, 4> cubic_basis(double s) {
  const double r = 1 - s;
  return {r * r * r / 6, (3 * s * s * s - 6 * s * s + 4) / 6, (-3 * s * s * s + 3 * s * s + 3 * s + 1) / 6, s * s * s / 6};
}
inline std::array<double, 4> cubic_basis_derivative(double s) {
  const double r = 1 - s;
  return {-r * r / 2, (3 * s * s - 4 * s) / 2, (-3 * s * s + 2 * s + 1) / 2, s * s / 2};
}
inline std::array<double, 4> cubic_basis_second_derivative(double s) { return {1 - s, 3 * s - 2, 1 - 3 * s, s}; }

}  // namespace bspline_detail

// Inline: called for every point of a regular face, where the call and the returned
// arrays cost about as much as the weights themselves.
inline BsplineWeights bspline_weights(const Uv& st, int derivatives) {
  using namespace bspline_detail;
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

}  // namespace subdiv
