#include "framework/pipeline/limit_mesh.h"

#include "framework/limit/tessellation.h"

namespace subdiv {
namespace {

DataArray index_array(const char* name, const std::vector<Index>& indices) {
  DataArray a{name, 1, {}, true};
  a.values.assign(indices.begin(), indices.end());
  return a;
}

}  // namespace

MeshData sampled_limit_mesh(const PreparedEvaluation& prepared, int segments) {
  Tessellation t = tessellate(*prepared.surface, prepared.mesh.positions, segments);
  MeshData m;
  m.point_data = {DataArray{"Normals", 3, std::move(t.normals), false, ArrayRole::Normals},
                  index_array("base_face", t.uv_face), DataArray{"uv", 2, std::move(t.uv), false}};
  m.cell_data = {index_array("base_face", t.base_face)};
  m.positions = std::move(t.positions);
  m.face_offsets = std::move(t.face_offsets);
  m.face_vertices = std::move(t.face_vertices);
  return m;
}

}  // namespace subdiv
