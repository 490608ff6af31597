#include "mesh_subset.h"

#include "framework/engine/mesh_pieces.h"

namespace subdiv::cli {

MeshData mesh_subset(const MeshData& mesh, std::span<const Index> vertices, std::span<const Index> faces,
                     std::span<const Index> new_vertex) {
  MeshData out;
  out.options = mesh.options;
  out.positions = gather_tuples(mesh.positions, 3, vertices);
  for (Index f : faces) {
    for (Index i = mesh.face_offsets[f]; i < mesh.face_offsets[f + 1]; ++i)
      out.face_vertices.push_back(new_vertex[mesh.face_vertices[i]]);
    out.face_offsets.push_back(Index(out.face_vertices.size()));
  }
  for (const DataArray& a : mesh.point_data) {
    out.point_data.push_back(a);
    out.point_data.back().values = gather_tuples(a.values, a.components, vertices);
  }
  for (const DataArray& a : mesh.cell_data) {
    out.cell_data.push_back(a);
    out.cell_data.back().values = gather_tuples(a.values, a.components, faces);
  }
  for (const FaceVaryingArray& a : mesh.face_varying) {
    FaceVaryingArray part = a;  // all values: corners of the kept faces index into them
    part.indices.clear();
    for (Index f : faces)
      part.indices.insert(part.indices.end(), a.indices.begin() + mesh.face_offsets[f],
                          a.indices.begin() + mesh.face_offsets[f + 1]);
    out.face_varying.push_back(std::move(part));
  }
  for (const CornerTag& c : mesh.corners)
    if (new_vertex[c.v] != kNone) out.corners.push_back({new_vertex[c.v], c.sharpness});
  return out;
}

}  // namespace subdiv::cli
