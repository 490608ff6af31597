#pragma once
// `subdiv parameterize` and subdivkit.parameterize: a disc-like mesh given texture
// coordinates by Tutte's embedding (tutte.h), as the point array "uv" with the role
// TextureCoordinates: OBJ writes it as vt (which `subdiv refine` reads back as face-varying
// data), a .vtp as its active texture coordinates.
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/parameterize/tutte.h"

namespace subdiv {

struct ParameterizedMesh {
  MeshData mesh;                  // the input with "uv" (earlier texture coordinates replaced)
  TutteResult embedding;
  std::vector<std::string> notes;  // texture coordinates replaced
};

// Throws subdiv::Error naming `source` for a mesh that is not a disc, or bad options.
ParameterizedMesh parameterize_mesh(MeshData mesh, const TutteOptions& options, const std::string& source);

// "circle" / "square", "uniform" / "mean-value": refused, naming `option`, otherwise.
BoundaryShape boundary_shape_from_name(const std::string& name, const std::string& option);
TutteWeights tutte_weights_from_name(const std::string& name, const std::string& option);

}  // namespace subdiv
