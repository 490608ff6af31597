#include "curve_interpolate.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>

#include "framework/curve/curve_refine.h"
#include "framework/interpolation/curve_limits.h"
#include "framework/interpolation/progressive.h"
#include "framework/io/formats.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/pipeline/curve_pipeline.h"
#include "framework/util/error.h"
#include "curve_refine.h"
#include "interpolate_common.h"
#include "level_output.h"
#include "progress.h"
#include "framework/util/quoted_text.h"

namespace subdiv::cli {
namespace {

namespace fs = std::filesystem;

// Level 0 carries which points were interpolated and how far each limit point ended from
// its target; finer levels carry the curve only.
void write_refined(const fs::path& out, const CurveScheme& scheme, const CurveLevel& base,
                   const ProgressiveResult& r, const std::vector<double>& targets,
                   const std::vector<std::uint8_t>& moving, int levels) {
  const CurveHierarchy h = refine_curves(scheme, base, levels);
  std::vector<MeshData> meshes;
  std::vector<double> positions = r.control;
  for (int l = 0; l <= levels; ++l) {
    if (l > 0) positions = h.stencils[size_t(l - 1)].apply(positions, 3);
    meshes.push_back(mesh_from_curve_level(h.levels[size_t(l)], positions));
  }
  std::vector<OutputLevel> out_levels;
  for (int l = 0; l <= levels; ++l) out_levels.push_back({&meshes[size_t(l)], l, {}, {}});
  DataArray interpolated{"interpolated", 1, {}, true}, residual{"limit_residual", 1, {}, false};
  for (Index v = 0; v < base.vertex_count; ++v) {
    interpolated.values.push_back(moving[size_t(v)] ? 1.0 : 0.0);
    double d2 = 0;
    for (int c = 0; c < 3; ++c) d2 += std::pow(r.limit[3 * size_t(v) + c] - targets[3 * size_t(v) + c], 2);
    residual.values.push_back(std::sqrt(d2));
  }
  out_levels.front().point_data = {std::move(interpolated), std::move(residual)};
  if (lowercase_extension(out) == ".vtp") write_vtp(out, out_levels.back());
  else write_pvd(out, out_levels);
}

}  // namespace

void check_curve_outputs(const std::string& output, const std::string& refined) {
  const std::string ext = lowercase_extension(output);
  if (ext != ".obj" && ext != ".vtp")
    throw Error(fmt::format("-o {}: polylines are written as .obj ('l' lines) or .vtp; .off, .ply and .stl hold "
                            "no polylines", subdiv::quoted(output)));
  if (!refined.empty() && lowercase_extension(refined) != ".pvd" && lowercase_extension(refined) != ".vtp")
    throw Error(fmt::format("--refined {}: use .pvd (every level) or .vtp (the finest level)", subdiv::quoted(refined)));
}

void write_curve_interpolation(const CurveInterpolationOutput& a, const InterpolateResult& r, const MeshData& mesh,
                               Progress& progress) {
  if (!a.refined.empty()) check_curve_size(r.curve_base, r.curve->arity, a.levels);
  progress.say(fmt::format("writing {}", a.output));
  const MeshData control = mesh_from_curve_level(r.curve_base, r.iteration.control);
  if (lowercase_extension(a.output) == ".vtp") {
    const OutputLevel level{&control, 0, {}, {}};
    write_vtp(a.output, level);
  } else {
    write_mesh(a.output, control);
  }
  if (!a.refined.empty()) {
    progress.say(fmt::format("writing {}", a.refined));
    std::vector<std::uint8_t> moving(size_t(r.vertices), 1);
    if (r.moving < r.vertices) moving = a.moving;
    write_refined(a.refined, *r.curve, r.curve_base, r.iteration, mesh.positions, moving, a.levels);
  }
  progress.done();
}

}  // namespace subdiv::cli
