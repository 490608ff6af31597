#include "framework/curve/curve_level.h"

#include <fmt/format.h>

#include "framework/util/error.h"
#include "framework/util/option_spelling.h"

namespace subdiv {

CurveLevel curve_level_from_mesh(const MeshData& mesh, const std::string& source) {
  if (mesh.face_count() > 0)
    throw OptionError(fmt::format("{}: the mesh has {} faces, but a curve scheme refines polylines only (OBJ 'l' "
                                  "lines, VTK line cells); refine this mesh with a surface scheme "
                                  "({{scheme_list}} lists them), or give a file of polylines",
                            source, mesh.face_count()));
  if (mesh.line_count() == 0)
    throw Error(fmt::format("{}: the mesh has no polylines to refine; a curve scheme needs OBJ 'l' lines "
                            "(e.g. \"l 1 2 3 4\", closed: \"l 1 2 3 4 1\") or VTK line cells",
                            source));
  CurveLevel level;
  level.vertex_count = mesh.vertex_count();
  for (Index p = 0; p < mesh.line_count(); ++p) {
    const Index begin = mesh.line_offsets[p], end = mesh.line_offsets[p + 1];
    const bool closed = end - begin >= 3 && mesh.line_vertices[begin] == mesh.line_vertices[end - 1];
    const Index size = closed ? end - begin - 1 : end - begin;
    if (closed && size < 3)
      throw Error(fmt::format("{}: polyline {} is closed (its last vertex repeats its first) but has only {} "
                              "points; a closed polygon needs at least 3",
                              source, p + 1, size));
    if (size < 2)
      throw Error(fmt::format("{}: polyline {} has {} point; a polyline needs at least 2", source, p + 1, size));
    for (Index i = begin; i < begin + size; ++i) {
      const Index v = mesh.line_vertices[i];
      if (v < 0 || v >= mesh.vertex_count())
        throw Error(fmt::format("{}: polyline {} names vertex {}, but the mesh has {} vertices", source, p + 1,
                                v + 1, mesh.vertex_count()));
      level.vertices.push_back(v);
    }
    level.offsets.push_back(Index(level.vertices.size()));
    level.closed.push_back(closed ? 1 : 0);
  }
  return level;
}

MeshData mesh_from_curve_level(const CurveLevel& level, std::vector<double> positions) {
  if (positions.size() != size_t(level.vertex_count) * 3)
    throw Error(fmt::format("curve level output: {} coordinates for {} vertices", positions.size(),
                            level.vertex_count));
  MeshData mesh;
  mesh.positions = std::move(positions);
  for (Index p = 0; p < level.polyline_count(); ++p) {
    const auto points = level.polyline(p);
    mesh.line_vertices.insert(mesh.line_vertices.end(), points.begin(), points.end());
    if (level.is_closed(p)) mesh.line_vertices.push_back(points.front());
    mesh.line_offsets.push_back(Index(mesh.line_vertices.size()));
  }
  return mesh;
}

}  // namespace subdiv
