#include "nonlinear_curve.h"

#include <fmt/format.h>

#include "framework/curve/curve_level.h"
#include "framework/io/formats.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/plugin/polyline_refine.h"
#include "framework/util/error.h"
#include "progress.h"

namespace subdiv::cli {
namespace {

// Every polyline of `level` as its own run of points (xyz), so each can be refined alone.
std::vector<std::vector<double>> polyline_points(const CurveLevel& level, const std::vector<double>& positions) {
  std::vector<std::vector<double>> out(level.polyline_count());
  for (Index p = 0; p < level.polyline_count(); ++p)
    for (Index v : level.polyline(p)) out[p].insert(out[p].end(), positions.begin() + 3 * v, positions.begin() + 3 * v + 3);
  return out;
}

// The polylines as a mesh; closed ones repeat their first point's index, as OBJ `l` does.
MeshData mesh_of(const std::vector<std::vector<double>>& polylines, const std::vector<std::uint8_t>& closed) {
  MeshData mesh;
  for (size_t p = 0; p < polylines.size(); ++p) {
    const Index first = mesh.vertex_count();
    mesh.positions.insert(mesh.positions.end(), polylines[p].begin(), polylines[p].end());
    const Index count = Index(polylines[p].size() / 3);
    for (Index i = 0; i < count; ++i) mesh.line_vertices.push_back(first + i);
    if (closed[p]) mesh.line_vertices.push_back(first);
    mesh.line_offsets.push_back(Index(mesh.line_vertices.size()));
  }
  return mesh;
}

}  // namespace

void refine_nonlinear_curves(const CurveRefineRequest& a, const CurveScheme& scheme) {
  const MeshData input = read_mesh(a.mesh);
  const CurveLevel base = curve_level_from_mesh(input, a.mesh);
  std::vector<std::vector<double>> polylines = polyline_points(base, input.positions);
  const std::string ext = lowercase_extension(a.output);
  std::vector<MeshData> levels{mesh_of(polylines, base.closed)};
  Progress progress;
  for (int l = 0; l < a.levels; ++l) {
    progress.say(fmt::format("level {}/{} of {} (non-linear)", l + 1, a.levels, scheme.name));
    for (Index p = 0; p < Index(polylines.size()); ++p)
      polylines[p] = refine_polyline(scheme, polylines[p], 3, base.is_closed(p), 1, l);
    if (ext == ".pvd" || l + 1 == a.levels) levels.push_back(mesh_of(polylines, base.closed));
  }
  progress.say(fmt::format("writing {}", a.output));
  if (ext == ".obj") {
    write_mesh(a.output, levels.back());
  } else {
    std::vector<OutputLevel> out;
    for (size_t k = 0; k < levels.size(); ++k)
      out.push_back({&levels[k], ext == ".pvd" ? int(k) : a.levels, {}, {}});
    if (ext == ".vtp") write_vtp(a.output, out.back());
    else write_pvd(a.output, out);
  }
  progress.done();
  if (!a.quiet)
    fmt::print("{}: {} level(s) of {} (non-linear) -> {} points on {} polylines -> {}\n", a.mesh, a.levels, scheme.name,
               levels.back().vertex_count(), levels.back().line_count(), a.output);
}

}  // namespace subdiv::cli
