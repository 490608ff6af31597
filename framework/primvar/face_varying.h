#pragma once
// Face-varying data (OpenSubdiv's "face-varying primvars"): values with their own index
// per face corner, so that neighbouring faces may disagree at a vertex — UV seams.
//
// Refined as OpenSubdiv refines it (Vtr::FVarLevel, Far::PrimvarRefiner::
// InterpolateFaceVarying): the values form a mesh of their own, with the vertex mesh's
// faces but the corners' value indices, in which a seam is a boundary. That mesh is
// refined with the same scheme, the vertex mesh's sharpness copied onto it, so that
//  - a value whose neighbourhood matches its vertex's takes the vertex's own rule;
//  - a value on a seam takes the crease rule along the seam (a smooth boundary), or stays
//    where it is (a sharp corner) as the linear-interpolation mode decides (below);
//  - an edge point on a seam is the mean of the edge's two values on that side.
// The modes (Sdc::Options::FVarLinearInterpolation), at the base level:
//   None            smooth everywhere: a value with one face is a smooth boundary too;
//   CornersOnly     a value with one face is a sharp corner (OpenSubdiv's default);
//   CornersPlus1    also every value of a vertex where three or more regions meet, and both
//                   values of a vertex whose two regions touch only at it;
//   CornersPlus2    also darts (a seam that ends inside the mesh) and both values of a
//                   vertex where one of two regions is a corner;
//   Boundaries      every value on a seam or the mesh boundary is sharp and seams stay
//                   straight: linear along all boundaries;
//   All             linear everywhere (bilinear in the face).
// Values that are sharp corners keep that tag at finer levels; with Boundaries every value
// on a seam is a corner at every level, with All every value and edge.
//
// Dual splits (every new point a face corner; OpenSubdiv has none): a new point's value is
// the dual rule applied to its corner in its own island; each point then has one value, so
// the faces a dual step makes across a seam or around a seam vertex join two islands.
//
// Splits whose new faces cross old edges (sqrt3's flipped triangles, mid-edge's vertex
// faces): the data follows the vertex mesh's new faces, each corner valued in one old face
// (so in one island) by the scheme's rule for its point on the value mesh
// (primvar/crossing_step.h says which face and why).
#include <span>
#include <string>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/io/mesh_data.h"

namespace subdiv {

enum class FaceVaryingLinear { None, CornersOnly, CornersPlus1, CornersPlus2, Boundaries, All };

// "none", "corners-only", "corners-plus1", "corners-plus2", "boundaries", "all".
const char* face_varying_linear_name(FaceVaryingLinear mode);
// OpenSubdiv's numbering in OBJ's "t facevaryinginterpolateboundary" tag: 0 none ... 5 all.
FaceVaryingLinear face_varying_linear_from_tag(int value);

struct FaceVaryingLevel {
  std::vector<double> values;  // components per value
  std::vector<Index> indices;  // per face corner, in the level's face order
};

// Levels 0..h.levels.size()-1 of one face-varying channel, with `components` per value;
// levels[0] is `base`, renumbered so that each value belongs to one vertex (a value index
// a file uses at two vertices becomes two values). `h` comes from refine_topology with the
// same runs and options. Throws subdiv::Error for indices that do not fit the base level,
// and for a split whose new faces lie each in one old face but that splits the islands
// into other faces than the mesh (none of the built-in ones).
std::vector<FaceVaryingLevel> refine_face_varying(std::span<const SchemeRun> runs, const Hierarchy& h,
                                                  const FaceVaryingLevel& base, int components,
                                                  FaceVaryingLinear mode, const RefineOptions& options);

// A channel's value mesh at the base level, as refine_face_varying starts from it: the
// vertex mesh's faces (same order) over the values, renumbered so that each value belongs
// to one vertex, with the vertex mesh's sharpness and the corners `mode` makes (and, for
// Boundaries and All, every boundary value a corner). Its limit surface, refined with the
// scheme and the boundary rule EdgesOnly, is the channel's limit (framework/limit evaluates
// it at (face, u, v); for All it is bilinear in each face).
struct FaceVaryingValueMesh {
  Level level;
  FaceVaryingLevel values;     // values.indices: per face corner, the level's face_vertices
  std::vector<Index> vertex_of;  // per value: its vertex
};
FaceVaryingValueMesh face_varying_value_mesh(const Level& vertices, const FaceVaryingLevel& base, int components,
                                             FaceVaryingLinear mode, BoundaryInterpolation boundary);

}  // namespace subdiv
