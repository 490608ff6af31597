#pragma once
// Quads between two creases under a dual split (docs/limit.md, "Faces between two creases"):
// between infinitely sharp creases the limit in closed form, between semi-sharp ones the step
// that follows a point along them until they decay.
//
// A quad whose two opposite edges lie on infinitely sharp creases (boundaries, sharpness
// >= 10), and whose two other edges are smooth or run between two corners of the mesh, has
// every corner on a crease: each of its new points is made by the crease rule, and its
// children are again such quads — its F-face, and the E-faces of its smooth edges, between
// the same two creases (a sharp edge has no E-face, a crease vertex no V-face between the
// creases). The face is refined along the creases only, never across: after L steps the
// quads between the creases join the crease polygons' level-L points, so the limit is the
// ruled surface between the two limit crease curves,
//   S(u, v) = (1 - v) C_0(u) + v C_1(u),
// v across (linear, as the level-L quads are bilinear across), u along, the crease curves
// at the parameter the half faces beside them use (dual_crease_chart.h, crease_side_limit:
// Chaikin's curve, the uniform quadratic B-spline with its control points at their Greville
// abscissae, clamped at corners). Its derivatives exist: C_i are C1 in u, and d/dv is
// C_1 - C_0. Requires the scheme's crease to be Chaikin's (crease_middles_kept).
#include <array>
#include <optional>
#include <vector>

#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

// The layout of a quad between two creases: its crease edges are edges k and k + 2, k = 0
// (along u, across v) or k = 1 (along v, across u). `lasting`: both are infinitely sharp.
struct CreaseStrip {
  int k = 0;
  bool lasting = false;
};

// The layout of f when it is such a quad, else empty: both crease edges infinitely sharp and
// its other two edges of sharpness 0 or infinitely sharp between two corners; or a crease edge
// semi-sharp (sharpness >= 1; the strip lasts until it decays), the other two edges of
// sharpness 0 and no corner of the mesh at its corners.
std::optional<CreaseStrip> crease_strip(const Level& L, Index f);

// One dual step of a point (u, v) of strip face f of `parent` (not lasting: it is followed
// until its creases decay, dual_limit.cpp): the child face between the same creases that
// holds it — the F-face over along in [1/4, 3/4], the E-face of the smooth edge at along = 0
// or 1 beyond — with the point in that face's (u, v) and d(u', v')/d(u, v). The child's
// along parameter is the parent's, doubled from the new points (a nested binary split of the
// crease edges, as the half faces beside split them: dual_crease_chart.h); across is kept.
struct StripStep {
  Index face = kNone;
  std::array<double, 2> uv{};
  std::array<std::array<double, 2>, 2> jacobian{};
};
StripStep strip_child(const Level& child, const ChildOrigins& origins, Index f, CreaseStrip strip, double u,
                      double v);

// The limit of the crease through edge (p, q) at u in [0, 1] from p: weights on L's vertices
// with their first and second derivatives in u. Empty where the crease polygon stops at a
// vertex that is not a corner (a dart, refused before).
struct CurveWeight {
  Index vertex = kNone;
  double w = 0, dw = 0, ddw = 0;
};
std::optional<std::vector<CurveWeight>> crease_edge_limit(const Level& L, Index p, Index q, double u);

// The limit of strip face f at its (u, v) as rows over L's vertices: position, d/du, d/dv,
// d2/du2, d2/dudv, d2/dv2 (one-sided at the crease curves' knots). Empty as crease_edge_limit.
using StripRows = std::array<std::vector<double>, 6>;
std::optional<StripRows> crease_strip_limit(const Level& L, Index f, CreaseStrip strip, double u, double v);

}  // namespace subdiv
