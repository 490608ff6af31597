#pragma once
// Child topology of the primal splits built directly from the parent's (as OpenSubdiv's
// Vtr::Refinement does): every child edge, face slot and CCW ring follows from the
// parent's arrays, so no search or sort is needed. Numbering:
// - child vertices: parent vertices, then one per edge, then (quad) one per face;
// - child edges: the two halves of parent edge e are 2e (a -> mid) and 2e+1 (mid -> b),
//   then the edges inside faces (quad: one per parent corner c, from the mid-point of the
//   corner's out-edge to the face point; triangle: three per face, edge 3f+i joins the
//   mid-points of face f's edges i and i-1);
// - child faces: quad: one per parent corner; triangle: 4f+i at corner i, 4f+3 the middle.
#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

Level quad_split_topology(const Level& parent);
Level triangle_split_topology(const Level& parent);

// The child's faces only (vertex_count, face_offsets, face_vertices; no edges or rings):
// for a last level that nothing refines further, as OpenSubdiv's default UniformOptions.
Level quad_split_faces(const Level& parent);
Level triangle_split_faces(const Level& parent);

// The origins of split_quad and split_triangle alone, without their parent faces (which
// only the child's faces need), for a last level whose values are made before its faces
// (engine/topology_steps.h): the values read the parent level and these origins, never the
// child's faces; the parent faces are added with the faces.
ChildOrigins quad_split_origins(const Level& parent);
ChildOrigins triangle_split_origins(const Level& parent);
void add_quad_parent_faces(const Level& parent, ChildOrigins& origins);
void add_triangle_parent_faces(const Level& parent, ChildOrigins& origins);

}  // namespace subdiv
