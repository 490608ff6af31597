#pragma once
// The limit surface sampled as a mesh that every front-end writes or shows the same way
// (`subdiv evaluate --samples N`, ParaView's "SubdivKit Limit").
#include <functional>
#include <string>

#include "framework/io/mesh_data.h"
#include "framework/pipeline/evaluate_request.h"

namespace subdiv {

// The prepared surface (its rational weights included) tessellated with `segments` per face
// edge (limit/tessellation.h: crack-free, neighbouring faces share their edge samples), as
// a mesh with the point arrays "Normals" (the unit limit normal, role normals), "base_face"
// and "uv" (the face and (u, v) each point was evaluated at), the cell array "base_face"
// (the input face each face lies in), and the mesh's face-varying channels (e.g. texture
// coordinates) evaluated at every face corner, split where the channel has seams. Where the
// surface has no normal (tessellation.h, zero_normals_warning) "Normals" is (0, 0, 0) and
// `warnings` says how many and where, for the front-end to show. Throws subdiv::Error as
// tessellate() does (segments < 1, odd with sub-faces).
// `say` hears the phase ("sampling the limit surface, 8 x 8 per face") once the request is
// known to fit, `fraction` the share of the samples done (both may be empty); the scope that
// carries them is opened here, in the library, whose thread-local progress the loops read.
MeshData sampled_limit_mesh(const PreparedEvaluation& prepared, int segments,
                            const std::function<void(const std::string&)>& say = {},
                            const std::function<void(double)>& fraction = {});

}  // namespace subdiv
