#pragma once
// Topology rules: each splitter maps a parent Level to a child Level and records where
// every child vertex came from. Child vertices are numbered by origin in blocks:
// children of parent vertices, then of edges, then of faces (then of face corners),
// each block in parent index order.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

struct SplitResult {
  Level child;
  ChildOrigins origins;
  // False when this step leaves boundaries and creases unrefined (odd sqrt3 steps):
  // their vertices then stay where they are.
  bool features_refined = true;
  // What the split did differently from its usual result, for the user (one sentence), or
  // empty: e.g. the faces a dual split leaves out around non-manifold edges and vertices.
  std::string warning;
  // A split that fills its own tags (not engine_propagates_tags) and whose child edge
  // sharpness depends on the crease method: the child's edge sharpness under Chaikin's
  // decay (DeRose, Kass & Truong 1998), which the refiner takes for --crease-method averaged;
  // `child.edge_sharpness` holds the uniform decay. Empty: the same under both.
  std::vector<float> averaged_edge_sharpness = {};
};

// Primal 1-to-k split of any polygon: a k-gon becomes k quads around a new face point.
SplitResult split_quad(const Level& parent);
// Primal 1-to-4 split of triangles; the caller checks that all faces are triangles.
SplitResult split_triangle(const Level& parent);
// The same two splits with the child's faces only (primal_topology.h: no edges or rings),
// for a last level that nothing refines further.
SplitResult split_quad_faces(const Level& parent);
SplitResult split_triangle_faces(const Level& parent);

// sqrt(3) (Kobbelt 2000): one new point per face, old edges flipped; boundaries and sharp
// edges are trisected every second step (step_index odd, counted from 0 at the input).
SplitResult split_sqrt3(const Level& parent, int step_index);
// Dual (Doo-Sabin): one new point per face corner; F-faces, E-faces (interior edges) and
// V-faces (interior vertices, and boundary vertices with three or more faces).
SplitResult split_dual(const Level& parent);
// Mid-edge (Peters-Reif 1997): one new point per edge; F-faces and V-faces.
SplitResult split_mid_edge(const Level& parent);
// The same splits with the child's faces only (no edges, rings or tags), for a last level.
SplitResult split_sqrt3_faces(const Level& parent, int step_index);
SplitResult split_dual_faces(const Level& parent);
SplitResult split_mid_edge_faces(const Level& parent);

// A splitter by id: the built-in ones below, and ids from kFirstRegisteredSplit up for
// splitters registered at run time (plugins, framework/plugin).
enum class SplitKind : std::uint16_t { Quad, Triangle, Sqrt3, Dual, MidEdge };
constexpr std::uint16_t kFirstRegisteredSplit = 16;

// A topology rule and what the engine needs to know about it. Built-in splitters are
// described the same way, so the scheme loader and the refiner treat all of them alike.
struct SplitterInfo {
  std::string name, description;
  std::function<SplitResult(const Level& parent, int step_index)> split;
  // Optional: the same split giving the child's faces only (vertex_count, face_offsets,
  // face_vertices; no edges, rings or tags), for a last level that nothing refines further
  // (RefineOptions::faces_only_last_level). Null: `split` is used.
  std::function<SplitResult(const Level& parent, int step_index)> split_faces_only;
  // Faces it accepts: 0 any polygon, 3 triangles only, 4 quads only.
  int required_face_size = 0;
  // The parent elements whose new points a scheme gives rules for (a scheme file may have
  // rules for these only), e.g. vertex, edge and face for the quad split. Other children
  // (sqrt3's trisected boundary points) follow the boundary curve scheme.
  std::vector<OriginKind> rule_elements;
  // How the split refines boundaries and creases: the arity of the curve scheme that fits
  // them, and whether old vertices stay on the curve (primal) or not (dual).
  int curve_arity = 2;
  bool primal = true;
  // True when child vertex v is parent vertex v and each parent edge's children join its
  // end's child to the edge's new point (the quad and triangle splits): the engine then
  // carries crease sharpness to the child. Otherwise `split` fills the child's tags itself
  // (or leaves them empty: all smooth).
  bool engine_propagates_tags = false;
  // What analysis and limit evaluation ask of a split (analysis/surface), so that a
  // plugin's split is analysed like a built-in one. `scale`: how much one step shrinks the
  // mesh around a fixed point (2 for binary splits, sqrt 3 for sqrt3, sqrt 2 for mid-edge).
  // `period`: after how many steps the split's pattern repeats; 2 for splits that rotate
  // the mesh, which the analysis then studies as S^2 (the rotation undone). Fixed points sit
  // on vertices for primal splits and at face centres otherwise (`primal`).
  double scale = 2.0;
  int period = 1;
  // Steps between refinements of boundaries and creases: sqrt3 trisects them every second
  // step (2); SplitResult::features_refined says which steps do.
  int feature_period = 1;
  // True when `split` accepts non-manifold levels (topology/level.h): the primal splits refine
  // them as OpenSubdiv does; sqrt3 keeps non-manifold edges unflipped, as creases, and the
  // dual ones leave a gap there, both saying so in SplitResult::warning. The engine refuses
  // non-manifold meshes for the others (plugins that do not opt in), naming the splitter.
  bool handles_non_manifold = false;
  std::string origin = "built-in";  // or the plugin that registered it
  // Refinement in pieces (engine/ghost_rings.h): how far a child face's topology reaches,
  // in rings of the parent level measured from the child's own place. 1/2 when every child
  // face lies in one parent face (the primal splits); 3/2 when the split also makes faces
  // around vertices or across edges (faces of corner or edge points, flipped edges): such a face is
  // made only where the element is interior, which depends on the faces one ring beyond it.
  // Negative: not known (a plugin's split that does not say), and pieces are refused.
  double topology_reach = -1;
  // How many rings of the child level one ring of the parent becomes, in the direction where
  // they are fewest: `scale` for splits whose child rings follow the parent's, 1 for a split
  // that turns the mesh by 45 degrees (a parent ring along an edge is one child ring across
  // its diagonal). 0: the same as `scale`.
  double ring_scale = 0;
};

// With `faces_only`, the splitter's split_faces_only where it has one.
SplitResult split(SplitKind kind, const Level& parent, int step_index, bool faces_only = false);
// The built-in names ("quad", "triangle", "sqrt3", "dual", "mid-edge") and registered ones;
// throws subdiv::Error listing the known names for an unknown one.
SplitKind split_kind_from_name(std::string_view name);
const SplitterInfo& splitter_info(SplitKind kind);
// Adds a splitter; throws subdiv::Error if the name is taken or the function is missing.
// Registered splitters live as long as the process.
SplitKind register_splitter(SplitterInfo info);
// Removes the most recently registered splitter, which must be `kind` (the plugin loader
// undoes a refused plugin's registrations this way).
void unregister_splitter(SplitKind kind);

}  // namespace subdiv
