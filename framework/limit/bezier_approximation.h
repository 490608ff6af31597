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
// scheme's own limit, bezier_approximation_unsupported) and a closed manifold mesh of
// quads without creases (the masks are those of interior smooth vertices).
#include <array>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

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

// The limit positions (xyz each) at points (faces[i], uv[2i], uv[2i + 1]): the corner points.
using CornerLimits =
    std::function<std::vector<double>(const std::vector<Index>& faces, const std::vector<double>& uv)>;

// The patches of every face of `topology` (one per face, in order). Each vertex's limit is
// asked for once, at one face's corner, so that all its patches share the corner point.
// Throws subdiv::Error naming the first face the masks do not cover (a face that is not a
// quad, a boundary or non-manifold edge), before asking for any limit.
std::vector<BezierPatch> bezier_patches(const Level& topology, std::span<const double> positions,
                                        const CornerLimits& corner_limits);

PatchSample evaluate_patch(const BezierPatch& patch, double u, double v);

}  // namespace subdiv
