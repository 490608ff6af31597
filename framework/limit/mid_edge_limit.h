#pragma once
// The limit surface of a mid-edge scheme (Peters & Reif 1997, "The simplest subdivision
// scheme for smoothing polyhedra") at (face, u, v).
//
// Parameterisation (docs/limit.md, "Mid-edge schemes"): the quad split's (u, v) — a quad's
// unit square, any other face as Bfr's QUAD_SUBFACES — read as the dual schemes' quadrants
// (dual_limit.h). One mid-edge step puts a point at every edge's middle and turns the grid by
// 45 degrees, so a new face straddles old edges and vertices; two steps nest. The second
// step's points are the middles of the first step's edges, one per corner (g, j) of the base
// mesh (the first step's edge between the middles of g's edges j - 1 and j), and the faces
// after two steps are those of one dual step: per face g the n-gon of its corners' points
// (the F-face), per edge a quad (the E-face), per vertex the n-gon around it (the V-face). So
// the point of corner (g, j) is put at the centre of quadrant (g, j), and the four faces
// around it hold its quarters, exactly as a dual step nests (dual_child_point).
//
// Evaluation follows the point's quadrant two steps at a time, through cuts around its face
// refined with the scheme's own rules (the engine; each configuration once, mid_edge_nodes.h),
// until either
// - the point's quadrant lies in a regular grid and two steps of the scheme refine a regular
//   grid as the four-direction quadratic box spline does (Zwart 1973, Powell 1974; checked on
//   the engine's rows, four_direction_patch.h): the box spline's closed form over the quadrant
//   gives the position and first derivatives, and the second derivatives inside its two
//   triangles (none on its knot lines, where it is only C1); or
// - the point is a face's centre, where the
// face's limit mask (the left eigenvector of 1 of its local subdivision matrix; Peters & Reif
// 1997, analysis/surface/limit_evaluation.h) gives the limit. A double is a dyadic rational,
// so the point becomes a quadrant corner after as many double steps as its coordinates have
// bits; after `max_steps` it is taken at the nearest corner (the quadrant is then 2^-max_steps
// of the base face). The derivatives at the centre of a quad come from the face's tangent
// masks (the left eigenvectors of the subdominant eigenvalue), scaled by linear precision as
// at a primal vertex (corner_limit.h): the cut's control points at their own (s, t) have the
// plane as limit, so a mask d gives d.P = (d.S) dP/ds + (d.T) dP/dt. Where the quad's
// neighbourhood is not yet a regular grid (an extraordinary point near), the descent goes on:
// the centre stays the centre of the quad's F-face, whose neighbourhood becomes regular. At the
// centre of a face that is not a quad (an extraordinary point) there are no derivatives.
//
// Holes (tagged faces) remove faces, not rules: the cuts drop the tags, and a point in a hole
// is refused by the limit surface. Refused (mid_edge_limit_unsupported): boundaries — the
// boundary V-face's closing edge joins the middles of two boundary edges, so the boundary
// polygon keeps its edges' length in the parameter, and the faces two steps make next to it
// (a trapezoid per boundary edge, a triangle per boundary vertex) cut the quadrants of the
// base face diagonally instead of nesting in them — and sharp and semi-sharp edges and vertices.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "framework/limit/face_domain.h"
#include "framework/limit/limit_surface.h"
#include "framework/limit/step_matrix.h"

namespace subdiv {

class SchemeLimits;
class MidEdgeNodes;

class MidEdgeLimit {
public:
  // `closed_form` false: descend to a face's centre even where the box spline applies (the
  // tests compare the two).
  MidEdgeLimit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options, SchemeLimits& limits,
               bool closed_form = true);
  ~MidEdgeLimit();

  // The base vertices an evaluation at `p` (from base_face_point) reads, in the order
  // `evaluate` takes their values.
  std::vector<Index> reads(const FacePoint& p) const;

  // Rows of the derivatives over those vertices (for stencils).
  struct Rows {
    std::vector<double> du, dv, duu, duv, dvv;
  };
  LimitSample evaluate(const FacePoint& p, const std::vector<double>& first_values, int channels, int derivatives,
                       Rows* rows_out = nullptr) const;

  int radius() const { return radius_; }
  // Two steps of the scheme refine a regular grid as the four-direction box spline does, and
  // its closed form is used.
  bool closed_form() const { return four_direction_; }

private:
  const Level& base_;
  LimitSurfaceOptions options_;
  int radius_ = 4;
  bool four_direction_ = false;
  std::unique_ptr<MidEdgeNodes> nodes_;  // shared by all evaluations (thread-safe)
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

// Why the mid-edge evaluation cannot take this mesh, or empty.
std::string mid_edge_limit_unsupported(const Level& base);

// The origins of two mid-edge steps written as those of one dual step (for dual_child_point):
// each vertex of level 2 as the corner (g, j) of level 0 it stands for (kind Corner), each
// face of level 2 with the face of level 0 it is the F-face of (parent_face). Vertices near
// the rim of a cut, which stand for no corner, are left with kind Vertex and parent kNone.
ChildOrigins mid_edge_double_origins(const Level& level0, const Level& level1, const ChildOrigins& step1,
                                     const Level& level2, const ChildOrigins& step2);

}  // namespace subdiv
