#pragma once
// Samples of a curve scheme's refinable function phi (curve_mask.h: the limit curve is
// sum_j P_j phi(t - j), phi(t) = sum_i a_i phi(m t - i)), exact up to round-off:
//   - at the integers: the limit mask of the local subdivision matrix (curve_eigen.h,
//     Halstead, Kass & DeRose 1993), since the limit at t = 0 is sum_j phi(-j) P_j;
//   - at the centre c of phi's support, [first, last] / (m - 1), shifted by integers, from
//     the integer values through the refinement equation (c is a multiple of 1/(2(m-1)),
//     reached after a few steps whenever m^r c is an integer).
// The limit point "of" control point j is then sum_d phi(c + d) P_{j - d}: the limit
// point itself for primal schemes (c = 0), the quadratic B-spline's (1, 6, 1)/8 for
// Chaikin.
#include <string>
#include <vector>

#include "framework/analysis/curve/curve_mask.h"

namespace subdiv {

struct BasisSamples {
  int integers_first = 0;           // phi(integers_first + i) = at_integers[i]
  std::vector<double> at_integers;
  double centre = 0;                // c
  int centre_first = 0;             // phi(c + centre_first + i) = at_centre[i]
  std::vector<double> at_centre;
};

// Throws subdiv::Error (naming `scheme`) when the scheme has no limit mask (1 is not the
// simple dominant eigenvalue) or when c cannot be reached in a few steps.
BasisSamples sample_basis(const CurveMask& mask, const std::string& scheme);

}  // namespace subdiv
