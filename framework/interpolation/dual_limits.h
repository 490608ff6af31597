#pragma once
// Limit points of control vertices under dual schemes (Doo-Sabin, its centroid variant,
// mid-edge). A dual step makes no vertex points, but it makes a V-face around every
// vertex v. When the scheme's face rules keep each face's centroid (Doo & Sabin 1978: Doo-Sabin
// interpolates the centroid of every face: the child F-face of a face has the same
// centroid and the nested F-faces shrink to one limit point), the limit point of v's V-face
// is its centroid, which is the point of the limit surface that belongs to v:
//
//   l(v) = (1/m) sum over the m corners of v's V-face of that corner's stencil row.
//
// The masks are read from the scheme's own first-step stencils, so no weights are assumed;
// dual_centroid_mismatch checks the centroid property on the mesh one step further down.
//
// Vertices on a crease or boundary (two edges sharp for the dual split, features/
// dual_features.h) make two points on the crease, the crease curve's at v, joined by a
// child edge along the crease; the crease rule keeps each crease edge's midpoint (checked
// the same way), so the nested edges shrink to it: l(v) is the mean of the two points'
// rows, v's point on the crease curve ((p + 6 v + q) / 8 for Chaikin's, the quadratic
// B-spline; next to a corner the clamped spline's). Corners are their own limit; a vertex
// that ends a crease (a dart) and a non-manifold vertex are refused.
#include <memory>
#include <string>

#include "framework/interpolation/limit_evaluator.h"
#include "framework/engine/refiner.h"

namespace subdiv {

class DualCentroidLimit final : public LimitEvaluator {
public:
  DualCentroidLimit(std::shared_ptr<const Scheme> scheme, RefineOptions options);
  std::string name() const override;

protected:
  StencilTable stencils_at(const Level& level, int step) const override;

private:
  std::shared_ptr<const Scheme> scheme_;
  RefineOptions options_;
};

// Per parent vertex, the child points one dual step makes on its sharp edges (kNone where
// it has none): `first` on edge `first_edge`, `second` on the other.
struct DualCreasePoints {
  std::vector<Index> first, second, first_edge;
};
DualCreasePoints dual_crease_points(const Level& parent, const ChildOrigins& origins);

// For each vertex of h.levels[0], the face of h.levels[1] made around it (its V-face), or
// kNone. A child vertex belongs to the parent vertex it was made at (a face corner's
// vertex, an edge's two ends, a vertex itself); a face with no parent face whose vertices
// all belong to v is v's V-face.
std::vector<Index> vertex_faces_after_step(const Hierarchy& h);

// Empty when, on `level`, every interior vertex's V-face keeps its centroid one step further
// down (the child face's mean stencil row is the V-face's centroid, to 1e-12 per weight);
// else the first face that does not, or why there are no V-faces.
std::string dual_centroid_mismatch(const Scheme& scheme, const Level& level, const RefineOptions& options);

}  // namespace subdiv
