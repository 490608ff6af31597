#pragma once
// Bicubic Gregory patches that approximate the limit surface, one per quad of the control
// mesh: Loop, Schaefer, Ni & Castaño (2009), "Approximating subdivision surfaces
// with Gregory patches for hardware tessellation", ACM TOG 28(5). A Gregory patch is a
// bicubic Bézier patch whose four interior control points are each a rational blend of two
// "face points", one per edge at that corner, so that the cross-boundary derivative along
// every edge can be chosen on its own: the patches then meet with G1 (one normal field)
// across every edge, which Loop & Schaefer's (2008) geometry patches do not
// (limit/bezier_approximation.h), without separate tangent patches.
//
// Per corner p_0 of valence n_0 (c_0 = cos(2 pi / n_0)), on its edge to p_1 (c_1 likewise):
// - corner point: p_0's limit position (given by the caller: the scheme's exact limit);
// - edge point: e_0 = p_0 + 1 / (n_0 lambda) sum_i cos(2 pi (i - j) / n_0) Ê_i for p_0's j-th
//   edge, Ê_i Loop & Schaefer's (2008) edge point on its i-th edge, lambda Catmull-Clark's
//   subdominant eigenvalue; projected onto the plane of the exact limit normal, so that the
//   corner tangent plane is the limit's;
// - face point: f_0 = (c_1 p_0 + (3 - 2 c_0 - c_1) e_0 + 2 c_0 e_1 + r_0) / 3, e_1 the edge
//   point of p_1 on the same edge, r_0 = (a - a') / 3 + (d - d') / 6 with a, d p_0's other
//   neighbour and the opposite corner in this quad, a', d' those in the quad across the
//   edge (the paper's section 3). The two quads' r cancel, so their cross derivatives sum to
//   (2 c_0 (1 - t) - 2 c_1 t) times the edge's tangent: G1.
// - inside the patch: at corner (0, 0), b_11 = (u f_(v=0) + v f_(u=0)) / (u + v), each face
//   point weighted by the distance to the other edge (likewise at the other corners).
// Where every corner has valence 4 this is the bicubic B-spline patch exactly.
//
// Boundaries and infinitely sharp creases as in the Bézier mode: along a boundary or crease
// edge the cubic B-spline curve's points ((2 v + w) / 3), next to it Loop & Schaefer's
// interior point (no other side to match), and at the other edges of a boundary, crease or
// corner vertex the Bézier mode's limit tangents (Biermann, Levin & Zorin 2000; their
// cosine c = cos(pi / k) for k faces on the side in the face points). So faces whose corners
// are all regular — valence 4 inside, two faces on each side of a boundary or crease, one
// face at a corner — get the exact limit there too, and the patches meet with G1 across
// every edge that is not a crease.
//
// Only for a scheme whose regular quad patch is the bicubic B-spline
// (bezier_approximation_unsupported; with boundaries or creases bezier_features_unsupported).
#include <array>
#include <span>
#include <vector>

#include "framework/limit/bezier_approximation.h"

namespace subdiv {

// One quad's Gregory patch, (u, v) as the limit surface's (corners (0,0), (1,0), (1,1),
// (0,1) at the face's vertices 0..3).
struct GregoryPatch {
  // The 12 boundary control points at j * 4 + i (i along u, j along v, i, j in 0..3); the
  // four interior entries (1,1), (2,1), (2,2), (1,2) are unused.
  std::array<Point3, 16> boundary;
  // Face points per corner k: [2 k] on the edge to corner k + 1, [2 k + 1] on the edge to
  // corner k - 1.
  std::array<Point3, 8> face;
};

// The patches of every face of a quad mesh (one per face, in order), corners at
// `limits.positions`, corner tangents projected onto the planes of `limits.normals` as
// bezier_patches does. Throws subdiv::Error naming the first face or edge the masks do not
// cover, as bezier_patches does (a face that is not a quad, a non-manifold edge, a
// semi-sharp edge or corner, a boundary or crease with one face on a side, a corner inside
// the surface, a boundary when `boundary` is None).
std::vector<GregoryPatch> gregory_patches(const Level& topology, std::span<const double> positions,
                                          BoundaryInterpolation boundary, const VertexLimits& limits);

// Position and first derivatives of the Gregory patch (rational inside, so the derivatives
// include the blends' own); du and dv and geometry_du and geometry_dv are the same.
PatchSample evaluate_gregory(const GregoryPatch& patch, double u, double v);

}  // namespace subdiv
