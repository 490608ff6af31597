#pragma once
// Bicubic Bézier patches that approximate the limit surface, one per quad of the control
// mesh, from masks of the control mesh alone: Loop & Schaefer (2008), "Approximating
// Catmull-Clark subdivision surfaces with bicubic patches", ACM TOG 27(1). Where every
// vertex of a quad has valence 4 the patch is the quad's bicubic B-spline patch exactly
// (its Bézier form); elsewhere it approximates. The geometry patches meet with C0 only;
// a separate pair of tangent patches per quad (degree 2 x 3 and 3 x 2) gives a normal
// field that is continuous across every edge (docs/limit.md has the masks).
//
// The masks are those of the paper (docs/limit.md derives them from the B-spline case):
// - interior point next to corner v of valence n: (n v + 2 e_a + 2 e_b + d) / (n + 5), e_a
//   and e_b v's neighbours in the quad, d the opposite corner;
// - edge point next to v on the edge v-w: the average of the interior points next to v in
//   the two quads of the edge, i.e. (2n v + 4 w + 2 e + 2 e' + d + d') / (2n + 10);
// - corner point: v's limit position (given by the caller: the scheme's exact limit);
// - tangent patches: the geometry patch's derivatives, except the corner derivatives (the
//   limit tangent masks of Catmull-Clark's subdominant eigenvectors along each edge) and the
//   two cross-boundary points next to each edge, chosen so that the two quads' cross
//   derivatives sum to lambda(t) times the edge's tangent, lambda linear from
//   2 cos(2 pi / n_A) to -2 cos(2 pi / n_B) (the paper's section 4).
//
// Only for a scheme whose regular quad patch is the bicubic B-spline (checked on the
// scheme's own limit, bezier_approximation_unsupported) and a manifold mesh of quads.
// Boundaries and infinitely sharp creases (limit/bezier_sectors.h) where the scheme's limit
// next to them is the B-spline patch with phantom points (bezier_features_unsupported):
// - edge point on a boundary or crease edge v-w: (2 v + w) / 3, the cubic B-spline curve's;
// - interior point next to v: as above with n twice the faces of v's sector (4 at a regular
//   boundary), or 2 pi k / alpha at a corner of k faces whose sector spans alpha = pi / 2
//   (convex) or 3 pi / 2 (concave) in the parameter plane (4 at a corner of one face);
// - corner derivatives: the feature curve's tangent and the cross tangent of Biermann,
//   Levin & Zorin (2000), combined along each edge of the sector; at a corner the two
//   curves' tangents, blended along the inner edges as at a corner of angle alpha.
// So faces whose corners are all regular — valence 4 inside, two faces on each side of a
// boundary or crease, one face at a corner — get the exact limit there too.
#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/topology/level.h"

namespace subdiv {

struct Scheme;

using Point3 = std::array<double, 3>;

// One quad's patches, (u, v) as the limit surface's (corners (0,0), (1,0), (1,1), (0,1) at
// the face's vertices 0..3). Control point (i, j) (i along u, j along v) at index:
struct BezierPatch {
  std::array<Point3, 16> geometry;  // j * 4 + i, i, j in 0..3
  std::array<Point3, 12> tangent_u;  // j * 3 + i, i in 0..2, j in 0..3: d/du
  std::array<Point3, 12> tangent_v;  // j * 4 + i, i in 0..3, j in 0..2: d/dv
};

struct PatchSample {
  Point3 position, du, dv;           // du, dv: the tangent patches
  Point3 geometry_du, geometry_dv;   // the geometry patch's own derivatives
};

// Why the approximation cannot be built for `scheme`, or empty: it must evaluate on quads
// (limit_surface.h) with the bicubic B-spline as its limit over regular quads, which is
// checked on the scheme's own exact limit (a regular torus with generic values).
std::string bezier_approximation_unsupported(const std::shared_ptr<const Scheme>& scheme);

// Why the boundary and crease masks do not fit `scheme`, or empty: its limit next to a
// boundary (corners kept) and an infinitely sharp crease must be the bicubic B-spline patch
// with phantom points 2 p_0 - p_1 across them, checked on the scheme's own exact limit.
std::string bezier_features_unsupported(const std::shared_ptr<const Scheme>& scheme, const FeatureOptions& features);

// The scheme's limit at each vertex of the control mesh (analysis/surface/limit_evaluation.h):
// positions (the corner points) and unit normals, xyz per vertex. A normal of zero length
// (none found) leaves that vertex's tangent masks as they are.
struct VertexLimits {
  std::vector<double> positions, normals;
};

// The patches of every face of `topology` (one per face, in order). Where a vertex's
// sectors share one tangent plane (inside the surface, on a boundary) the corner
// derivatives are projected onto the plane of its limit normal, so that the tangent patches'
// normal there is the scheme's own even where the masks are Catmull-Clark's approximations
// (another scheme; a boundary vertex with three or more faces).
// Throws subdiv::Error naming the first face or edge the masks do not cover (a face that is
// not a quad, a non-manifold edge, a semi-sharp edge or corner, a boundary or crease with one
// face on a side, a corner inside the surface, a boundary when `boundary` is None). A dart takes the smooth vertex's masks, as the scheme's dart rule does.
std::vector<BezierPatch> bezier_patches(const Level& topology, std::span<const double> positions,
                                        BoundaryInterpolation boundary, const VertexLimits& limits);

PatchSample evaluate_patch(const BezierPatch& patch, double u, double v);

}  // namespace subdiv
