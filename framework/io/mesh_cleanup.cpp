#include "framework/io/mesh_cleanup.h"

#include <algorithm>
#include <fmt/format.h>

namespace subdiv {

std::vector<std::string> MeshCleanup::warnings(const std::string& source) const {
  std::vector<std::string> out;
  if (dropped_faces)
    out.push_back(fmt::format("{}: {} face(s) with fewer than 3 distinct vertices dropped (they enclose no area)",
                              source, dropped_faces));
  if (dropped_vertices)
    out.push_back(fmt::format("{}: {} vertex/vertices used by no face or polyline dropped", source, dropped_vertices));
  return out;
}

namespace {

int distinct_count(const Index* first, const Index* last) {
  int n = 0;
  for (const Index* p = first; p != last; ++p) n += std::find(first, p, *p) == p;
  return n;
}

// The tuples of `a` whose new number (new_index[i]) is not kNone, in order.
DataArray kept_tuples(const DataArray& a, const std::vector<Index>& new_index) {
  DataArray out = a;
  out.values.clear();
  const size_t c = size_t(a.components);
  for (size_t i = 0; i < new_index.size(); ++i)
    if (new_index[i] != kNone) out.values.insert(out.values.end(), a.values.begin() + i * c, a.values.begin() + (i + 1) * c);
  return out;
}

}  // namespace

MeshData drop_unrefinable(const MeshData& mesh, MeshCleanup& report) {
  report = {};
  // Indices out of range are the validator's and the level builder's to refuse, by name.
  for (const auto* list : {&mesh.face_vertices, &mesh.line_vertices})
    for (Index v : *list)
      if (v < 0 || v >= mesh.vertex_count()) return mesh;
  for (Index f : mesh.holes)
    if (f < 0 || f >= mesh.face_count()) return mesh;
  // Faces: keep those with 3 or more distinct vertices; remember new face numbers for holes.
  std::vector<Index> new_face(size_t(mesh.face_count()), kNone);
  std::vector<Index> kept_corners;  // [begin, end) pairs of the kept faces' corners
  MeshData out;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Index* first = mesh.face_vertices.data() + mesh.face_offsets[f];
    const Index* last = mesh.face_vertices.data() + mesh.face_offsets[f + 1];
    if (distinct_count(first, last) < 3) {
      ++report.dropped_faces;
      continue;
    }
    new_face[f] = out.face_count();
    kept_corners.insert(kept_corners.end(), {mesh.face_offsets[f], mesh.face_offsets[f + 1]});
    out.face_vertices.insert(out.face_vertices.end(), first, last);
    out.face_offsets.push_back(Index(out.face_vertices.size()));
  }
  // Vertices: keep those a kept face or a polyline uses.
  std::vector<Index> new_vertex(size_t(mesh.vertex_count()), kNone);
  for (Index v : out.face_vertices) new_vertex[v] = 0;
  for (Index v : mesh.line_vertices) new_vertex[v] = 0;
  Index next = 0;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (new_vertex[v] == kNone) {
      ++report.dropped_vertices;
      continue;
    }
    new_vertex[v] = next++;
    out.positions.insert(out.positions.end(), mesh.positions.begin() + 3 * v, mesh.positions.begin() + 3 * v + 3);
  }
  if (!report.dropped_faces && !report.dropped_vertices) return mesh;
  for (Index& v : out.face_vertices) v = new_vertex[v];
  out.line_offsets = mesh.line_offsets;
  for (Index v : mesh.line_vertices) out.line_vertices.push_back(new_vertex[v]);
  for (const CreaseTag& c : mesh.creases)
    if (new_vertex[c.v0] != kNone && new_vertex[c.v1] != kNone)
      out.creases.push_back({new_vertex[c.v0], new_vertex[c.v1], c.sharpness});
  for (const CornerTag& c : mesh.corners)
    if (new_vertex[c.v] != kNone) out.corners.push_back({new_vertex[c.v], c.sharpness});
  for (Index f : mesh.holes)
    if (new_face[f] != kNone) out.holes.push_back(new_face[f]);
  out.options = mesh.options;
  out.warnings = mesh.warnings;
  for (const DataArray& a : mesh.point_data) out.point_data.push_back(kept_tuples(a, new_vertex));
  for (const DataArray& a : mesh.cell_data) out.cell_data.push_back(kept_tuples(a, new_face));
  for (const FaceVaryingArray& a : mesh.face_varying) {
    FaceVaryingArray kept = a;
    kept.indices.clear();
    for (size_t i = 0; i < kept_corners.size(); i += 2)
      kept.indices.insert(kept.indices.end(), a.indices.begin() + kept_corners[i], a.indices.begin() + kept_corners[i + 1]);
    out.face_varying.push_back(std::move(kept));
  }
  return out;
}

}  // namespace subdiv
