#pragma once
// A polynomial patch of degree 4 in each of s and t over a quad, held as its values at the
// lattice (i/4, j/4), 0 <= i, j <= 4, and evaluated with the tensor product of that
// lattice's Lagrange bases. The quad analogue of triangle_patch.h: a node whose exactly
// sampled rows satisfy its refinement equations as such a polynomial is one — Catmull-Clark's
// faces along boundaries and infinitely sharp creases (bicubic B-spline patches with
// phantom points; Lacewell & Burley 2007), which the interior B-spline
// check (limit_nodes.h) does not see, since their neighbourhoods lack the full 4 x 4 grid.
#include <vector>

#include "framework/limit/corner_limit.h"

namespace subdiv {

constexpr int kTensorLattice = 25;

// The (s, t) of lattice point q = j * 5 + i.
Uv tensor_lattice_point(int q);

// Rows of `labels` entries: position, first and second derivatives at (s, t); with `order`
// below 2 the derivative rows above it are left empty (each row's values do not depend on it).
CornerRows tensor_rows(const std::vector<std::vector<double>>& lattice, const Uv& st, int order = 2);

}  // namespace subdiv
