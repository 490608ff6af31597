#pragma once
// The limit surface approximated by Loop & Schaefer's bicubic patches (limit/bezier_approximation.h),
// as every front-end asks for it (`subdiv evaluate --approximate bezier`), measured against
// the exact limit (limit/limit_surface.h) at the same (face, u, v): the distance no library shows.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/limit/bezier_approximation.h"
#include "framework/limit/gregory_approximation.h"
#include "framework/pipeline/evaluate_request.h"

namespace subdiv {

class RefinedControlMesh;  // limit/refined_control_mesh.h

// The patches of an approximation and the control mesh they are built on: the base mesh,
// or where it has faces that are not quads or semi-sharp creases and corners, the mesh a
// few uniform steps of the scheme make of it (as `subdiv refine -l steps` writes it): one
// step makes every face a quad, ceil(s) steps let sharpness s decay, after which the
// masks' smooth and infinitely sharp rules are the scheme's. Every front-end evaluates
// them at the base mesh's (face, u, v), through `mesh`.
template <typename Patch>
struct Approximation {
  std::vector<Patch> patches;    // one per face of the mesh they are built on
  std::vector<Index> base_face;  // per patch: the base face it lies in
  // Per patch: 1 where its base face is a hole. A hole removes faces, not rules: every patch
  // is built as on the mesh without the tags, and a hole's patches are never sampled or
  // written.
  std::vector<std::uint8_t> in_hole;
  int steps = 0;                 // uniform steps from the base mesh to the patches' mesh
  std::shared_ptr<const RefinedControlMesh> mesh;
};
using BezierApproximation = Approximation<BezierPatch>;
using GregoryApproximation = Approximation<GregoryPatch>;

// The patches of a prepared surface. Throws subdiv::Error saying why they cannot be built:
// the scheme (bezier_approximation_unsupported; with boundaries or creases also
// bezier_features_unsupported), a sequence, rational weights, or a face or edge the masks do
// not cover (bezier_patches: naming it, on the refined level when steps > 0).
BezierApproximation approximation_patches(const PreparedEvaluation& prepared);

// Loop, Schaefer, Ni & Castaño's Gregory patches of a prepared surface
// (`--approximate gregory`). Throws subdiv::Error as approximation_patches does (the same
// scheme, mesh and feature checks; gregory_patches naming the face or edge).
GregoryApproximation gregory_approximation_patches(const PreparedEvaluation& prepared);

// Distances from the approximation to the exact limit.
struct ApproximationDistances {
  std::vector<double> per_point;  // |approximation - limit| at each sample
  std::vector<double> per_face;   // per base face: the largest over its samples (0 without samples)
  double largest = 0, mean = 0;
  Index largest_face = kNone;  // the first base face within 1e-9 (relative) of the largest
  Index samples = 0;
};

// Points of the approximation: positions, unit normals (of the tangent patches), distances.
struct ApproximatedPoints {
  std::vector<double> positions, normals;
  ApproximationDistances distances;
};
ApproximatedPoints approximate_points(const PreparedEvaluation& prepared, const BezierApproximation& patches,
                                      std::span<const Index> faces, std::span<const double> uv);
// Likewise with the Gregory patches' own unit normals.
ApproximatedPoints approximate_points(const PreparedEvaluation& prepared, const GregoryApproximation& patches,
                                      std::span<const Index> faces, std::span<const double> uv);

// The approximation tessellated N x N per face as limit_mesh.h tessellates the exact limit
// (crack-free: the patches meet with C0, points on shared edges are evaluated once), with
// the point arrays Normals (the tangent patches' unit normal), base_face, uv and
// limit_distance, and the cell arrays base_face and limit_distance (the largest distance
// over the base face's samples); the mesh's `warnings` say where Normals are (0, 0, 0), as
// sampled_limit_mesh's.
MeshData approximated_limit_mesh(const PreparedEvaluation& prepared, const BezierApproximation& patches,
                                 int segments, ApproximationDistances& distances);
// Likewise with the Gregory patches (Normals: their own unit normal; crack-free, as they
// share their boundary curves).
MeshData approximated_limit_mesh(const PreparedEvaluation& prepared, const GregoryApproximation& patches,
                                 int segments, ApproximationDistances& distances);

enum class ApproximationKind { Bezier, Gregory };

// "the patches are built on level L, ... : P patches", or empty when they are the base
// mesh's (steps 0).
std::string approximation_level_note(int steps, size_t patches);

// "... against the exact limit: largest distance X (face F), mean Y over N samples".
std::string approximation_summary(const ApproximationDistances& d, ApproximationKind kind = ApproximationKind::Bezier);

// The geometry patches as a VTK XML unstructured grid (.vtu, ASCII) of Bézier quadrilaterals
// (VTK_BEZIER_QUADRILATERAL, degree 3 x 3 in the cell array HigherOrderDegrees; VTK's
// point order: corners, edges, interior), with the cell arrays base_face and, when given
// (one per base face), limit_distance, the base face's; holes' patches left out. ParaView (5.5+) shows them as
// curved patches.
std::string bezier_control_net_vtu(const BezierApproximation& patches, std::span<const double> limit_distance);

}  // namespace subdiv
