#pragma once
// The local subdivision matrix of a curve scheme on the invariant neighbourhood of an old
// point (Zorin et al. 2000).
#include "framework/analysis/curve/curve_mask.h"

#include <vector>

namespace subdiv {

// Rows and columns are control points first_index .. first_index + size() - 1 around old
// point 0 (mask indexing of curve_mask.h); rows[p][j] is the weight of old point
// first_index + j in new point first_index + p.
struct LocalSubdivisionMatrix {
  int first_index = 0;
  std::vector<std::vector<double>> rows;

  int size() const { return static_cast<int>(rows.size()); }
};

// The invariant neighbourhood is, as in Zorin et al. 2000, the set of control points whose
// basis functions phi(t - j) do not vanish on every small interval around t = 0. The
// refinable function of a mask a_first..a_last of arity m is supported on
// [first/(m-1), last/(m-1)] (from phi(t) = sum_i a_i phi(m t - i)), so the neighbourhood
// is the integers j in [-last/(m-1), -first/(m-1)]: 5 points for the mask (1,4,6,4,1)/8 on
// -2..2, 7 for a 4-point mask on -3..3. New points of that range depend only on old points
// of that range, so the matrix is square and S^k describes every level.
//
// This is wider than the smallest set that merely maps to itself (3 points for the first
// example): that set only sees the limit point, while the full neighbourhood also sees the
// curve on both sides of it, which is what the eigen-analysis needs.
//
// "Around old point 0" means around parameter t = 0 of the mask's own indexing. For a
// mask centred on 0 (primal: (1,4,6,4,1)/8, 4-point) that is an old vertex; for a dual
// mask such as (1,3,3,1)/4 on -1..2 it is the knot between old points -1 and 0.
//
// Zero coefficients at the ends of the mask are ignored. The result is empty when no
// integer lies in the range (a degenerate mask, e.g. one coefficient at index 1, m = 3).
LocalSubdivisionMatrix local_subdivision_matrix(const CurveMask& mask);

}  // namespace subdiv
