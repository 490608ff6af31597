#include "framework/io/mesh_seams.h"

#include <map>

namespace subdiv {
namespace {

void copy_tuple(const std::vector<double>& from, int components, Index i, std::vector<double>& to) {
  to.insert(to.end(), from.begin() + size_t(i) * components, from.begin() + size_t(i + 1) * components);
}

}  // namespace

MeshData split_at_seams(const MeshData& mesh) {
  if (mesh.face_varying.empty()) return mesh;
  MeshData out = mesh;
  out.positions.clear();
  out.face_vertices.clear();
  out.face_varying.clear();
  out.creases.clear();
  out.corners.clear();
  for (DataArray& a : out.point_data) a.values.clear();
  std::vector<DataArray> unfolded;
  for (const FaceVaryingArray& f : mesh.face_varying) unfolded.push_back({f.name, f.components, {}, false, f.role});
  DataArray vertex_id{"vertex_id", 1, {}, true};
  std::vector<Index> first_point(size_t(mesh.vertex_count()), kNone);
  // A point per vertex and the face-varying value indices at a corner.
  std::map<std::vector<Index>, Index> point_of;
  std::vector<Index> key(mesh.face_varying.size() + 1);
  for (size_t c = 0; c < mesh.face_vertices.size(); ++c) {
    const Index v = mesh.face_vertices[c];
    key[0] = v;
    for (size_t k = 0; k < mesh.face_varying.size(); ++k) key[k + 1] = mesh.face_varying[k].indices[c];
    auto [it, added] = point_of.emplace(key, out.vertex_count());
    if (added) {
      copy_tuple(mesh.positions, 3, v, out.positions);
      for (size_t k = 0; k < mesh.point_data.size(); ++k)
        copy_tuple(mesh.point_data[k].values, mesh.point_data[k].components, v, out.point_data[k].values);
      for (size_t k = 0; k < mesh.face_varying.size(); ++k)
        copy_tuple(mesh.face_varying[k].values, mesh.face_varying[k].components, key[k + 1], unfolded[k].values);
      vertex_id.values.push_back(double(v));
      if (first_point[v] == kNone) first_point[v] = it->second;
    }
    out.face_vertices.push_back(it->second);
  }
  // Vertices no face uses (polyline points) keep a point of their own.
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (first_point[v] != kNone) continue;
    first_point[v] = out.vertex_count();
    copy_tuple(mesh.positions, 3, v, out.positions);
    for (size_t k = 0; k < mesh.point_data.size(); ++k)
      copy_tuple(mesh.point_data[k].values, mesh.point_data[k].components, v, out.point_data[k].values);
    for (DataArray& u : unfolded) u.values.insert(u.values.end(), size_t(u.components), 0.0);
    vertex_id.values.push_back(double(v));
  }
  for (Index& v : out.line_vertices) v = first_point[v];
  for (const CreaseTag& t : mesh.creases) out.creases.push_back({first_point[t.v0], first_point[t.v1], t.sharpness});
  for (const CornerTag& t : mesh.corners) out.corners.push_back({first_point[t.v], t.sharpness});
  for (DataArray& u : unfolded) out.point_data.push_back(std::move(u));
  out.point_data.push_back(std::move(vertex_id));
  return out;
}

}  // namespace subdiv
