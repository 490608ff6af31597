#pragma once
// Part of a mesh with the data that goes with it: pieces of a refinement in pieces, before
// (a piece of the base mesh) and after (the faces a piece keeps).
#include <span>

#include "framework/io/mesh_data.h"

namespace subdiv::cli {

// The faces `faces` of `mesh` over the vertices `vertices` (both lists of old indices, in
// the new order; new_vertex maps an old vertex to its new index, kNone where unused), with
// their point, cell and face-varying arrays and corner tags. Creases are left to the caller.
MeshData mesh_subset(const MeshData& mesh, std::span<const Index> vertices, std::span<const Index> faces,
                     std::span<const Index> new_vertex);

}  // namespace subdiv::cli
