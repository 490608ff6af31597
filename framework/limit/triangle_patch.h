#pragma once
// A polynomial patch of degree 4 over a triangle, held as its values at the principal
// lattice (i/4, j/4), i + j <= 4, and evaluated with that lattice's Lagrange basis in
// barycentric coordinates (Nicolaides 1972): Loop's regular triangles are quartic box
// spline patches (Stam 1998, "Evaluation of Loop subdivision surfaces"), and a node whose
// sampled rows satisfy its own refinement equations exactly as a quartic is one.
#include <array>
#include <vector>

#include "framework/limit/corner_limit.h"

namespace subdiv {

constexpr int kQuarticLattice = 15;

// The (s, t) of lattice point q, the points ordered by rows j = 0..4, i = 0..4 - j.
Uv quartic_lattice_point(int q);

// Rows of `labels` entries: position, first and second derivatives at (s, t) from the
// lattice rows.
// With `order` below 2 the derivative rows above it are left empty (each row's values do
// not depend on it).
CornerRows quartic_rows(const std::vector<std::vector<double>>& lattice, const Uv& st, int order = 2);

// quartic_rows for a patch over at most kFixedLabels labels (Loop's regular triangle: 12)
// into fixed arrays, the same products summed in the same order (the same bits), without
// allocating: the per-point path of faces whose own node is such a patch.
constexpr size_t kFixedLabels = 16;
struct FixedRows {
  size_t labels = 0;
  int count = 0;  // rows set: 1 (position), 3 (and d/ds, d/dt) or 6 (and d2/ds2, d2/dsdt, d2/dt2)
  std::array<std::array<double, kFixedLabels>, 6> row;
};
// False (nothing set) when the patch has more labels than that.
bool quartic_rows_fixed(const std::vector<std::vector<double>>& lattice, const Uv& st, int order, FixedRows& out);

// l_m(z) = prod_{a < m} (z - a) / (m - a), the Lagrange factor of the lattice, with its first
// and second derivatives in z.
void lagrange_factor(int m, double z, double& value, double& derivative, double& second);

}  // namespace subdiv
