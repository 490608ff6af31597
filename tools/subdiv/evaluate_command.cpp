// `subdiv evaluate MESH [-s SCHEME] (--at POINTS.csv | --samples N) [--derivatives 0|1|2] -o OUT`:
// points of the limit surface at given (face, u, v), with OpenSubdiv Bfr's parameterisation,
// or the limit surface sampled N x N per face as a crack-free mesh (framework/limit,
// docs/limit.md).
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <tbb/global_control.h>

#include "commands.h"
#include "shared_options.h"
#include "framework/io/formats.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/pipeline/adaptive_request.h"
#include "framework/pipeline/approximation_request.h"
#include "framework/pipeline/level_distance.h"
#include "framework/limit/limit_surface.h"
#include "framework/limit/tessellation.h"
#include "framework/pipeline/limit_mesh.h"
#include "framework/pipeline/phase_progress.h"
#include "framework/pipeline/evaluate_request.h"
#include "framework/pipeline/points_file.h"
#include "framework/io/mesh_write.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/atomic_file.h"
#include "framework/util/checked_file_stream.h"
#include "framework/util/error.h"
#include "framework/util/memory_limit.h"
#include "framework/util/parallel_for_all.h"
#include "framework/util/quoted_text.h"
#include "progress.h"
#include "adaptive_refine_option.h"
#include "level_output.h"
#include "safe_print.h"

