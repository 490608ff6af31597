#pragma once
// The limit surface of a dual scheme (a split with a new point per face corner: Doo-Sabin,
// its centroid variant, even-degree quad B-splines) at (face, u, v), exactly.
//
// Parameterisation (docs/limit.md, "Dual schemes"): the same (u, v) as the quad split's —
// a quad's unit square, any other face as Bfr's QUAD_SUBFACES — read as quadrants: the
// quarter of face g at corner j (between g[j], the middles of its edges at g[j] and its
// centre) has coordinates (a, b) in [0, 1]^2 with (0, 0) at g[j], (1, 0) at the middle of
// edge j, (1, 1) at the centre; a quad's quadrant j is its quarter at corner j, an n-gon's
// sub-face j is its quadrant j. One dual step puts the new point c of corner (g, j) at the
// quadrant's centre (1/2, 1/2), and the four new faces around c (g's F-face, the E-faces
// of edges j and j - 1, the V-face of g[j]) have their own quadrants at c exactly on the
// four quarters of (g, j), each with its centre at the corner of (g, j) its face comes
// from. Quadrants therefore nest as a binary quad split does, and on a regular grid (the
// biquadratic B-spline) each control point sits at its Greville point, so the scheme has
// linear precision in these coordinates.
//
// Next to boundaries and sharp creases a face with corners on the crease is covered by the
// quadrants of its other corners, which reach to the crease (dual_crease_chart.h); the
// nesting is the same. Where a semi-sharp crease has decayed, such a face is read in its own
// quadrants again (follow_decay). A quad between two creases on opposite sides is refined
// along them only (dual_crease_strip.h): between infinitely sharp creases its limit is the
// ruled surface between the two crease curves, in closed form; between semi-sharp ones the
// point is followed along (strip_child) until they decay, then read in its face's quadrants.
//
// Evaluation follows the point's quadrant down the refinement of its neighbourhood (the
// engine refines a cut around the face, as for primal schemes) until either
// - the 3 x 3 points around the quadrant's corner are regular and untagged and the scheme
//   refines regular quads as the biquadratic B-spline does (checked on its rows): the
//   closed form over the quadrant (biquadratic_patch.h), with derivatives; or
// - the point is on the crease side of a quadrant of a face with corners on an infinitely
//   sharp crease: the crease curve's closed form where the crease is Chaikin's
//   (crease_side_limit), else at (1, 1) the middle of the face's crease run, whose limit is
//   the crease curve's there; or
// - the point is the centre of a face: the limit mask of that face (the left eigenvector
//   of 1 of its local subdivision matrix; analysis/surface/limit_evaluation.h, Doo & Sabin
//   1978; Peters & Reif 1998, "Analysis of algorithms generalizing B-spline
//   subdivision"). Derivatives do not exist there when the face is not a quad
//   (the extraordinary point), and are not computed for schemes without the closed form.
// A double is a dyadic rational, so the point is a quadrant corner after as many steps as
// its coordinates have bits; after `max_steps` it is taken at the nearest corner (the
// quadrant is then 2^-max_steps of the base face).
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "framework/limit/face_domain.h"
#include "framework/limit/limit_surface.h"

namespace subdiv {

class SchemeLimits;
class WeightTableCache;

class DualLimit {
public:
  // `radius`: face rings of the cut around the current face (the rules' reach and the face
  // masks' labelling fit inside).
  DualLimit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options, int radius,
            SchemeLimits& limits);
  ~DualLimit();

  // The base vertices an evaluation at `p` (from base_face_point) reads, in the order
  // `evaluate` takes their values.
  std::vector<Index> reads(const FacePoint& p) const;

  // Rows of the derivatives over those vertices (for stencils).
  struct Rows {
    std::vector<double> du, dv, duu, duv, dvv;
  };
  LimitSample evaluate(const FacePoint& p, const std::vector<double>& first_values, int channels, int derivatives,
                       Rows* rows_out = nullptr) const;

  bool closed_form() const { return biquadratic_; }

private:
  // Throws why base face f is not evaluated (a corner at a vertex faces_refused_at names,
  // dual_crease_chart.h), if it is not.
  void check_face(Index f) const;

  const Scheme& scheme_;
  const Level& base_;
  LimitSurfaceOptions options_;
  int radius_;
  SchemeLimits& limits_;
  std::unique_ptr<WeightTableCache> tables_;  // cut_weight_tables.h
  bool biquadratic_ = false;
  bool chaikin_crease_ = false;  // the crease is Chaikin's: its closed form applies on it
  bool middles_kept_ = true;     // the crease keeps its edges' middles (else dual_crease_curve.h)
  std::vector<Index> refused_at_;  // per base face: the vertex that keeps it from evaluation, or kNone
};

// A point of a face (face_domain.h: a quad's (u, v), or an n-gon's sub-face) after one dual
// step: the face of `child` whose quadrant holds it, with that face's own coordinates (a
// quad's (u, v), else its sub-face) and the true d(st)/d(u, v) — for sequences whose head
// has a dual split (sequence_head.h). Empty for a point of a triangle's own (u, v).
std::optional<FacePoint> dual_child_point(const Level& parent, const Level& child, const ChildOrigins& origins,
                                          const FacePoint& p);

// Why the dual evaluation cannot take this mesh, or empty (holes, and the boundaries and
// creases dual_crease_chart.h does not cover yet). Faces with a corner at a vertex
// faces_refused_at names are refused one by one, when evaluated.
std::string dual_limit_unsupported(const Level& base);
// The same for a dual split in a sequence's head (dual_child_point), which follows closed
// untagged meshes only, and every face there (so also no such vertex anywhere).
std::string dual_head_unsupported(const Level& base);

}  // namespace subdiv
