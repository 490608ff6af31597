#pragma once
// A polynomial patch of degree 4 over a triangle, held as its values at the principal
// lattice (i/4, j/4), i + j <= 4, and evaluated with that lattice's Lagrange basis in
// barycentric coordinates (Nicolaides 1972): Loop's regular triangles are quartic box
// spline patches (Stam 1998, "Evaluation of Loop subdivision surfaces"), and a node whose
// sampled rows satisfy its own refinement equations exactly as a quartic is one. A patch
// that is the quartic box spline's is evaluated from the box spline's closed forms instead
// (box_spline_patch.h).
#include <array>
#include <optional>
#include <vector>

#include "framework/limit/box_spline_patch.h"
#include "framework/limit/bspline_patch.h"
#include "framework/limit/corner_limit.h"

namespace subdiv {

constexpr int kQuarticLattice = 15;

// The (s, t) of lattice point q, the points ordered by rows j = 0..4, i = 0..4 - j.
Uv quartic_lattice_point(int q);

// A node's polynomial patch as the nodes keep it (LimitNodes::quartic): its rows at the
// lattice (this file's for a triangle, tensor_patch.h's for a quad) and, for a triangle
// whose patch is the quartic box spline, which label is which of the spline's functions;
// for a quad whose patch is the bicubic B-spline (tensor_patch.h), its control points' labels.
struct PolynomialPatch {
  std::vector<std::vector<double>> lattice;
  std::optional<BoxSplineLabels> box;
  std::optional<BicubicLabels> bicubic;
};

// The patch of a triangle from its lattice rows, its box spline labels found when it is one.
PolynomialPatch triangle_patch(std::vector<std::vector<double>> lattice);

// Rows of `labels` entries: position, first and second derivatives at (s, t), from the box
// spline's closed forms where the patch has them, else from the lattice rows (the lattice
// form alone: the second overload).
// With `order` below 2 the derivative rows above it are left empty (each row's values do
// not depend on it).
CornerRows quartic_rows(const PolynomialPatch& patch, const Uv& st, int order = 2);
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
bool quartic_rows_fixed(const PolynomialPatch& patch, const Uv& st, int order, FixedRows& out);

// l_m(z) = prod_{a < m} (z - a) / (m - a), the Lagrange factor of the lattice, with its first
// and second derivatives in z.
void lagrange_factor(int m, double z, double& value, double& derivative, double& second);

}  // namespace subdiv