namespace subdiv::cli {
namespace {

struct EvaluateArgs {
  std::string mesh, scheme = "catmull-clark", at, output;
  std::vector<std::string> params;
  std::string boundary = "edges-and-corners", crease_method = "uniform";
  std::string fvar_boundary = "all";
  bool boundary_given = false, crease_method_given = false, fvar_boundary_given = false;  // else the mesh's tags
  bool derivatives_given = false;  // --derivatives: only --at writes derivatives
  std::string features;
  double feature_angle = -1;
  int derivatives = 1;
  int samples = 0;
  int adaptive = -1;  // --adaptive L; < 0: not given
  double tolerance = 0;  // --tolerance T with --adaptive; 0: features only
  std::string transitions = "polygons";  // --transitions with --adaptive
  int level_distance = -1;  // --level-distance L; < 0: not given
  bool limit = false;
  std::string approximate, bezier_net;  // --approximate bezier [--bezier-net OUT.vtu]
  int threads = 0;
  bool force = false;  // --force: -o may be the input mesh or the --at points file
};

// -o naming the --at file would replace the points with their evaluation; as refine's
// check_output_not_input does for the mesh, refused unless --force.
void check_output_not_points(const EvaluateArgs& a) {
  std::error_code ec;
  if (a.at.empty() || a.force || !std::filesystem::equivalent(a.at, a.output, ec) || ec) return;
  throw Error(fmt::format("-o {} is the points file --at {}: writing would lose the points; name another output, "
                          "or add --force to overwrite it",
                          subdiv::quoted(a.output), subdiv::quoted(a.at)));
}

// The positions (and derivatives), then each face-varying channel's values, per point.
void write_csv(const std::filesystem::path& out, const SurfacePoints& queries, const EvaluatedPoints& points,
               int derivatives, const std::vector<std::string>& fvar_names, const std::vector<EvaluatedPoints>& fvar,
               Progress& progress) {
  write_file_atomically(out, [&](const std::filesystem::path& tmp) {
    CheckedFileStream f(tmp, out);  // a full disk is an error with the fix, never a short file
    f << "face,u,v,x,y,z";
    if (derivatives > 0) f << ",du_x,du_y,du_z,dv_x,dv_y,dv_z";
    if (derivatives > 1) f << ",duu_x,duu_y,duu_z,duv_x,duv_y,duv_z,dvv_x,dvv_y,dvv_z";
    for (size_t k = 0; k < fvar.size(); ++k)
      for (int c = 0; c < fvar[k].channels; ++c) f << ',' << fvar_names[k] << '_' << c;
    f << '\n';
    // NaN (a derivative that does not exist) as "nan", every number in its shortest exact form.
    auto number = [](double x) { return std::isnan(x) ? std::string("nan") : fmt::format("{}", x); };
    std::vector<const std::vector<double>*> columns{&points.position};
    if (derivatives > 0) columns.insert(columns.end(), {&points.du, &points.dv});
    if (derivatives > 1) columns.insert(columns.end(), {&points.duu, &points.duv, &points.dvv});
    constexpr size_t kRowsPerReport = 1 << 16;
    for (size_t i = 0; i < queries.size(); ++i) {
      if (i % kRowsPerReport == 0) progress.fraction(double(i) / double(queries.size()));
      f << fmt::format("{},{},{}", queries.faces[i], queries.uv[2 * i], queries.uv[2 * i + 1]);
      for (const auto* d : columns)
        for (size_t c = 0; c < 3; ++c) f << ',' << number((*d)[3 * i + c]);
      for (const EvaluatedPoints& e : fvar)
        for (size_t c = 0; c < size_t(e.channels); ++c) f << ',' << number(e.position[i * size_t(e.channels) + c]);
      f << '\n';
    }
    f.close();
  });
}

// The points file, each point checked on the surface, with a bar while it is read.
SurfacePoints read_points(const std::string& file, const LimitSurface& surface, Progress& progress) {
  progress.say(fmt::format("reading {}", file));
  SurfacePoints points = read_points_file(
      file, [&surface](Index face, double u, double v) { return surface.check(face, u, v); },
      [&progress](double done) { progress.fraction(done); });
  progress.done();
  return points;
}

// The mesh written with the bar `subdiv refine` draws while writing, after its warnings
// (sample points without a normal, limit_mesh.h).
void write_with_bar(const std::string& path, const MeshData& mesh, Progress& progress) {
  for (const std::string& w : mesh.warnings) print_safe(stderr, "subdiv: warning: {}\n", w);
  progress.say(fmt::format("writing {}", path));
  write_mesh(path, mesh, [&progress](double done) { progress.fraction(done); });
  progress.done();
}

// The command line's options as a pipeline request (framework/pipeline/evaluate_request.h).
// The mesh is read here, with the reading bar `subdiv refine` draws (io/io_progress.h).
EvaluateRequest evaluate_request(const EvaluateArgs& a, Progress& progress) {
  EvaluateRequest r;
  progress.say(fmt::format("reading {}", a.mesh));
  r.mesh = read_mesh(a.mesh, [&progress](double done) { progress.fraction(done); });
  r.mesh_name = a.mesh;
  progress.done();
  r.scheme.text = a.scheme;
  r.scheme.parameters = parse_params(a.params);
  if (a.boundary_given) r.shape.boundary = boundary_from_name(a.boundary, "--boundary");
  if (a.crease_method_given) r.shape.crease_method = crease_method_from_name(a.crease_method, "--crease-method");
  if (a.fvar_boundary_given) r.shape.face_varying = face_varying_from_name(a.fvar_boundary, "--fvar-boundary");
  r.feature_file = a.features;
  r.feature_angle = a.feature_angle;
  r.progress = progress.phase_callback();
  r.progress_fraction = progress.fraction_callback();
  return r;
}

// --approximate bezier: Loop & Schaefer's patches (framework/pipeline/approximation_request.h),
// written as --samples or --at would write the exact limit, with their distance to it.
void write_approximation_csv(const std::filesystem::path& out, const SurfacePoints& q, const ApproximatedPoints& p) {
  write_file_atomically(out, [&](const std::filesystem::path& tmp) {
    CheckedFileStream f(tmp, out);
    f << "face,u,v,x,y,z,nx,ny,nz,limit_distance\n";
    for (size_t i = 0; i < q.size(); ++i) {
      f << fmt::format("{},{},{}", q.faces[i], q.uv[2 * i], q.uv[2 * i + 1]);
      for (const auto* d : {&p.positions, &p.normals})
        for (size_t c = 0; c < 3; ++c) f << ',' << fmt::format("{}", (*d)[3 * i + c]);
      f << ',' << fmt::format("{}", p.distances.per_point[i]) << '\n';
    }
    f.close();
  });
}

// --approximate gregory: Loop, Schaefer, Ni & Castaño's patches, written as bezier's are
// (without control nets: a Gregory patch is not a VTK cell type).
void run_gregory(const EvaluateArgs& a, Progress& progress) {
  const PreparedEvaluation prepared = prepare_evaluation(evaluate_request(a, progress));
  progress.done();
  for (const std::string& w : prepared.warnings) print_safe(stderr, "subdiv: warning: {}\n", w);
  const GregoryApproximation patches = gregory_approximation_patches(prepared);
  if (patches.steps > 0) print_safe("subdiv: {}\n", approximation_level_note(patches.steps, patches.patches.size()));
  if (a.samples > 0) {
    ApproximationDistances distances;
    MeshData mesh = approximated_limit_mesh(prepared, patches, a.samples, distances);
    print_safe("subdiv: {}\n", approximation_summary(distances, ApproximationKind::Gregory));
    write_with_bar(a.output, mesh, progress);
  } else {
    const LimitSurface& surface = *prepared.surface;
    const SurfacePoints q =
        read_points(a.at, surface, progress);
    const ApproximatedPoints points = approximate_points(prepared, patches, q.faces, q.uv);
    print_safe("subdiv: {}\n", approximation_summary(points.distances, ApproximationKind::Gregory));
    write_approximation_csv(a.output, q, points);
  }
}

void run_approximation(const EvaluateArgs& a, Progress& progress) {
  if (a.approximate != "bezier" && a.approximate != "gregory")
    throw Error(fmt::format("--approximate {}: the approximations are bezier (Loop & Schaefer's bicubic patches) "
                            "and gregory (Loop, Schaefer, Ni & Castaño's Gregory patches)",
                            subdiv::quoted(a.approximate)));
  if (a.approximate == "gregory") {
    if (!a.bezier_net.empty())
      throw Error("--bezier-net goes with --approximate bezier: Gregory patches are rational inside and have no "
                  "Bézier control net to write");
    return run_gregory(a, progress);
  }
  if (!a.bezier_net.empty() && lowercase_extension(a.bezier_net) != ".vtu")
    throw Error(fmt::format("--bezier-net {}: the control nets are written as VTK Bézier quadrilaterals (.vtu)",
                            subdiv::quoted(a.bezier_net)));
  const PreparedEvaluation prepared = prepare_evaluation(evaluate_request(a, progress));
  progress.done();
  for (const std::string& w : prepared.warnings) print_safe(stderr, "subdiv: warning: {}\n", w);
  const BezierApproximation patches = approximation_patches(prepared);
  if (patches.steps > 0) print_safe("subdiv: {}\n", approximation_level_note(patches.steps, patches.patches.size()));
  // The control nets go into a temporary that becomes --bezier-net only once -o is in place,
  // so a failure of either write leaves neither file.
  StagedFiles nets;
  const auto write_nets_then = [&](const ApproximationDistances& distances, const auto& write_output) {
    if (!a.bezier_net.empty()) {
      CheckedFileStream f(nets.stage(a.bezier_net), a.bezier_net);
      f << bezier_control_net_vtu(patches, distances.per_face);
      f.close();
    }
    write_output();
    nets.commit();
  };
  if (a.samples > 0) {
    ApproximationDistances distances;
    MeshData mesh = approximated_limit_mesh(prepared, patches, a.samples, distances);
    print_safe("subdiv: {}\n", approximation_summary(distances));
    write_nets_then(distances, [&] { write_with_bar(a.output, mesh, progress); });
  } else {
    const LimitSurface& surface = *prepared.surface;
    const SurfacePoints q =
        read_points(a.at, surface, progress);
    const ApproximatedPoints points = approximate_points(prepared, patches, q.faces, q.uv);
    print_safe("subdiv: {}\n", approximation_summary(points.distances));
    write_nets_then(points.distances, [&] { write_approximation_csv(a.output, q, points); });
  }
}

// "cube.obj: limit of catmull-clark at 3 point(s), with first derivatives in 0.020 s -> out.csv",
// as `subdiv refine` says what it wrote.
std::string derivatives_said(int derivatives) {
  return derivatives == 0 ? "" : derivatives == 1 ? ", with first derivatives" : ", with first and second derivatives";
}

void run_mode(const EvaluateArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const int modes = int(!a.at.empty()) + int(a.samples > 0) + int(a.adaptive >= 0) + int(a.level_distance >= 0);
  if (modes != 1)
    throw Error("give one of --at POINTS.csv (points at given parameters), --samples N (a mesh of the surface), "
                "--adaptive L (a mesh refined where the surface is irregular) or --level-distance L (level L's "
                "vertices on the limit, with their distance to it)");
  if (a.level_distance >= 0 && !a.approximate.empty())
    throw Error("--approximate goes with --samples N or --at POINTS.csv, not --level-distance");
  if (a.limit && a.adaptive < 0) throw Error("--limit goes with --adaptive L");
  if (a.derivatives_given && (a.at.empty() || !a.approximate.empty()))
    throw Error("--derivatives goes with --at POINTS.csv: only its .csv has derivative columns (with --approximate "
                "bezier or gregory, normals)");
  if (a.tolerance != 0 && a.adaptive < 0) throw Error("--tolerance goes with --adaptive L");
  if (a.transitions != EvaluateArgs{}.transitions && a.adaptive < 0) throw Error("--transitions goes with --adaptive L");
  if (!a.approximate.empty() && a.adaptive >= 0)
    throw Error("--approximate goes with --samples N or --at POINTS.csv, not --adaptive");
  if (a.approximate.empty() && !a.bezier_net.empty()) throw Error("--bezier-net goes with --approximate bezier");
  check_output_not_input(a.mesh, a.output, a.force);
  check_output_not_points(a);
  // Every file this run writes, before any work: a bad path found after the patches or
  // samples are made would cost all of it; and a folder is named as one, not as a name
  // without an extension.
  for (const std::string& out : {a.output, a.bezier_net})
    if (!out.empty()) check_writable(out);
  const std::string ext = lowercase_extension(a.output);
  if (!a.at.empty() && ext != ".csv")
    throw Error(fmt::format("-o {}: --at writes .csv (face,u,v,x,y,z[,du_*,dv_*[,duu_*,duv_*,dvv_*]])", subdiv::quoted(a.output)));
  if ((a.samples > 0 || a.adaptive >= 0 || a.level_distance >= 0) && ext == ".csv")
    throw Error(fmt::format("-o {}: --samples, --adaptive and --level-distance write a mesh (.vtp, .obj, .ply, .off, .stl)",
                            subdiv::quoted(a.output)));
  if (a.at.empty()) check_mesh_output_format(a.output);
  const int threads = a.threads > 0 ? a.threads : int(tbb::this_task_arena::max_concurrency());
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  Progress progress;
  if (!a.approximate.empty()) return run_approximation(a, progress);
  if (a.level_distance >= 0) {
    const LevelDistance d = level_distance(evaluate_request(a, progress), a.level_distance);
    progress.done();
    print_safe("subdiv: {}\n", level_distance_summary(d));
    write_with_bar(a.output, d.mesh, progress);
    return;
  }
  if (a.adaptive >= 0) {  // the same as subdiv refine --adaptive L (adaptive_refine_option.cpp)
    AdaptiveRequest request = adaptive_request_from(evaluate_request(a, progress), a.adaptive, a.tolerance, a.limit);
    request.transitions = transitions_from_name(a.transitions);
    AdaptiveResult r = refine_adaptive_request(std::move(request));
    progress.done();
    for (const std::string& w : r.warnings) print_safe(stderr, "subdiv: warning: {}\n", w);
    print_safe("subdiv: {}\n", adaptive_summary(r));
    write_with_bar(a.output, adaptive_mesh_data(std::move(r.mesh), std::move(r.point_arrays), std::move(r.face_varying)), progress);
    return;
  }
  const PreparedEvaluation prepared = prepare_evaluation(evaluate_request(a, progress));
  progress.done();
  for (const std::string& w : prepared.warnings) print_safe(stderr, "subdiv: warning: {}\n", w);
  const auto say = progress.phase_callback();
  const auto fraction = progress.fraction_callback();
  if (a.samples > 0) {
    const MeshData sampled = sampled_limit_mesh(prepared, a.samples, say, fraction);
    write_with_bar(a.output, sampled, progress);
    print_safe("{}: limit of {}, {} segment(s) per face edge -> {} vertices, {} faces in {:.3f} s -> {}\n", a.mesh,
               prepared.scheme_label, a.samples, sampled.positions.size() / 3, sampled.face_count(), seconds_since(t0),
               a.output);
    return;
  }
  const LimitSurface& surface = *prepared.surface;
  const SurfacePoints queries =
      read_points(a.at, surface, progress);
  const std::vector<Index>& faces = queries.faces;
  const std::vector<double>& uv = queries.uv;
  std::vector<std::string> fvar_names;
  std::vector<EvaluatedPoints> fvar;
  for (size_t k = 0; k < prepared.face_varying.size(); ++k) {
    fvar_names.push_back(prepared.face_varying[k].name);
    fvar.push_back(evaluate_face_varying(prepared, k, faces, uv, 0));
  }
  EvaluatedPoints points;
  {
    const PhaseProgress bar(say, fraction, fmt::format("evaluating {} points", faces.size()));
    points = evaluate_limit_points(prepared, faces, uv, a.derivatives);
  }
  progress.say(fmt::format("writing {}", a.output));
  write_csv(a.output, queries, points, a.derivatives, fvar_names, fvar, progress);
  progress.done();
  print_safe("{}: limit of {} at {} point(s){} in {:.3f} s -> {}\n", a.mesh, prepared.scheme_label, faces.size(),
             derivatives_said(a.derivatives), seconds_since(t0), a.output);
}

// What the run does and the fix when it runs out of memory (util/memory_limit.h), naming
// the option the user gave: "fewer levels" means nothing to --samples.
std::pair<std::string, std::string> memory_advice(const EvaluateArgs& a) {
  if (a.samples > 0)
    return {fmt::format("sampling {} with {} segments per face edge", subdiv::quoted(a.mesh), a.samples),
            kFewerSamplesAdvice};
  if (a.adaptive >= 0)
    return {fmt::format("refining {} adaptively to level {}", subdiv::quoted(a.mesh), a.adaptive),
            "ask for a lower --adaptive level or a larger --tolerance"};
  if (a.level_distance >= 0)
    return {fmt::format("moving level {} of {} onto the limit", a.level_distance, subdiv::quoted(a.mesh)),
            "ask for a lower --level-distance"};
  return {fmt::format("evaluating the points of {} on {}", subdiv::quoted(a.at), subdiv::quoted(a.mesh)),
          "evaluate fewer points at a time (split the --at file), or ask for fewer --derivatives"};
}

// --samples outside 1 to kMaxSegments in the library's words (tessellation.h), where CLI11's
// Range would say only "Value 2000 not in range 1 to 1024". A value that is no whole number is
// left to CLI11's conversion, which names it.
CLI::Validator samples_range() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        int n = 0;
        if (!CLI::detail::lexical_cast(text, n)) return {};
        const std::string why = segments_out_of_range(n);
        return why.empty() ? why : fmt::format("{} is out of range; {}", text, why);
      },
      fmt::format("INT in [1 - {}]", kMaxSegments));
}

