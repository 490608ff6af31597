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

namespace subdiv::cli {
namespace {

namespace fs = std::filesystem;

void check_outputs(const CurveInterpolateRequest& a) {
  const std::string ext = lowercase_extension(a.output);
  if (ext != ".obj" && ext != ".vtp")
    throw Error(fmt::format("-o '{}': polylines are written as .obj ('l' lines) or .vtp; .off, .ply and .stl hold "
                            "no polylines", a.output));
  if (!a.refined.empty() && lowercase_extension(a.refined) != ".pvd" && lowercase_extension(a.refined) != ".vtp")
    throw Error(fmt::format("--refined '{}': use .pvd (every level) or .vtp (the finest level)", a.refined));
}

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

std::string describe_limit(const StencilTable& limit, const CurveLevel& level) {
  // The row of a vertex in the middle of the longest polyline shows the interior weights.
  Index longest = 0;
  for (Index p = 1; p < level.polyline_count(); ++p)
    if (level.size(p) > level.size(longest)) longest = p;
  const Index v = level.polyline(longest)[size_t(level.size(longest) / 2)];
  std::vector<std::string> terms;
  for (Index i = limit.offsets[v]; i < limit.offsets[v + 1]; ++i) terms.push_back(fmt::format("{:.6g}", limit.weights[i]));
  return fmt::format("the limit curve at each point's parameter; inside a polyline the weights ({})", fmt::join(terms, ", "));
}

}  // namespace

void interpolate_curves_command(const CurveInterpolateRequest& a) {
  check_output_path(a.output);
  check_outputs(a);
  const auto scheme = load_curve(a.scheme, a.params);
  const MeshData mesh = read_mesh(a.mesh);
  const CurveLevel base = curve_level_from_mesh(mesh, a.mesh);
  const std::vector<std::uint8_t> moving = read_selection(a.select, base.vertex_count);
  if (!a.refined.empty()) check_curve_size(base, scheme->arity, a.levels);

  Progress progress;
  progress.say("finding the limit points");
  const StencilTable limit = curve_limit_stencils(*scheme, base);
  const IterationRun run = run_iterations(limit, mesh.positions, moving, {a.tolerance, a.max_iterations, a.verbose},
                                          progress);
  const ProgressiveResult& r = run.result;

  progress.say(fmt::format("writing {}", a.output));
  const MeshData control = mesh_from_curve_level(base, r.control);
  if (lowercase_extension(a.output) == ".vtp") {
    const OutputLevel level{&control, 0, {}, {}};
    write_vtp(a.output, level);
  } else {
    write_mesh(a.output, control);
  }
  if (!a.refined.empty()) {
    progress.say(fmt::format("writing {}", a.refined));
    write_refined(a.refined, *scheme, base, r, mesh.positions, moving, a.levels);
  }
  progress.done();

  warn_if_stopped(run, "the polylines written are");
  if (a.quiet) return;
  fmt::print("{}: {} points on {} polyline{}; curve scheme {}\n", a.mesh, base.vertex_count, base.polyline_count(),
             base.polyline_count() == 1 ? "" : "s", scheme->name);
  fmt::print("limit: {}\n", describe_limit(limit, base));
  print_iterations(run, "points", a.verbose);
  fmt::print("wrote {}", a.output);
  if (!a.refined.empty()) fmt::print(" and {} ({} levels)", a.refined, a.levels);
  fmt::print("\n");
}

}  // namespace subdiv::cli
