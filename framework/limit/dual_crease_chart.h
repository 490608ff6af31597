#pragma once
// Faces next to boundaries and sharp creases under a dual split, and the quadrants they are
// parameterised by (docs/limit.md, "Dual schemes at boundaries and creases").
//
// A corner of a face is a *crease corner* when one of its two face edges is sharp for the
// dual split (features/dual_features.h: a boundary edge, or sharpness >= 1) or its vertex
// collapses (a corner): its new point lies on the crease (or is the corner itself). A face
// with crease corners is a *half face*: across the crease the scheme contracts by 3/4 per
// step, not 1/2 (docs/analysis.md, "Dual schemes at boundaries and creases"), so the
// quadrants of a closed face, nested as a binary split, would leave the quadrants at crease
// corners unrefined across (the "outer half" of a boundary face never reached). Instead the
// crease corners own no quadrant: the face is covered by the quadrants of its other corners,
// each reaching to the crease, as if the face were the half of a face mirrored across the
// crease. The quadrant of corner i has (0, 0) at corner i, (1, 0) at the middle of edge i or,
// when corner i + 1 is a crease corner, at that corner; (0, 1) likewise towards corner i - 1;
// and (1, 1) at the middle of the crease run (the middle of the crease edge, or the corner
// the run turns at). One dual step puts the new point of corner i at (1/2, 1/2), as for a
// closed face, and the four faces around it (all four exist: it is a smooth point) hold its
// quarters, so quadrants nest as a binary quad split does.
//
// Supported (dual_crease_unsupported says why not): boundary and crease vertices with two
// faces on each side of the crease (a regular boundary or crease; faces at other crease
// vertices are refused one by one, faces_refused_at), corners (a boundary
// vertex of one face, or a vertex whose edges are all sharp and decay together), crease edges
// infinitely sharp or of one sharpness along a crease;
// half faces of the base mesh are quads. These stay so at every level: the new faces next to
// the crease are the F-faces of half faces and the E-faces across crease vertices, quads
// with one crease edge, or a crease run through a corner.
#include <optional>
#include <utility>
#include <vector>
#include <string>

#include "framework/features/feature_options.h"
#include "framework/limit/face_domain.h"
#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

struct Scheme;

// The crease corners of face f form one cyclic run: corners first, first + 1, ...,
// first + length - 1 (mod the face size). length 0: no crease corner (a closed face).
struct CreaseRun {
  int first = 0;
  int length = 0;
};

// The run of f's crease corners; empty when they are not one run (a face between two creases).
std::optional<CreaseRun> crease_run(const Level& L, Index f);

bool is_crease_corner(const Level& L, Index f, int corner);

// A boundary edge, or one of sharpness >= 10: sharp at every level.
bool edge_infinitely_sharp(const Level& L, Index e);

// The other end of x's sharp edge (for the dual split) that does not lead to `not_to`, or kNone.
Index other_crease_neighbour(const Level& L, Index x, Index not_to);

// The run of the corners of `face` (of the child level of a dual step) that the step made on
// a crease (a crease corner's point: on a sharp edge, or a corner's point): the run the face's
// quadrants were laid out by. A semi-sharp crease that decays leaves it non-empty while the
// face's own run (crease_run) is empty: the face is then read in a closed face's quadrants.
std::optional<CreaseRun> made_on_crease_run(const Level& parent, const Level& child, const ChildOrigins& origins,
                                            Index face);

// The quadrant of a non-crease corner of a half quad in the quad's (u, v): (u, v) = origin +
// a (to_a) + b (to_b).
struct QuadrantChart {
  Uv origin{}, to_a{}, to_b{};
};
QuadrantChart half_quad_quadrant(CreaseRun run, int corner);

// The crease run's middle as weights on f's corners (its middle corner, or the two middle
// corners' mean): the limit at (1, 1) of every quadrant of a half face whose crease is
// infinitely sharp (the crease curve at a knot, Chaikin 1974: the mean of the two control
// points; a corner stays).
std::vector<std::pair<int, double>> crease_run_middle(CreaseRun run, int face_size);

// The limit on the crease side of the quadrant of off-crease corner `corner` of half quad f:
// the side from the crease corner X next to it (corner + 1 when `towards_next`, else
// corner - 1) to the quadrant's (1, 1), at s in [0, 1] from X, as weights on L's vertices.
// The crease is Chaikin's curve, the uniform quadratic B-spline with control points at their
// Greville abscissae (X at 0, the next crease vertex at 1), clamped at a corner of the mesh
// (knots 0, 0, 0, 1, 2, ...: the corner at 0, its neighbour at 1/2; Chaikin 1974, Boehm 1980;
// between two corners with one vertex between them, 0, 0, 0, 1, 1, 1: a quadratic Bezier curve),
// so the point is t = s/2 from X towards the run's other end, or (1 - s)/2 from the corner a
// run turns at. Empty when X is not a crease corner. The run must be infinitely sharp and the
// scheme's crease Chaikin's (crease_middles_kept).
std::vector<std::pair<Index, double>> crease_side_limit(const Level& L, Index f, CreaseRun run, int corner,
                                                        bool towards_next, double s);

// Whether every edge of the run is infinitely sharp (a boundary, or sharpness >= 10).
bool crease_run_infinitely_sharp(const Level& L, Index f, CreaseRun run);

// Empty when the scheme's crease keeps what the quadrants' (1, 1) rest on, checked on the
// engine's rows for an open grid (as biquadratic_patch.h checks the regular rule): every child
// boundary edge along a parent boundary edge (p, q) between non-corners has its middle at
// (p + q)/2 (Chaikin's cuts are symmetric about the middle), and a corner's point is the
// corner. Otherwise why not (even-degree quad B-splines of d >= 4, whose smoothing passes
// move the crease points).
// With `chaikin`, also whether every boundary point is Chaikin's cut (3/4, 1/4; the middle of
// an edge at a corner), which crease_side_limit's closed form assumes.
// With `middles`, a crease that does not keep its middles is no error: *middles says so.
std::string crease_middles_kept(const Scheme& scheme, const FeatureOptions& features, bool* chaikin = nullptr,
                                bool* middles = nullptr);

// Why boundaries and creases of `base` cannot be evaluated under a dual scheme, or empty.
// Vertices with other than two faces on a side of their crease are not among them: they
// refuse only the faces around them (faces_refused_at).
std::string dual_crease_unsupported(const Level& base);

// Where the faces with a corner at v are not evaluated, what v is and why (both empty where
// they are; docs/limit.md, "Dual schemes at boundaries, creases and corners"): a boundary or
// crease vertex with other than two faces on a side of its crease (a boundary vertex of 3 or
// more faces; a crease vertex of 1 or 3 or more faces on a side), and a corner whose ring of
// faces grows (an edge there that is smooth, or becomes smooth while the vertex stays a corner)
// or that decays into such a crease vertex; an interior vertex of valence 2 (its V-face would
// have two sides). The faces without such a corner never reach the
// structure it makes: it lives on the descendants of the vertex's own corner points, inside
// the quadrants of its faces.
struct VertexRefusal {
  std::string what, why;
};
VertexRefusal faces_refused_at(const Level& L, Index v);

}  // namespace subdiv
