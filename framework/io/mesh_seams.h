#pragma once
// Face-varying data for formats that hold per-point data only (VTK, and so ParaView): the
// mesh with one point per distinct (vertex, face-varying values) pair, so that a vertex on
// a UV seam becomes one point per side and every face corner finds its own UV at its point.
// This is how ParaView shows textures across seams. Each face-varying array becomes a
// point array (texture coordinates stay the active ones); point data is copied to every
// point made from its vertex; the point array "vertex_id" names that vertex. Crease and
// corner tags go to the first point made from each vertex.
#include "framework/io/mesh_data.h"

namespace subdiv {

// Returned as it is when it has no face-varying arrays.
MeshData split_at_seams(const MeshData& mesh);

}  // namespace subdiv
