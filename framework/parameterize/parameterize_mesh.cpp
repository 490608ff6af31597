#include "framework/parameterize/parameterize_mesh.h"

#include <algorithm>
#include <fmt/format.h>

#include "framework/io/mesh_level.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// Existing texture coordinates give way to the new ones (a mesh has one active set).
template <class Array>
void drop_texture_coordinates(std::vector<Array>& arrays, std::vector<std::string>& notes, const char* kind) {
  const auto old = std::remove_if(arrays.begin(), arrays.end(), [&](const Array& a) {
    const bool uv = a.role == ArrayRole::TextureCoordinates || a.name == "uv";
    if (uv) notes.push_back(fmt::format("replaced the {} texture coordinates {}", kind, subdiv::quoted(a.name)));
    return uv;
  });
  arrays.erase(old, arrays.end());
}

}  // namespace

ParameterizedMesh parameterize_mesh(MeshData mesh, const TutteOptions& options, const std::string& source) {
  if (mesh.face_count() == 0)
    throw Error(fmt::format("{}: the mesh has no faces; Tutte's embedding maps the faces of a disc", source));
  ParameterizedMesh out;
  const Level level = level_from_mesh(mesh, source);
  out.embedding = tutte_embedding(level, mesh.positions, options, source);
  drop_texture_coordinates(mesh.point_data, out.notes, "per-vertex");
  drop_texture_coordinates(mesh.face_varying, out.notes, "face-varying");
  mesh.point_data.push_back({"uv", 2, out.embedding.uv, false, ArrayRole::TextureCoordinates});
  out.mesh = std::move(mesh);
  return out;
}

BoundaryShape boundary_shape_from_name(const std::string& name, const std::string& option) {
  if (name == "circle") return BoundaryShape::Circle;
  if (name == "square") return BoundaryShape::Square;
  throw Error(fmt::format("{} {}: give circle or square", option, subdiv::quoted(name)));
}

TutteWeights tutte_weights_from_name(const std::string& name, const std::string& option) {
  if (name == "uniform") return TutteWeights::Uniform;
  if (name == "mean-value") return TutteWeights::MeanValue;
  throw Error(fmt::format("{} {}: give uniform (Tutte 1963) or mean-value (Floater 2003)", option, subdiv::quoted(name)));
}

}  // namespace subdiv
