#pragma once
// A polynomial patch of degree 4 in each of s and t over a quad, held as its values at the
// lattice (i/4, j/4), 0 <= i, j <= 4, and evaluated with the tensor product of that
// lattice's Lagrange bases. The quad analogue of triangle_patch.h: a node whose exactly
// sampled rows satisfy its refinement equations as such a polynomial is one — Catmull-Clark's
// faces along boundaries and infinitely sharp creases (bicubic B-spline patches with
// phantom points; Lacewell & Burley 2007), which the interior B-spline
// check (limit_nodes.h) does not see, since their neighbourhoods lack the full 4 x 4 grid.
#include <optional>
#include <vector>

#include "framework/limit/bspline_patch.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/triangle_patch.h"

namespace subdiv {

constexpr int kTensorLattice = 25;

// The (s, t) of lattice point q = j * 5 + i.
Uv tensor_lattice_point(int q);

// Rows of `labels` entries: position, first and second derivatives at (s, t); with `order`
// below 2 the derivative rows above it are left empty (each row's values do not depend on it).
CornerRows tensor_rows(const std::vector<std::vector<double>>& lattice, const Uv& st, int order = 2);

// The control points' labels of a patch given by its rows at the lattice when every
// label's lattice values are one uniform bicubic B-spline function's (bspline_patch.h) to
// 1e-12, each function taken once, or all zero; empty otherwise. Both are polynomials of
// degree at most 4 in each of s and t, so agreeing at the lattice they agree everywhere:
// the patch is then the B-spline's, evaluated in closed form (nodes next to an
// extraordinary vertex, which LimitNodes::bspline's check of every node they lead to does
// not take).
std::optional<BicubicLabels> bicubic_lattice_labels(const std::vector<std::vector<double>>& lattice);

// The patch of a quad from its lattice rows, its B-spline labels found when it is one.
PolynomialPatch tensor_patch(std::vector<std::vector<double>> lattice);

}  // namespace subdiv
