// `subdiv refine MESH --scheme S --levels L -o OUT`: the main job.
#include <algorithm>
#include <chrono>
#include <fmt/format.h>

#include "commands.h"
#include "curve_refine.h"
#include "framework/io/formats.h"
#include "framework/pipeline/memory_guard.h"
#include "framework/util/option_spelling.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/pipeline/thread_limit.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "level_output.h"
#include "output_options.h"
#include "piece_refine.h"
#include "process_group.h"
#include "progress.h"
#include "shared_options.h"
#include "adaptive_refine_option.h"
#include "framework/util/quoted_text.h"
#include "safe_print.h"

namespace subdiv::cli {
namespace {

struct RefineArgs {
  std::string mesh, scheme = "catmull-clark", output;
  int levels = 1;
  std::vector<std::string> params, vertex_params;
  std::string boundary = "edges-and-corners", crease_method = "uniform";
  std::string features;        // --features FILE.json
  double feature_angle = -1;   // --feature-angle DEG; < 0: not given
  int threads = 0;
  int start_level = 0;
  bool levels_given = false;  // -l on the command line (a sequence A:1,B:3 sets its own total otherwise)
  bool quiet = false;
  bool limit = false;
  bool normals = false;  // --normals: limit normals without moving the points
  // Set when given on the command line, which then wins over the mesh file's option tags.
  bool boundary_given = false, crease_method_given = false, fvar_boundary_given = false;
  std::string fvar_boundary = "all";  // OpenSubdiv's default (Sdc::Options::FVAR_LINEAR_ALL)
  bool smooth_triangles = false;  // --smooth-triangles
  int pieces = 0;                 // --pieces N; 0: not given
  std::string max_memory;         // --max-memory SIZE; empty: not given
  bool pieces_given = false;
  OutputArgs output_format;  // --arrays, --compression, --compression-level
  bool timings = false;      // --timings
  bool force = false;        // --force: -o may be the input mesh
  std::string weights;       // --weights NAME: the point array of rational weights
  AdaptiveArgs adaptive;     // --adaptive [L], --tolerance T
  bool in_pieces() const { return pieces_given || !max_memory.empty(); }
};

// --start-level's range is the pipeline's kMaxStartLevel, which refuses the same in its own words.

// The command line's options as a pipeline request (framework/pipeline/refine_request.h).
RefineRequest refine_request(const RefineArgs& a, const OutputChoice& output, Progress& progress) {
  RefineRequest r;
  r.mesh_file = a.mesh;
  r.scheme.text = a.scheme;
  r.scheme.parameters = parse_params(a.params);
  r.levels = a.levels;
  r.levels_given = a.levels_given;
  r.start_level = a.start_level;
  if (a.boundary_given) r.shape.boundary = boundary_from_name(a.boundary, "--boundary");
  if (a.crease_method_given) r.shape.crease_method = crease_method_from_name(a.crease_method, "--crease-method");
  if (a.fvar_boundary_given) r.shape.face_varying = face_varying_from_name(a.fvar_boundary, "--fvar-boundary");
  r.shape.smooth_triangles = a.smooth_triangles;
  r.feature_file = a.features;
  r.feature_angle = a.feature_angle;
  r.vertex_parameter_files = vertex_param_files(a.vertex_params);
  r.limit_positions = a.limit;
  r.limit_normals = a.normals;
  r.weights_array = a.weights;
  const std::string ext = lowercase_extension(a.output);
  // Only ParaView's files hold SubdivKit's arrays; a .vtp holds the finest level alone.
  if (ext == ".vtp" || ext == ".pvd" || ext == ".pvtp") r.described_arrays = output.arrays;
  r.keep_all_levels = ext == ".pvd";
  r.memory_advice = "ask for fewer levels, or refine in pieces (--pieces N or --max-memory SIZE, -o OUT.pvtp)";
  r.progress = [&progress](const std::string& phase) { progress.say(phase); };
  r.progress_fraction = [&progress](double done) { progress.fraction(done); };
  return r;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) print_safe(stderr, "subdiv: warning: {}\n", w);
}

// --pieces and --max-memory write a .pvtp, and only a .pvtp comes from them; what a piece
// cannot do yet is refused before any work.
void check_piece_options(const RefineArgs& a) {
  const bool pvtp = lowercase_extension(a.output) == ".pvtp";
  if (!a.in_pieces()) {
    if (pvtp)
      throw Error(fmt::format("cannot write {}: a .pvtp holds a refinement in pieces; add --pieces N (or "
                              "--max-memory SIZE), or write .vtp or .pvd",
                              subdiv::quoted(a.output)));
    return;
  }
  if (!pvtp)
    throw Error(fmt::format("--pieces and --max-memory write one .vtp per piece and a .pvtp that lists them, but -o "
                            "{} is not a .pvtp; write -o {}.pvtp",
                            subdiv::quoted(a.output), std::filesystem::path(a.output).replace_extension().string()));
  if (a.limit || a.normals)
    throw Error(fmt::format("{} cannot be combined with --pieces or --max-memory yet (limit masks read a ring "
                            "beyond a piece); refine whole, or leave out {}",
                            a.limit ? "--limit" : "--normals", a.limit ? "--limit" : "--normals"));
}

// --tolerance belongs to --adaptive, and an adaptive mesh is written as write_mesh writes it
// (adaptive_refine_option.cpp): options that would be ignored are refused instead.
void check_adaptive_options(const RefineArgs& a) {
  if (!a.adaptive.given()) {
    if (a.adaptive.tolerance != 0) throw Error("--tolerance goes with --adaptive L");
    if (a.adaptive.transitions != AdaptiveArgs{}.transitions) throw Error("--transitions goes with --adaptive L");
    return;
  }
  const OutputArgs defaults;
  const OutputArgs& o = a.output_format;
  for (const auto& [given, option] : {std::pair{o.arrays != defaults.arrays, "--arrays"},
                                      std::pair{o.compression != defaults.compression, "--compression"},
                                      std::pair{o.compression_level != defaults.compression_level, "--compression-level"},
                                      std::pair{o.vtp_encoding != defaults.vtp_encoding, "--vtp-encoding"}})
    if (given)
      throw Error(fmt::format("{} goes with uniform refinement: --adaptive writes its mesh with its own arrays "
                              "(face_level, base_face, ...), lz4 compression and base64 encoding; leave out {}",
                              option, option));
}

// --pieces N or --max-memory SIZE: see piece_refine.h.
void run_in_pieces(const RefineArgs& a, const RefineRequest& request, const PreparedRefinement& prepared,
                   const OutputChoice& output, Progress& progress, std::chrono::steady_clock::time_point t0) {
  PieceJob job{a.output, a.pieces, a.max_memory.empty() ? 0.0 : parse_memory_size(a.max_memory, "--max-memory"),
               output, {}};
  // One bar over the pieces: piece p of n is (p + its levels' share) / n of the work.
  int piece_now = 0, piece_count = 1;
  job.piece_starts = [&](int piece, int pieces) {
    piece_now = piece, piece_count = pieces;
    progress.say(fmt::format("piece {}/{}", piece + 1, pieces));
  };
  RefineRequest piece_request = request;
  piece_request.progress_fraction = [&](double done) { progress.fraction((piece_now + done) / piece_count); };
  const Index faces = prepared.base.face_count();
  if (a.pieces_given && a.pieces < 1)
    throw Error(fmt::format("--pieces {}: a refinement needs at least one piece; ask for 1 to {} pieces", a.pieces,
                            faces));
  if (a.pieces > faces)
    throw Error(fmt::format("--pieces {}: the mesh has only {} faces to share out; ask for 1 to {} pieces", a.pieces,
                            faces, faces));
  std::vector<std::string> notes;
  bool first = true;
  const RefinePieceData refine = [&](const Hierarchy& h, const MeshData& piece, const RefineOptions& o) {
    LevelDataNotes said;  // every piece would say the same: the first one's
    auto levels = refine_level_data(prepared, h, piece, o, piece_request, said);
    if (first) notes = std::move(said.notes), first = false;
    return levels;
  };
  RefineOptions options = prepared.options;
  options.faces_only_last_level = last_level_faces_suffice(request, prepared);
  const PieceSummary done = refine_in_pieces(job, prepared.sequence, prepared.mesh, prepared.base, options, refine);
  progress.done();
  if (a.quiet) return;
  for (const auto& note : prepared.notes) print_safe("{}\n", spell_options(note, cli_option_spelling()));
  for (const auto& note : notes) print_safe("{}\n", spell_options(note, cli_option_spelling()));
  print_safe("{}: {} level(s) of {} in {} piece(s) ({}, {} ghost ring(s)){} -> {} faces in {:.3f} s -> {}\n", a.mesh,
             prepared.sequence.total_levels, a.scheme, done.pieces, done.method, done.rings,
             done.ranks > 1 ? fmt::format(" on {} ranks, this rank", done.ranks) : "", done.faces,
             seconds_since(t0), a.output);
}

void run(const RefineArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  check_output_not_input(a.mesh, a.output, a.force);
  if (is_curve_scheme(a.scheme) && a.in_pieces())
    throw Error(fmt::format("--pieces: {} is a curve scheme; refinement in pieces is for surfaces, refine "
                            "polylines whole (leave out --pieces and --max-memory)",
                            subdiv::quoted(a.scheme)));
  if (is_curve_scheme(a.scheme))  // polylines: tools/subdiv/curve_refine.cpp
    return refine_curves_command(
        {a.mesh, a.scheme, a.output, a.levels, parse_params(a.params), a.threads, a.quiet, a.weights});
  check_piece_options(a);
  check_adaptive_options(a);
  if (!a.in_pieces()) check_output_path(a.output);
  const OutputChoice output = output_choice(a.output_format);  // a bad --arrays is refused before any work
  const ThreadLimit threads(a.threads, "--threads");
  if (!threads.note().empty() && !a.quiet) print_safe(stderr, "subdiv: note: {}\n", threads.note());
  Progress progress(a.timings, a.quiet);
  RefineRequest request = refine_request(a, output, progress);
  if (a.adaptive.given())
    return run_adaptive_refine(std::move(request), a.adaptive, a.limit, a.in_pieces(), a.output, a.quiet, progress,
                               t0);
  PreparedRefinement prepared = prepare_refinement(request);
  print_warnings(prepared.warnings);
  if (a.in_pieces()) return run_in_pieces(a, request, prepared, output, progress, t0);
  RefineResult result = run_refinement(std::move(prepared), request);
  print_warnings(result.hierarchy.warnings);
  print_warnings(result.limit_warnings);
  if (!result.limit_note.empty() && !a.quiet)
    print_safe(stderr, "subdiv: note: {}\n", spell_options(result.limit_note, cli_option_spelling()));
  progress.say(fmt::format("writing {}", a.output));
  Hierarchy& h = result.hierarchy;
  // The faces written: holes are left out of every output, so out of the count too.
  const Level& finest = h.levels.back();
  const Index fine_vertices = finest.vertex_count,
              fine_faces = finest.face_count() - Index(std::count_if(finest.face_hole.begin(), finest.face_hole.end(),
                                                                     [](std::uint8_t hole) { return hole != 0; }));
  OutputChoice writing = output;  // VTK's progress events move the bar
  writing.vtk.progress = [&progress](double done) { progress.fraction(done); };
  write_levels(a.output, std::move(h), std::move(result.levels), result.features, result.finest_point_data,
               result.tags, writing);
  progress.done();
  if (!a.quiet) {
    for (const auto& note : result.notes) print_safe("{}\n", spell_options(note, cli_option_spelling()));
    print_safe("{}: {} level(s) of {} -> {} vertices, {} faces in {:.3f} s -> {}\n", a.mesh,
               result.sequence.total_levels, a.scheme, fine_vertices, fine_faces, seconds_since(t0), a.output);
  }
}

}  // namespace

