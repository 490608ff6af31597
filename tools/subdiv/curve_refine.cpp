#include "curve_refine.h"

#include <chrono>
#include <fmt/format.h>

#include "framework/io/formats.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/pipeline/curve_pipeline.h"
#include "framework/pipeline/thread_limit.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"
#include "progress.h"
#include "safe_print.h"

namespace subdiv::cli {
namespace {

void check_curve_output(const std::filesystem::path& out) {
  const std::string ext = lowercase_extension(out);
  if (ext == ".vtp" || ext == ".pvd" || ext == ".obj") return;
  throw Error(fmt::format("cannot write polylines to {}: use .vtp or .pvd (ParaView) or .obj ('l' lines); "
                          ".off, .ply and .stl hold no polylines",
                          subdiv::quoted(out.string())));
}

// .obj: the finest level's polylines; .vtp: the finest level with SubdivKit's arrays; .pvd:
// every level.
void write_curve_levels(const std::filesystem::path& output, std::vector<RefinedCurveLevel>& levels) {
  const std::string ext = lowercase_extension(output);
  if (ext == ".obj") return write_mesh(output, levels.back().mesh);
  std::vector<CurveLevelDescription> descriptions;
  for (const auto& level : levels) descriptions.push_back(describe_curve_level(level));
  std::vector<OutputLevel> out;
  for (size_t k = 0; k < levels.size(); ++k) {
    OutputLevel o{&levels[k].mesh, levels[k].level, std::move(descriptions[k].point_data),
                  std::move(descriptions[k].cell_data)};
    o.point_data.insert(o.point_data.end(), levels[k].mesh.point_data.begin(), levels[k].mesh.point_data.end());
    out.push_back(std::move(o));
  }
  if (ext == ".vtp") write_vtp(output, out.back());
  else write_pvd(output, out);
}

}  // namespace

bool is_curve_scheme(const std::string& scheme) {
  try {
    return scheme_kind(scheme) == "curve";
  } catch (const Error&) {
    return false;
  }
}

void refine_curves_command(const CurveRefineArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  check_curve_output(a.output);
  const ThreadLimit thread_limit(a.threads, "--threads");
  if (!thread_limit.note().empty()) print_safe(stderr, "subdiv: note: {}\n", thread_limit.note());
  Progress progress;
  CurveRefineRequest request;
  request.mesh_file = a.mesh;
  request.scheme.text = a.scheme;
  request.scheme.parameters = a.params;
  request.levels = a.levels;
  request.weights_array = a.weights;
  request.keep_all_levels = lowercase_extension(a.output) == ".pvd";
  request.progress = [&](const std::string& phase) { progress.say(phase); };
  CurveRefineResult result = refine_curve_request(std::move(request));
  progress.say(fmt::format("writing {}", a.output));
  write_curve_levels(a.output, result.levels);
  progress.done();
  if (a.quiet) return;
  for (const auto& note : result.notes) print_safe(stderr, "subdiv: note: {}\n", note);
  const CurveLevel& fine = result.levels.back().topology;
  int closed = 0;
  for (auto c : fine.closed) closed += c;
  print_safe("{}: {} level(s) of {}{} -> {} points on {} polylines ({} closed) in {:.3f} s -> {}\n", a.mesh, a.levels,
             result.scheme->name, result.scheme->nonlinear ? " (non-linear)" : "", fine.vertex_count,
             fine.polyline_count(), closed, seconds_since(t0), a.output);
}

}  // namespace subdiv::cli
