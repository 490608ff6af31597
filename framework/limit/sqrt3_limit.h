#pragma once
// The limit surface of a √3 scheme (Kobbelt 2000, "√3-subdivision"; Labsik & Greiner 2000,
// "Interpolatory √3-subdivision") at (face, u, v).
//
// Parameterisation (docs/limit.md, "√3 schemes"): Bfr's triangle, corners (0,0), (1,0), (0,1),
// read in barycentric coordinates b = (1 - u - v, u, v). One √3 step puts a point at every
// triangle's centroid and flips the old edges, so a child triangle straddles an old edge and
// one step does not nest. Two steps do: they are a 1-to-9 triadic split of every triangle
// (Kobbelt 2000, section 2: "applying the √3 operator twice ... a tri-section of every
// original edge"). The vertices after two steps are the old vertices, the old faces' points
// (at the centroid, b = (1/3, 1/3, 1/3)) and the points of the level-1 faces, one over each
// third of an old edge (the centroid of (a, P(f0), P(f1)) is (2a + b) / 3 when the grid is
// unfolded affinely across the edge). They are the lattice points 3b in Z^3, and the nine
// triangles between them (six like the parent, three turned by 180 degrees) each lie in one
// old triangle. The child's own (s, t) are its barycentric coordinates from its corner 0,
// as the level's face lists it.
//
// Evaluation follows the point down two steps at a time, through cuts around its triangle
// refined with the scheme's own rules (the engine; each configuration once, sqrt3_nodes.h), to
// the triangle of level 2k that holds it. A double is
// not a ternary rational, so the point never becomes a vertex (except the base corners and
// points on their edges' lattice lines that are exact): after 34 double steps the triangle
// is 3^-34 < 2^-53 of the base triangle, and the point is taken at its nearest corner, whose
// limit mask (the left eigenvector of 1 of its local subdivision matrix) gives the position
// and whose tangent masks give the derivatives (analysis/surface/limit_evaluation.h,
// corner_limit.h); its second-derivative masks (left eigenvectors of 1/9, normalised by
// quadratic generation) give the second derivatives where the scheme is C2 there (Kobbelt's
// sqrt3 at a regular interior vertex; not the interpolating scheme, whose eigenvalue 0.180 >
// 1/9 makes the curvature unbounded), after kSecondOrderSteps double steps. The error is
// at most the triangle's size times the first derivative for positions and times the second
// for the derivatives: round-off. Next to an extraordinary
// vertex the derivatives change on the scale of the distance to it, so the descent goes on
// 34 double steps past the last triangle that touches the extraordinary vertex (a run of the
// same neighbourhood and child is taken at once with the step's matrix powers,
// sqrt3_nodes.h); a point exactly at a vertex stops there (no derivatives at an
// extraordinary one).
//
// Boundaries (Kobbelt 2000, section 5): the first step keeps a boundary triangle's (a, b,
// face point), the second trisects the boundary edge and flips the triangle's other edges to
// the trisection points, so two steps are the same triadic split with the trisection points
// at (2a + b)/3 and (a + 2b)/3 (sqrt3_nodes.cpp), and a boundary vertex's limit is its limit
// mask from the boundary configuration's subdivision matrix (the analysis). No derivatives
// on the boundary itself (its vertices included): across it they do not exist in this
// parameterisation (the rows next to the boundary shrink by about 0.37 per double step
// against the parameter's 1/3, and at a boundary vertex the directional derivatives are not
// linear; measured, docs/limit.md). Near it the tangent masks are scaled by linear precision,
// which the boundary rules lack within two rings of the boundary (the first step's face point
// of a boundary triangle has 5 neighbours and the vertex rule moves it off its parameter),
// so a point off the boundary descends until its vertex is 4 rings from it. Holes remove
// faces, not rules: the cuts drop the tags.
//
// Sharp edges are kept and trisected like a boundary (refine/sqrt3_split.cpp), so creases
// take the same road, the cuts keeping their sharpness; no derivatives on a crease. An edge
// whose sharpness ends between the two steps of a pair (s mod 2 in (0, 1]) is kept in the
// first step and flipped in the second, so the triangle kept beside it gets its face point at
// (4a + 4b + c)/9, off the triadic lattice: such a mesh is not evaluated here but as the
// sequence of the scheme's first steps, followed one at a time (sqrt3_single_step_levels),
// and the scheme over the mesh they make (limit_surface.cpp).
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "framework/limit/face_domain.h"
#include "framework/limit/limit_surface.h"
#include "framework/limit/step_matrix.h"

namespace subdiv {

class SchemeLimits;
class Sqrt3Nodes;

class Sqrt3Limit {
public:
  Sqrt3Limit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options, SchemeLimits& limits);
  ~Sqrt3Limit();

  // The base vertices an evaluation at `p` (from base_face_point) reads, in the order
  // `evaluate` takes their values.
  std::vector<Index> reads(const FacePoint& p) const;

  // Rows of the derivatives over those vertices (for stencils).
  struct Rows {
    std::vector<double> du, dv, duu, duv, dvv;
  };
  LimitSample evaluate(const FacePoint& p, const std::vector<double>& first_values, int channels, int derivatives,
                       Rows* rows_out = nullptr) const;

  // Face rings of the cut around the current face.
  int radius() const { return radius_; }

  // Double steps after which the triangle holding a point is below round-off (3^-34 < 2^-53).
  static constexpr int kRoundOffSteps = 34;
  // The same for second derivatives, which are only Hölder continuous: the nearest vertex's are
  // off by about (3^-k)^alpha, alpha = 0.907 for Kobbelt's sqrt3 at a regular vertex (the next
  // eigenvalue after 1/9 is 0.0410 = 3^-2.907; measured between vertices, 0.8 to 1.2, by
  // central differences, docs/limit.md), so 43 double steps: 3^(-0.8 * 43) < 2^-53.
  static constexpr int kSecondOrderSteps = 43;

private:
  const Scheme& scheme_;
  const Level& base_;
  int radius_ = 5;
  std::unique_ptr<Sqrt3Nodes> nodes_;  // shared by all evaluations (thread-safe)
  // Per base face (made on first use): the node of its cut and the base vertices in the node's
  // label order, which is the order reads() gives and evaluate() takes.
  struct Entry {
    int node = -1;
    std::vector<Index> vertices;
  };
  const Entry& entry(Index face) const;
  mutable std::mutex entry_mutex_;
  mutable std::vector<std::unique_ptr<Entry>> entries_;
};

// How many steps (an even number, so that the pairs after them keep Kobbelt's boundary
// alternation) must be followed one at a time before every pair is the triadic split: enough
// for each edge whose sharpness ends between the two steps of a pair to have decayed; 0 when
// there is none.
int sqrt3_single_step_levels(const Level& base);

}  // namespace subdiv