void run(const EvaluateArgs& a) {
  const auto [during, fix] = memory_advice(a);
  advising_when_out_of_memory(during, fix, [&] { run_mode(a); });
}

}  // namespace

void add_evaluate_command(CLI::App& app) {
  auto args = std::make_shared<EvaluateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "evaluate", "Points of the limit surface at given (face, u, v), exactly (OpenSubdiv Bfr's parameterisation)");
  cmd->add_option("mesh", args->mesh, "Input mesh")->required()->check(CLI::ExistingFile);
  cmd->add_option("-s,--scheme", args->scheme, "Scheme name or .json file (binary quad or triangle, dual, sqrt3 or mid-edge split)")
      ->capture_default_str();
  add_param_option(cmd, args->params);
  add_boundary_option(cmd, "--boundary", args->boundary);
  add_crease_method_option(cmd, args->crease_method);
  cmd->add_option("--features", args->features,
                  "Feature sidecar (JSON): creases and corners, as subdiv refine --features")
      ->check(CLI::ExistingFile);
  cmd->add_option("--feature-angle", args->feature_angle,
                  "Make every edge whose faces' normals differ by more than DEG degrees an infinitely sharp crease")
      ->check(CLI::Range(0.0, 180.0));  // as refine's: a negative angle is no angle, not "off"
  add_fvar_boundary_option(cmd, args->fvar_boundary,
                           "Face-varying data (OBJ vt: UVs with seams), evaluated at the same points (columns NAME_0, "
                           "NAME_1, ... after the others)");
  cmd->add_option("--at", args->at,
                  "Points to evaluate: a .csv with the header face,u,v (any case, names and fields may be in double "
                  "quotes), then one point per row (a u or v too small for a double, as 1e-400, is 0)");
  cmd->add_option("--samples", args->samples,
                  "Instead of --at: the surface as a crack-free mesh, N x N quads per quad, N^2 triangles per "
                  "triangle (faces with other sizes: N/2 x N/2 per sub-face, N even), with normals; face-varying "
                  "data (UVs) sampled at every corner, split at its seams; rational weights honoured; Normals "
                  "(0,0,0), with a warning, where the surface has none")
      ->check(samples_range());
  cmd->add_option("--adaptive", args->adaptive,
                  "Instead of --at: the mesh refined to level L only where it is irregular (extraordinary vertices, "
                  "creases, sharp vertices, faces of another shape), watertight (coarse faces take the finer "
                  "vertices along their edges), with cell arrays face_level and base_face")
      ->check(CLI::Range(0, kMaxAdaptiveLevel));
  add_tolerance_option(cmd, args->tolerance);
  add_transitions_option(cmd, args->transitions);
  cmd->add_flag("--limit", args->limit, "With --adaptive: every vertex on the limit surface");
  cmd->add_option("--level-distance", args->level_distance,
                  "Instead of --at: uniform level L's vertices moved onto the limit surface (at their own (face, u, "
                  "v)), with the point array level_distance (how far level L is from the limit there) and the "
                  "largest and mean distance printed")
      ->check(CLI::Range(0, 12));
  cmd->add_option("--approximate", args->approximate,
                  "bezier: instead of the exact limit, Loop & Schaefer's (2008) bicubic patches, one per quad of a "
                  "mesh with boundaries and sharp creases (exact where every valence is 4; other faces and "
                  "semi-sharp tags read on the level where every face is a quad and the tags have decayed), normals "
                  "from their tangent patches; "
                  "adds limit_distance (to the exact limit; --samples: per point and per face, the face's largest) "
                  "and prints the largest and mean distance; "
                  "gregory: Loop, Schaefer, Ni & Castano's (2009) bicubic Gregory patches, one per quad of the "
                  "same meshes (exact where every valence is 4; normals continuous across every edge but creases), "
                  "normals their own, the same arrays and distances");
  cmd->add_option("--bezier-net", args->bezier_net,
                  "With --approximate bezier: also write the patches' control nets as VTK Bezier quadrilaterals (.vtu)");
  cmd->add_option("--derivatives", args->derivatives,
                  "0: positions; 1: also du and dv; 2: also duu, duv, dvv (nan where they do not exist)")
      ->check(CLI::Range(0, 2))
      ->capture_default_str();
  cmd->add_option("-o,--output", args->output,
                  "Output: with --at a .csv (face,u,v,x,y,z then du_x..dv_z, duu_x..dvv_z); with --samples or "
                  "--adaptive a mesh (.vtp, .obj, ...)")
      ->required();
  cmd->add_flag("--force", args->force, "Write -o even where it is the input mesh or the --at points file, which is then lost");
  cmd->add_option("-j,--threads", args->threads, "Worker threads (0: all cores)")->check(CLI::NonNegativeNumber);
  cmd->footer("Parameters: quads (0,0) (1,0) (1,1) (0,1); triangles (0,0) (1,0) (0,1); other faces of quad schemes\n"
              "Bfr's QUAD_SUBFACES tiles (also for dual and mid-edge schemes); sqrt3: the triangle's, two steps a triadic\n"
              "split (docs/limit.md). Example: subdiv evaluate examples/meshes/cube.obj --at points.csv -o limit.csv");
  cmd->callback([cmd, args] {
    args->boundary_given = cmd->count("--boundary") > 0;
    args->crease_method_given = cmd->count("--crease-method") > 0;
    args->fvar_boundary_given = cmd->count("--fvar-boundary") > 0;
    args->derivatives_given = cmd->count("--derivatives") > 0;
    run(*args);
  });
}

}  // namespace subdiv::cli
