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
void validate_mesh_data(const MeshData& mesh, std::string_view context);

}  // namespace subdiv
