// `subdiv refine MESH --scheme S --levels L -o OUT`: the main job.
#include <chrono>
#include <fmt/format.h>
#include <tbb/global_control.h>

#include "commands.h"
#include "framework/io/formats.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/scheme/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "level_output.h"
#include "memory_guard.h"
#include "progress.h"
#include "curve_refine.h"

namespace subdiv::cli {
namespace {

struct RefineArgs {
  std::string mesh, scheme = "catmull-clark", output;
  int levels = 1;
  std::vector<std::string> params;
  std::string boundary = "edges-and-corners", crease_method = "uniform";
  int threads = 0;
  bool quiet = false;
};

ParameterOverrides parse_params(const std::vector<std::string>& params) {
  ParameterOverrides out;
  for (const auto& p : params) {
    const auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error(fmt::format("--param '{}' must be written name=value", p));
    out[p.substr(0, eq)] = p.substr(eq + 1);
  }
  return out;
}

RefineOptions refine_options(const RefineArgs& a) {
  RefineOptions o;
  o.levels = a.levels;
  o.threads = a.threads;
  o.boundary = a.boundary == "none" ? BoundaryInterpolation::None
               : a.boundary == "edges" ? BoundaryInterpolation::EdgesOnly
                                       : BoundaryInterpolation::EdgesAndCorners;
  o.crease_method = a.crease_method == "chaikin" ? CreaseMethod::Chaikin : CreaseMethod::Uniform;
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void run(const RefineArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  if (is_curve_scheme(a.scheme))  // polylines: tools/subdiv/curve_refine.cpp
    return refine_curves_command({a.mesh, a.scheme, a.output, a.levels, parse_params(a.params), a.threads, a.quiet});
  check_output_path(a.output);
  std::unique_ptr<tbb::global_control> thread_limit;
  if (a.threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, a.threads);
  const auto scheme = load_scheme(a.scheme, parse_params(a.params));
  const MeshData mesh = read_mesh(a.mesh);
  if (mesh.face_count() == 0)
    throw Error(fmt::format("{}: the mesh has no faces to refine{}", a.mesh,
                            mesh.line_count() ? "; its polylines need a curve scheme (e.g. --scheme chaikin)" : ""));
  Level base = level_from_mesh(mesh, a.mesh);
  check_fits_in_memory(*scheme, base, a.levels);

  const RefineOptions options = refine_options(a);
  Progress progress;
  progress.say(fmt::format("refining topology: {} levels of {}", a.levels, scheme->name));
  Hierarchy h = refine_topology(*scheme, std::move(base), options);
  progress.say("building stencils");
  build_stencils(*scheme, h, options);
  std::vector<std::vector<double>> positions{mesh.positions};
  for (int l = 0; l < a.levels; ++l) {
    progress.say(fmt::format("level {}/{}: {} faces", l + 1, a.levels, h.levels[l + 1].face_count()));
    positions.push_back(h.stencils[l].apply(positions.back(), 3));
  }
  progress.say(fmt::format("writing {}", a.output));
  write_levels(a.output, h, positions);
  progress.done();
  if (!a.quiet) {
    const Level& fine = h.levels.back();
    fmt::print("{}: {} level(s) of {} -> {} vertices, {} faces in {:.3f} s -> {}\n", a.mesh, a.levels,
               scheme->name, fine.vertex_count, fine.face_count(), seconds_since(t0), a.output);
  }
}

}  // namespace

void add_refine_command(CLI::App& app) {
  auto args = std::make_shared<RefineArgs>();
  auto* cmd = app.add_subcommand("refine", "Refine a mesh with a scheme and write the result");
  cmd->add_option("mesh", args->mesh, "Input mesh (" + supported_input_formats() + ")")->required();
  cmd->add_option("-s,--scheme", args->scheme, "Scheme name (see `subdiv schemes`) or path to a .json file")
      ->capture_default_str();
  cmd->add_option("-l,--levels", args->levels, "Number of refinement levels")->check(CLI::Range(0, 30))->capture_default_str();
  cmd->add_option("-o,--output", args->output,
                  "Output file: .vtp (finest level) or .pvd (all levels) for ParaView, or .obj, .off, .ply, .stl")
      ->required();
  cmd->add_option("-p,--param", args->params, "Scheme parameter, name=value (repeatable), e.g. --param beta=warren");
  cmd->add_option("--boundary", args->boundary,
                  "Boundary interpolation, as OpenSubdiv names it: edges-and-corners (boundary corners stay), "
                  "edges (corners follow the boundary curve), none")
      ->check(CLI::IsMember({"none", "edges", "edges-and-corners"}))
      ->capture_default_str();
  cmd->add_option("--crease-method", args->crease_method, "How semi-sharp crease sharpness decays: uniform or chaikin")
      ->check(CLI::IsMember({"uniform", "chaikin"}))
      ->capture_default_str();
  cmd->add_option("-j,--threads", args->threads, "Worker threads (0: all cores); results are identical for any count")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  cmd->footer("Example: subdiv refine examples/meshes/cube.obj --scheme catmull-clark --levels 3 -o cube.pvd");
  cmd->callback([args] { run(*args); });
}

}  // namespace subdiv::cli
