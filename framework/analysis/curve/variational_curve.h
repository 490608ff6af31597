#pragma once
// Variational interpolatory curve schemes (Kobbelt 1996, "A variational approach to
// subdivision", CAGD 13(8) 743-761): the old points stay, and the new points of one step
// minimise a discrete fairness energy of the refined polygon P,
//
//     E(P) = sum_i K(P_i)^2,   K(P_i) = sum_{j=0..s} alpha_j P_{i+j-r},
//
// with alpha(1) = sum_j alpha_j = 0. Setting the derivatives with respect to the new points
// to zero gives one banded, symmetric positive definite linear system per level (cyclic for
// closed polygons), solved here with Eigen's sparse LDL^T.
//
// Open polylines: the sum runs over the i whose stencil i - r .. i - r + s lies inside the
// refined polyline (no points are invented beyond its ends). The ends so get the natural
// end conditions of the restricted energy: linear data stays linear up to the ends, cubic
// data is reproduced only away from them.
//
// The solution of a closed polygon is translation invariant and decays geometrically away
// from each old point, so the bi-infinite rules (the scheme's mask, for analysis) are read
// off a long closed polygon, trimmed where the weights fall below round-off.
#include <string>
#include <utility>
#include <vector>

#include "framework/analysis/curve/curve_mask.h"
#include "framework/scheme/curve_scheme.h"

namespace subdiv {

struct VariationalEnergy {
  int arity = 2;               // m: old point i is refined point m i
  std::vector<double> alpha;   // alpha_0 .. alpha_s
  int r = 0;                   // K(P_i) reads P_{i-r} .. P_{i-r+s}
  std::string where;           // the scheme file, for messages
};

// The scheme's energy at level `level` (alpha may be formulas of the parameters and l).
// Throws subdiv::Error naming the file when a coefficient is not finite or alpha(1) != 0.
VariationalEnergy variational_energy(const CurveScheme& curve, int level);

// One new point's weights: (old point, weight) in increasing old point order.
using VariationalRow = std::vector<std::pair<long, double>>;

// The new points of one polyline of `n` old points as rows over its old points (0 .. n-1).
// Polylines up to kVariationalWindow points are solved whole (every weight); longer ones
// take the bi-infinite rules away from the ends, trimmed at round-off. New point q is refined
// point m (q / (m-1)) + 1 + q % (m-1): (m-1) n of them in a closed polygon, (m-1)(n-1) in
// an open polyline.
// Throws subdiv::Error when the energy does not determine the new points (too few points).
std::vector<VariationalRow> variational_rows(const VariationalEnergy& e, long n, bool closed);

// Rule r (1 <= r < m) of the bi-infinite scheme: weights on old points i + start, ...;
// rule 0 keeps the old point. Weights below 1e-17 of the largest are trimmed.
void variational_rules(const VariationalEnergy& e, std::vector<int>& starts, std::vector<std::vector<double>>& weights);

// The old points of a polygon far from which the bi-infinite rules hold to round-off:
// variational_rows solves polylines up to this size whole.
inline constexpr long kVariationalWindow = 256;

}  // namespace subdiv
