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
BsplineWeights bspline_weights(const Uv& st, int derivatives = 2);

// A patch's 16 control points among a node's labels: `grid` the label of each cell (row by
// row from (-1, -1)); `label` the same labels in increasing order and `cell` the cell of
// each, the order in which a sum over the node's labels meets them.
struct BicubicLabels {
  std::array<Index, 16> grid{}, label{};
  std::array<std::uint8_t, 16> cell{};
};
BicubicLabels bicubic_labels(const std::array<Index, 16>& grid);

}  // namespace subdiv
