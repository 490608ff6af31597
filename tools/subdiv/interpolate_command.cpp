// `subdiv interpolate MESH --scheme S [--select ...] [--lambda x] -o OUT`: progressive
// interpolation, so that the limit surface passes through the chosen vertices.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "commands.h"
#include "shared_options.h"
#include "curve_interpolate.h"
#include "curve_refine.h"
#include "interpolate_common.h"
#include "framework/pipeline/interpolate_request.h"
#include "framework/pipeline/scheme_source.h"
#include "framework/pipeline/thread_limit.h"
#include "framework/interpolation/limit_selection.h"
#include "framework/interpolation/progressive.h"
#include "framework/io/formats.h"
#include "framework/io/mesh_level.h"
#include "framework/io/vertex_values.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "level_output.h"
#include "progress.h"
#include "framework/util/quoted_text.h"
#include "safe_print.h"

namespace subdiv::cli {
namespace {

namespace fs = std::filesystem;

struct InterpolateArgs {
  std::string mesh, scheme = "catmull-clark", output, refined;
  std::string select = "all", lambda;
  std::vector<std::string> params, vertex_params;
  std::string boundary = "edges-and-corners";
  double tolerance = -1;  // < 0: 1e-10 times the bounding-box diagonal
  int max_iterations = 1000;
  int levels = 3;
  int threads = 0;
  bool verbose = false, quiet = false;
  bool force = false;  // --force: -o or --refined may be the input mesh
};

void check_directory(const fs::path& out) {
  const fs::path dir = out.parent_path();
  std::error_code ec;  // (a name too long to look up is "does not exist" too)
  if (!dir.empty() && !fs::is_directory(dir, ec))
    throw Error(fmt::format("cannot write {}: directory {} does not exist", subdiv::quoted(out.string()), subdiv::quoted(dir.string())));
}

std::optional<double> parse_number(const std::string& text) {
  double x = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return x;
}

double distance(const double* a, const double* b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Per level, the vertex point of each base vertex.
std::vector<std::vector<Index>> descendants_per_level(const Hierarchy& h) {
  std::vector<std::vector<Index>> at(h.levels.size());
  at[0].resize(h.levels[0].vertex_count);
  for (Index v = 0; v < h.levels[0].vertex_count; ++v) at[0][v] = v;
  for (size_t l = 0; l < h.origins.size(); ++l) {
    std::vector<Index> child_of(size_t(h.levels[l].vertex_count), kNone);
    for (size_t c = 0; c < h.origins[l].kind.size(); ++c)
      if (h.origins[l].kind[c] == OriginKind::Vertex) child_of[h.origins[l].parent[c]] = Index(c);
    at[l + 1].resize(at[l].size());
    for (size_t v = 0; v < at[l].size(); ++v) at[l + 1][v] = at[l][v] == kNone ? kNone : child_of[at[l][v]];
  }
  return at;
}

void write_refined(const fs::path& out, const Hierarchy& h, const std::vector<double>& control,
                   const std::vector<double>& targets, const std::vector<double>& limit,
                   const std::vector<std::uint8_t>& moving) {
  const auto at = descendants_per_level(h);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<MeshData> meshes;
  meshes.reserve(h.levels.size());
  std::vector<double> positions = control;
  for (size_t l = 0; l < h.levels.size(); ++l) {
    if (l > 0) positions = h.stencils[l - 1].apply(positions, 3);
    meshes.push_back(mesh_from_level(h.levels[l], positions));
  }
  std::vector<OutputLevel> levels;
  for (size_t l = 0; l < h.levels.size(); ++l) {
    const Index count = h.levels[l].vertex_count;
    DataArray base{"base_vertex", 1, std::vector<double>(count, -1.0), true};
    DataArray role{"interpolated", 1, std::vector<double>(count, -1.0), true};
    DataArray target_distance{"target_distance", 1, std::vector<double>(count, nan), false};
    DataArray limit_residual{"limit_residual", 1, std::vector<double>(count, nan), false};
    const std::vector<double>& p = meshes[l].positions;
    for (size_t v = 0; v < at[l].size(); ++v) {
      const Index c = at[l][v];
      if (c == kNone) continue;
      base.values[c] = double(v);
      role.values[c] = moving[v] ? 1.0 : 0.0;
      target_distance.values[c] = distance(&p[3 * size_t(c)], &targets[3 * v]);
      limit_residual.values[c] = distance(&limit[3 * v], &targets[3 * v]);
    }
    OutputLevel level;
    level.mesh = &meshes[l];
    level.level = int(l);
    level.point_data = {std::move(base), std::move(role), std::move(target_distance), std::move(limit_residual)};
    levels.push_back(std::move(level));
  }
  if (lowercase_extension(out) == ".vtp") write_vtp(out, levels.back());
  else write_pvd(out, levels);
}

// --lambda: one number (the scheme's parameter, range-checked by the loader) or a file of
// per-vertex values (as --vertex-param lambda=FILE).
void apply_lambda(const InterpolateArgs& a, InterpolateRequest& request, Index vertex_count) {
  if (a.lambda.empty()) return;
  const std::optional<double> value = parse_number(a.lambda);
  std::error_code ec;
  if (!value && !fs::is_regular_file(a.lambda, ec))
    throw Error(fmt::format("--lambda {} is neither a number nor a file of per-vertex values", subdiv::quoted(a.lambda)));
  if (!declares_parameter(load_surface_sequence(request.scheme, a.levels, request.scheme.parameters), "lambda"))
    throw Error(fmt::format("--lambda: no scheme in {} has a parameter lambda; Lin et al. 2015's shape control is "
                            "--scheme catmull-clark-shape:1,catmull-clark", subdiv::quoted(a.scheme)));
  if (value) {
    request.scheme.parameters["lambda"] = a.lambda;
    return;
  }
  if (request.vertex_parameters.count("lambda")) throw Error("--lambda FILE and --vertex-param lambda=...: give one");
  request.vertex_parameters["lambda"] = read_vertex_values(a.lambda, "lambda", vertex_count);
}

void check_outputs(const InterpolateArgs& a, bool curve) {
  check_output_not_input(a.mesh, a.output, a.force);
  if (!a.refined.empty()) check_output_not_input(a.mesh, a.refined, a.force, "--refined");
  check_output_path(a.output);
  check_directory(a.output);
  if (!a.refined.empty()) {
    const std::string ext = lowercase_extension(a.refined);
    if (ext != ".pvd" && ext != ".vtp")
      throw Error(fmt::format("--refined {}: use .pvd (every level, for ParaView's time slider) or .vtp (the "
                              "finest level); they carry the per-point residuals", subdiv::quoted(a.refined)));
    check_directory(a.refined);
    if (fs::absolute(a.refined) == fs::absolute(a.output))
      throw Error("--refined and -o name the same file; give two names");
  }
  if (curve) check_curve_outputs(a.output, a.refined);
}

InterpolateRequest request_from(const InterpolateArgs& a, MeshData mesh) {
  InterpolateRequest r;
  r.moving = read_selection(a.select, mesh.vertex_count());
  r.mesh = std::move(mesh);
  r.mesh_name = a.mesh;
  r.scheme.text = a.scheme;
  r.scheme.parameters = parse_params(a.params);
  r.levels = a.levels;
  r.tolerance = a.tolerance;
  r.max_iterations = a.max_iterations;
  r.boundary = boundary_from_name(a.boundary);
  r.vertex_parameters = read_vertex_parameter_files(vertex_param_files(a.vertex_params), r.mesh.vertex_count());
  return r;
}

void write_surface_interpolation(const InterpolateArgs& a, const InterpolateResult& r, const MeshData& mesh,
                                 const std::vector<std::uint8_t>& moving, Progress& progress) {
  Hierarchy refined;
  if (!a.refined.empty()) {
    progress.say(fmt::format("refining {} levels", r.sequence.total_levels));
    refined = refine_for_limit(r.sequence, r.base, r.options);
  }
  progress.say(fmt::format("writing {}", a.output));
  MeshData out = mesh;
  out.positions = r.iteration.control;
  write_mesh(a.output, out);
  if (!a.refined.empty()) {
    progress.say(fmt::format("writing {}", a.refined));
    write_refined(a.refined, refined, r.iteration.control, mesh.positions, r.iteration.limit, moving);
  }
  progress.done();
}

void run(const InterpolateArgs& a) {
  const bool curve = is_curve_scheme(a.scheme);
  check_outputs(a, curve);
  if (a.max_iterations < 0) throw Error("--max-iter must be 0 or more");
  if (curve && !a.lambda.empty())
    throw Error(fmt::format("--lambda: {} is a curve scheme; Lin et al. 2015's shape parameter is for surfaces", subdiv::quoted(a.scheme)));
  const ThreadLimit thread_limit(a.threads, "--threads");
  if (!thread_limit.note().empty()) print_safe(stderr, "subdiv: note: {}\n", thread_limit.note());

  Progress progress(false, a.quiet);
  progress.say(fmt::format("reading {}", a.mesh));  // the bar `subdiv refine` draws while reading
  const MeshData mesh = read_mesh(a.mesh, [&progress](double done) { progress.fraction(done); });
  InterpolateRequest request = request_from(a, mesh);
  apply_lambda(a, request, mesh.vertex_count());
  const std::vector<std::uint8_t> moving = request.moving;
  std::vector<std::string> log;
  show_iterations(request, progress, a.verbose, log);
  const InterpolateResult r = interpolate_mesh(std::move(request));
  if (r.curve) write_curve_interpolation({a.output, a.refined, a.levels, moving}, r, mesh, progress);
  else write_surface_interpolation(a, r, mesh, moving, progress);

  warn_if_stopped(r, r.curve ? "the polylines written are" : "the control mesh written is");
  if (a.quiet) return;
  if (r.curve)
    print_safe("{}: {} points on {} polyline{}; curve scheme {}\n", a.mesh, r.curve_base.vertex_count,
               r.curve_base.polyline_count(), r.curve_base.polyline_count() == 1 ? "" : "s", r.curve->name);
  else
    print_safe("{}: {} vertices, {} faces; scheme {}\n", a.mesh, r.base.vertex_count, r.base.face_count(), a.scheme);
  print_safe("limit: {}\n", r.limit_description);
  print_iterations(r, log, r.curve ? "points" : "vertices", a.verbose);
  print_safe("wrote {}", a.output);
  const int levels = r.curve ? a.levels : r.sequence.total_levels;
  if (!a.refined.empty()) print_safe(" and {} ({} levels)", a.refined, levels);
  print_safe("\n");
}

}  // namespace

void add_interpolate_command(CLI::App& app) {
  auto args = std::make_shared<InterpolateArgs>();
  auto* cmd = app.add_subcommand("interpolate",
                                 "Move control vertices so that the limit surface (or, for polylines, the limit "
                                 "curve) passes through them (progressive interpolation, global or local)");
  cmd->add_option("mesh", args->mesh, "Input mesh (" + supported_input_formats() + "); its vertices are the targets")
      ->required();
  cmd->add_option("-s,--scheme", args->scheme,
                  "Scheme or sequence whose limit surface interpolates, e.g. catmull-clark, loop, or Lin et al. 2015's "
                  "catmull-clark-shape:1,catmull-clark (the last scheme repeats); for polylines a curve scheme, "
                  "e.g. cubic-bspline or chaikin")
      ->capture_default_str();
  cmd->add_option("--select", args->select,
                  "Vertices to interpolate (the others stay fixed): all, a comma list of 0-based ids, or a file of "
                  "ids ('#' comments)")
      ->capture_default_str();
  cmd->add_option("--lambda", args->lambda,
                  "The shape parameter of Lin et al. 2015, in (7/20, 1]: one number (as --param lambda=x), or a file with one "
                  "value per vertex (as --vertex-param lambda=FILE)");
  add_param_option(cmd, args->params);
  add_vertex_param_option(cmd, args->vertex_params);
  cmd->add_option("--tol", args->tolerance,
                  "Stop when every selected vertex's limit point is this close to it (model units; default 1e-10 "
                  "times the bounding-box diagonal)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-iter", args->max_iterations, "Iteration cap")->check(CLI::NonNegativeNumber)->capture_default_str();
  cmd->add_option("-o,--output", args->output,
                  "The new control mesh (.obj, .off, .ply, .stl, .vtp; polylines: .obj or .vtp)")->required();
  cmd->add_option("--refined", args->refined,
                  "Also write the new control mesh refined --levels times (.pvd or .vtp) with per-point arrays "
                  "target_distance, limit_residual, interpolated and base_vertex");
  cmd->add_option("-l,--levels", args->levels, "Levels for --refined")->check(CLI::Range(1, 12))->capture_default_str();
  add_boundary_option(cmd, "--boundary", args->boundary);
  cmd->add_option("-j,--threads", args->threads, "Worker threads (0: all cores)")->check(CLI::NonNegativeNumber);
  cmd->add_flag("-v,--verbose", args->verbose, "Print the residuals of every iteration");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  cmd->add_flag("--force", args->force, "Write -o and --refined even where one is the input mesh, which is then lost");
  cmd->footer("Example: subdiv interpolate examples/meshes/cross.obj --scheme catmull-clark-shape:1,catmull-clark "
              "--lambda 0.5 --select 0,1,2,3 -o cross-interp.obj --refined cross-interp.pvd\n"
              "Polylines: subdiv interpolate examples/curves/open-zigzag.obj --scheme cubic-bspline -o zigzag-interp.obj");
  cmd->callback([args] { run(*args); });
}

}  // namespace subdiv::cli
