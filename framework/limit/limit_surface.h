#pragma once
// The limit surface of a linear scheme at any (face, u, v): position, first and second
// derivatives, exact to round-off, and the same as weights over the control points (a limit stencil).
//
// Method (docs/limit.md): the point is followed down the refinement of its own
// neighbourhood. At every step the face's neighbourhood is cut out of the current level
// (analysis/surface/local_patch.h), refined one step by the scheme's own rules (the engine),
// and the child face holding the point is found (face_domain.h). Machine numbers are dyadic
// rationals, so with a binary split the point becomes a vertex of some level after as many
// steps as its coordinates have bits (Schaefer & Warren 2007, "Exact evaluation of
// non-polynomial subdivision schemes at rational parameter values"): there its limit is
// the vertex's limit mask applied to the level's points, and its derivatives the
// vertex's tangent masks (the left eigenvectors of the local subdivision matrix, Stam 1998,
// "Exact evaluation of Catmull-Clark subdivision surfaces at arbitrary parameter values";
// analysis/surface/limit_evaluation.h) scaled to the parameterisation. Near an extraordinary
// vertex the point approaches (or wherever a step leads back to the same neighbourhood), the
// levels are skipped together with powers of the local subdivision matrix (limit_nodes.h),
// so a point at u = 1e-300 costs about what one at u = 0.3 does. Where every step ahead is
// the bicubic B-spline's (checked on the scheme's rows, limit_nodes.h), the face is that
// patch and is evaluated in closed form at once; likewise a triangle whose exact rows are a
// quartic satisfying its refinement equations (triangle_patch.h: Loop's regular triangles). Semi-sharp creases are refined until they
// are smooth or sharp, like everything else.
//
// Supported: stationary linear schemes whose split is the binary quad or triangle split
// (Catmull-Clark, Loop, the butterflies, bilinear, composite split + averaging schemes), and
// the dual split (Doo-Sabin, even-degree quad B-splines; dual_limit.h, in the quad split's
// parameterisation read as nested quadrants), with regular boundaries, infinitely sharp creases
// and corners (dual_crease_chart.h says which); the √3 split on closed untagged meshes
// (sqrt3_limit.h: two steps are a triadic split of each base triangle); the mid-edge split
// there (mid_edge_limit.h: two steps are a dual step of the halved grid; on a regular grid
// the four-direction box spline's, evaluated in closed form); and plugins' splits
// that scale each face into m x m affine copies (plugin_split_limit.h). Refused with the
// reason: non-linear rules (no limit stencil exists), level-dependent weights (no fixed local
// subdivision matrix).
#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/topology/level.h"

