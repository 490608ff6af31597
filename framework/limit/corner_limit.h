#pragma once
// The limit at a vertex of some level, and the derivatives of the surface there along a
// face's parameter directions.
//
// The position is the vertex's limit mask (the left eigenvector of 1 of its local
// subdivision matrix; analysis/surface/limit_evaluation.h). The tangent masks towards the
// vertex's ring neighbours (left eigenvectors of the subdominant eigenvalue) give
// derivatives only up to a factor each; the factors follow from linear precision: where the
// parameterisation is regular, control points placed at their own (s, t) coordinates
// (the face's grid unfolded across its neighbours) have the plane (s, t) as their limit, so
// a tangent mask d gives d . P = (d . S) dP/ds + (d . T) dP/dt, two equations per mask for
// the two unknown derivatives (Stam 1998, section 4, for Catmull-Clark's regular patches).
#include <span>
#include <string>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/limit/face_domain.h"
#include "framework/limit/limit_surface.h"

namespace subdiv {

// The parameter-space coordinates of the level's vertices with `face` at its own frame (a
// quad's corners (0,0), (1,0), (1,1), (0,1), a triangle's (0,0), (1,0), (0,1)), the grid
// continued across edges through faces of the same shape; NaN for a vertex reached by two
// paths that disagree (an irregular vertex in between) or not reached.
std::vector<Uv> unfold(const Level& level, Index face, bool triangles);

// The limit at a corner as rows over the level's vertices: the position, and d/ds, d/dt in
// the face's own coordinates (empty where the vertex is not regular).
struct CornerRows {
  std::vector<double> position, ds, dt;  // one weight per vertex of the level
  // Second derivatives d2/ds2, d2/dsdt, d2/dt2: from the polynomial patches (bspline_patch.h,
  // triangle_patch.h), or at a vertex with `second` (below); else empty.
  std::vector<double> dss, dst, dtt;
  // Why a regular vertex has no derivatives, where the scheme is at fault (not C1 there):
  // the eigenvalues against the scale. Asking for derivatives there is refused.
  std::string no_derivatives;
};

// Why a vertex has no limit mask: the analysis's verdict for its configuration (LimitMask).
struct NoLimitMask {
  std::string verdict;  // empty: no analysis has failed (the neighbourhood was not yet analysable)
  std::string failure;  // the scheme fails a condition there (Verdict::Fails): which; else empty
};

// The refusal for a point whose descent found no limit mask after `steps` steps: where the
// scheme fails (its local subdivision matrix lacks the simple dominant eigenvalue 1, or
// another condition), its rules, not the mesh, must change, and the message says so.
std::string no_limit_mask(const Scheme& scheme, int steps, const NoLimitMask& why);

// A scheme whose regular vertices' eigenvalues do not match the parameterisation
// (CornerRows::no_derivatives says how): "scheme S is not C1, so its limit has no derivatives
// or normals: <why>; check its rules with `subdiv analyze S`". The callers add what to do instead.
std::string not_c1(const Scheme& scheme, const std::string& why);
// not_c1 with the way to evaluate positions only, for the evaluation's refusal of derivatives.
std::string not_c1_derivatives(const Scheme& scheme, const std::string& why);

// The rows at the face's corner `corner`. False when the vertex's neighbourhood is not yet one the masks
// describe (a semi-sharp feature, another irregular vertex nearby): refine and try again.
// `mask_error` receives the analysis's verdict when it has no mask for the configuration.
// `scale`: the parameterisation's contraction per step of the analysis (1/2 for binary
// splits), which a regular vertex's subdominant eigenvalues must equal for the limit to be
// differentiable there; 0 leaves it unchecked.
// With `second`, also the second derivatives at a regular interior vertex whose analysis has
// second-derivative masks (LimitMask::quadratic), each a combination of d2/ds2, d2/dsdt,
// d2/dt2 whose factors follow from quadratic generation as the tangents' do from linear
// precision: control points at the values of a quadratic q(s, t) at their unfolded (s, t)
// have q plus an affine function as their limit, which the masks do not see, so a mask m
// gives m . P = (m . S²/2) P_ss + (m . S T) P_st + (m . T²/2) P_tt. Only for a scheme that
// generates quadratics there (checked by the callers' tests against central differences).
bool corner_rows(SchemeLimits& limits, const Level& level, const FacePoint& point, int corner, int step,
                 bool triangles, CornerRows& rows, NoLimitMask& mask_error, double scale = 0, bool second = false);

}  // namespace subdiv
