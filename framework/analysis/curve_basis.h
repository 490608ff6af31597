#pragma once
// Samples of a curve scheme's refinable function phi (curve_mask.h: the limit curve is
// sum_j P_j phi(t - j), phi(t) = sum_i a_i phi(m t - i)), exact up to round-off:
//   - at the integers: phi(k) = sum_l a_{m k - l} phi(l), the eigenvector of eigenvalue 1
//     of that finite system with sum_k phi(k) = 1 (seed 000 §3(d): the limit mask);
//   - at the centre c of phi's support, [first, last] / (m - 1), shifted by integers, from
//     the integer values through the refinement equation (c is a multiple of 1/(2(m-1)),
//     reached after a few steps whenever m^r c is an integer).
// The limit point "of" control point j is then sum_d phi(c + d) P_{j - d}: the limit
// point itself for primal schemes (c = 0), the quadratic B-spline's (1, 6, 1)/8 for
// Chaikin.
#include <string>
#include <vector>

#include "framework/analysis/curve_mask.h"

namespace subdiv {

struct BasisSamples {
  int integers_first = 0;           // phi(integers_first + i) = at_integers[i]
  std::vector<double> at_integers;
  double centre = 0;                // c
  int centre_first = 0;             // phi(c + centre_first + i) = at_centre[i]
  std::vector<double> at_centre;
};

// Throws subdiv::Error (naming `scheme`) when the system has no solution summing to one
// (the scheme does not converge) or when c cannot be reached in a few steps.
BasisSamples sample_basis(const CurveMask& mask, const std::string& scheme);

}  // namespace subdiv
