#pragma once
// Structural checks on a MeshData that every reader runs on its result and every writer
// runs before it creates a file, so that bad data is refused before anything is written
// and the engine receives only meshes whose indices and numbers make sense.
// Topology (manifoldness, orientation, degenerate faces) is the engine's to judge.
#include <string_view>

#include "framework/io/mesh_data.h"

namespace subdiv {

// Throws subdiv::Error "<context>: <problem>; <fix>" for: CSR arrays that are not
// offsets into their index arrays, faces with fewer than 3 vertices, polylines with fewer
// than 2, indices out of range, non-finite coordinates, crease or corner tags naming
// missing vertices, crease tags joining a vertex to itself, negative or non-finite
// sharpness.
//
// `ranges`, if given, receives what the checks of positions and faces see on their way (one
// pass over each array either way): writers put these ranges into their files' headers
// (write_vtp's RangeMin and RangeMax) without another pass over hundreds of megabytes.
struct MeshValueRanges {
  // Smallest and largest Euclidean norm of a point, as vtkDataArray::GetRange(-1) gives them
  // (the square root of the sum of squares, summed x, y, z). Not known (false) when there are
  // no points or some squares overflow (coordinates beyond 1e154, which need a scaled norm).
  bool point_norms_known = false;
  double point_norm_min = 0, point_norm_max = 0;
  // Smallest and largest index in face_vertices; not known when there are none.
  bool face_vertices_known = false;
  Index face_vertex_min = 0, face_vertex_max = 0;
};
void validate_mesh_data(const MeshData& mesh, std::string_view context, MeshValueRanges* ranges = nullptr);

}  // namespace subdiv
