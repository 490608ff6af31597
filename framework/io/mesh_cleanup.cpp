#include "framework/io/mesh_cleanup.h"

#include <span>
#include <fmt/format.h>

namespace subdiv {

std::vector<std::string> MeshCleanup::warnings(const std::string& source) const {
  std::vector<std::string> out;
  if (dropped_vertices)
    out.push_back(fmt::format("{}: {} vertex/vertices used by no face or polyline dropped", source, dropped_vertices));
  return out;
}

namespace {

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

MeshData drop_unrefinable(MeshData&& mesh, MeshCleanup& report) {
  report = {};
  // One pass marks the vertices in use. Indices out of range are the validator's and the
  // level builder's to refuse, by name.
  std::vector<Index> new_vertex(size_t(mesh.vertex_count()), kNone);
  for (std::span<const Index> list : {std::span<const Index>(mesh.face_vertices), std::span<const Index>(mesh.line_vertices)})
    for (Index v : list) {
      if (v < 0 || v >= mesh.vertex_count()) return std::move(mesh);
      new_vertex[v] = 0;
    }
  for (Index v = 0; v < mesh.vertex_count(); ++v) report.dropped_vertices += new_vertex[v] == kNone;
  if (!report.dropped_vertices) return std::move(mesh);  // the usual case: no copy
  MeshData out;
  Index next = 0;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (new_vertex[v] == kNone) continue;
    new_vertex[v] = next++;
    out.positions.insert(out.positions.end(), mesh.positions.begin() + 3 * v, mesh.positions.begin() + 3 * v + 3);
  }
  out.face_offsets = mesh.face_offsets;
  for (Index v : mesh.face_vertices) out.face_vertices.push_back(new_vertex[v]);
  out.line_offsets = mesh.line_offsets;
  for (Index v : mesh.line_vertices) out.line_vertices.push_back(new_vertex[v]);
  for (const CreaseTag& c : mesh.creases)
    if (new_vertex[c.v0] != kNone && new_vertex[c.v1] != kNone)
      out.creases.push_back({new_vertex[c.v0], new_vertex[c.v1], c.sharpness});
  for (const CornerTag& c : mesh.corners)
    if (new_vertex[c.v] != kNone) out.corners.push_back({new_vertex[c.v], c.sharpness});
  out.holes = mesh.holes;
  out.options = mesh.options;
  out.warnings = mesh.warnings;
  for (const DataArray& a : mesh.point_data) out.point_data.push_back(kept_tuples(a, new_vertex));
  out.cell_data = mesh.cell_data;  // every face is kept
  out.face_varying = mesh.face_varying;  // every face is kept, with its corners
  return out;
}

MeshData drop_unrefinable(const MeshData& mesh, MeshCleanup& report) { return drop_unrefinable(MeshData(mesh), report); }

}  // namespace subdiv