namespace subdiv {

struct Scheme;
struct FacePoint;

struct LimitSurfaceOptions {
  FeatureOptions features;  // boundary interpolation and crease method, as in OpenSubdiv
  // Steps after which a point that is still not a vertex is taken at the nearest corner
  // of its face (whose size is then at most 2^-max_steps of the base face's: below
  // round-off).
  int max_steps = 64;
  // Faces in an untagged regular quad grid (quad_grid_labelled, local_patch.h) share one
  // node, found without cutting and signing each face's neighbourhood, and points in a face
  // whose limit is a bicubic patch are evaluated without the nodes' lock; any other face whose
  // cut's key (limit/cut_key.h) was met already takes that cut's node without cutting; a
  // face with sub-faces (an n-gon under a quad split) refines its cut once for all its points,
  // not once per point. False sends every face and point the general way (the tests compare
  // the two: the same bits).
  bool shortcuts = true;
};

// One evaluated point: `channels` values each for the position and its derivatives along
// the base face's u and v. Derivatives are absent (has_derivatives false) exactly at an
// extraordinary vertex, where the parameterisation is singular. Second derivatives
// (d2/du2, d2/dudv, d2/dv2) are present where the point lies in a face over which the
// limit is a polynomial patch (the scheme is C2 there: a bicubic B-spline or other tensor
// patch of degree <= 4 per direction, a quartic triangle patch) — every point of a
// Catmull-Clark or Loop surface but an extraordinary vertex itself, a dart or a point on a
// semi-sharp crease before its sharpness decays; at such vertices the curvature is unbounded
// or depends on the direction (docs/limit.md), and has_second_derivatives is false. A
// mid-edge surface has them inside the pieces of its four-direction box spline and none on
// that spline's knot lines, where it is only C1 (mid_edge_limit.h).
struct LimitSample {
  std::vector<double> position, du, dv;
  std::vector<double> duu, duv, dvv;
  bool has_derivatives = false;
  bool has_second_derivatives = false;
  int steps = 0;  // steps the evaluation took (a run of self-similar levels taken at once counts once)
};

// A limit stencil: position and derivatives as weights over the base mesh's vertices.
struct LimitStencil {
  std::vector<Index> vertices;
  std::vector<double> position, du, dv, duu, duv, dvv;  // one weight per entry of `vertices`
  bool has_derivatives = false;
  bool has_second_derivatives = false;
};

// A run of a sequence's head (sequence_head.h): a scheme for a number of levels.
struct LimitHeadRun {
  std::shared_ptr<const Scheme> scheme;
  int levels = 0;
};

class LimitSurface {
public:
  // Checks that the scheme can be evaluated and keeps the base level (with its tags).
  // Throws subdiv::Error saying why a scheme is refused.
  LimitSurface(std::shared_ptr<const Scheme> scheme, Level base, const LimitSurfaceOptions& options = {});
  // The limit of a sequence ("A:1,B:3"): `head` refines the base first, then `tail` repeats.
  // Points and stencils are still in the base faces' (u, v) and over the base vertices; the
  // head's splits must be followed (binary quad, triangle, dual, sqrt3, mid-edge in pairs, plugins' splits a period at a time:
  // sequence_head.h), its rules be linear (they may depend on the level), and the tail be a
  // scheme the first constructor takes.
  LimitSurface(std::vector<LimitHeadRun> head, std::shared_ptr<const Scheme> tail, Level base,
               const LimitSurfaceOptions& options = {});
  ~LimitSurface();
  LimitSurface(LimitSurface&&) noexcept;
  LimitSurface& operator=(LimitSurface&&) noexcept;

  const Level& base() const;
  const LimitSurfaceOptions& options() const;
  // True when the scheme's split makes triangles (faces are parameterised as triangles).
  bool triangles() const;

  // The limit of `values` (channels per base vertex) at (face, u, v) in Bfr's
  // parameterisation (face_domain.h). Throws subdiv::Error for a face that does not exist,
  // a hole, or (u, v) outside the face's domain, and where the point's neighbourhood is one
  // the evaluation refuses (the message names the face and (u, v)). Thread-safe. `derivatives` is the highest
  // order computed: 0 the position only (about half the work), 1 also du and dv, 2 also the
  // second derivatives where they exist.
  LimitSample evaluate(Index face, double u, double v, std::span<const double> values, int channels,
                       int derivatives = 1) const;
  // evaluate() into a sample the caller owns, the same bits: its vectors are cleared and
  // refilled, keeping their memory, so that a loop over many points (one sample per thread)
  // allocates nothing where the face has a closed form. Every field is set as evaluate()
  // sets it (the ones not computed empty or false). On an exception `out` is unspecified.
  void evaluate_into(Index face, double u, double v, std::span<const double> values, int channels, int derivatives,
                     LimitSample& out) const;

  // The same point as weights over the base vertices: evaluate() of any values equals
  // these weights applied to them (to round-off).
  LimitStencil stencil(Index face, double u, double v, int derivatives = 1) const;

  // Why a (face, u, v) would be refused, or empty.
  std::string check(Index face, double u, double v) const;

private:
  void evaluate_at(const FacePoint& p, std::span<const double> values, int channels, int derivatives,
                   LimitSample& out) const;
  LimitStencil sequence_stencil(Index face, double u, double v, int derivatives) const;
  void evaluate_unnamed(Index face, double u, double v, std::span<const double> values, int channels,
                        int derivatives, LimitSample& out) const;
  LimitStencil stencil_unnamed(Index face, double u, double v, int derivatives) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Why a scheme cannot be evaluated on its limit surface, or empty.
std::string limit_surface_unsupported(const Scheme& scheme);

}  // namespace subdiv