void add_refine_command(CLI::App& app) {
  auto args = std::make_shared<RefineArgs>();
  auto* cmd = app.add_subcommand("refine", "Refine a mesh with a scheme and write the result");
  cmd->add_option("mesh", args->mesh, "Input mesh (" + supported_input_formats() + ")")->required();
  cmd->add_option("-s,--scheme", args->scheme,
                  "Scheme name (see `subdiv schemes`) or path to a .json file; a sequence A:1,B:3 applies A "
                  "for one level, then B for three (a name without :N takes the rest of --levels)")
      ->capture_default_str();
  CLI::Option* levels =
      cmd->add_option("-l,--levels", args->levels, "Number of refinement levels")->check(CLI::Range(0, 30))->capture_default_str();
  cmd->add_option("-o,--output", args->output,
                  "Output file: .vtp (finest level) or .pvd (all levels) for ParaView, or .obj, .off, .ply, .stl; "
                  ".pvtp with --pieces")
      ->required();
  cmd->add_flag("--force", args->force, "Write -o even where it is the input mesh, which is then lost");
  cmd->add_option("--pieces", args->pieces,
                  std::string("Refine in N pieces, one after another (only one in memory), or spread over the ranks "
                              "of mpirun (this build: ") +
                      process_group_kind() +
                      "); each piece gets the ghost rings its scheme needs, so the result equals the whole "
                      "refinement. Writes OUT_pieces/piece_<i>.vtp and OUT.pvtp; see docs/scale.md")
      ;
  cmd->add_option("--max-memory", args->max_memory,
                  "Memory each process may use, e.g. 8G or 512M: picks --pieces so that the base mesh and one piece "
                  "at a time fit (with --pieces given, refuses a piece that would not)");
  add_param_option(cmd, args->params);
  add_vertex_param_option(cmd, args->vertex_params);
  add_boundary_option(cmd, "--boundary", args->boundary);
  add_crease_method_option(cmd, args->crease_method);
  cmd->add_option("--features", args->features,
                  "Feature sidecar (JSON): creases by edge or vertex path and corners by vertex, 0-based, with "
                  "sharpness; applied after the mesh file's own tags (see docs/features.md)");
  cmd->add_option("--feature-angle", args->feature_angle,
                  "Make every edge whose faces' normals differ by more than DEG degrees an infinitely sharp crease")
      ->check(CLI::Range(0.0, 180.0));
  cmd->add_option("-j,--threads", args->threads, "Worker threads (0: all cores); results are identical for any count")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--start-level", args->start_level,
                  "How many steps the input has already been refined (schemes whose steps alternate, like "
                  "sqrt3's boundary trisection, and level-dependent schemes count from the original mesh)")
      ->check(CLI::Range(0, kMaxStartLevel))
      ->capture_default_str();
  cmd->add_flag("--limit", args->limit,
                "Move the finest level's vertices, and the input's interpolated point arrays, to their limit values "
                "and write limit normals as point data 'normal' (with --levels 0: the limits of the input's own "
                "vertices; a scheme that is not C1 has no normals: they are left out with a warning)");
  cmd->add_flag("--normals", args->normals,
                "Write the exact limit normals of the finest level's vertices as point data 'normal' (the vertices "
                "stay where refinement put them). Normals in the input are not refined: a mix of unit normals is "
                "no normal, so they are left out with a note. Refused for a scheme that is not C1 (no normals exist)");
  add_fvar_boundary_option(cmd, args->fvar_boundary, "Face-varying data (OBJ vt: UVs with seams)");
  cmd->add_option("--weights", args->weights,
                  "Rational subdivision: the point array holding each control point's weight w > 0; the scheme "
                  "refines (w*p, w) and the points are projected back, so weighted nets draw conics and quadrics "
                  "exactly (docs/rational.md). Default: OBJ's 'v x y z w', or a point array named 'weight'");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  add_output_options(cmd, args->output_format);
  add_adaptive_options(cmd, args->adaptive);
  cmd->add_flag("--timings", args->timings,
                "Print each step's wall time and the peak memory so far on stderr (reading, topology, each "
                "level's values, writing)");
  cmd->footer("Example: subdiv refine examples/meshes/cube.obj --scheme catmull-clark --levels 3 -o cube.pvd");
  cmd->add_flag("--smooth-triangles", args->smooth_triangles,
                "Catmull-Clark: OpenSubdiv's smooth triangles (TRI_SUB_SMOOTH), the same as --param "
                "triangles=smooth; a mesh's 't smoothtriangles' tag does the same unless --param says otherwise");
  cmd->callback([args, cmd, levels] {
    args->levels_given = levels->count() > 0;
    resolve_adaptive_level(*cmd, args->adaptive, args->levels, args->levels_given);
    args->boundary_given = cmd->count("--boundary") > 0;
    args->crease_method_given = cmd->count("--crease-method") > 0;
    args->fvar_boundary_given = cmd->count("--fvar-boundary") > 0;
    args->pieces_given = cmd->count("--pieces") > 0;
    run(*args);
  });
}

}  // namespace subdiv::cli
