// `subdiv refine MESH --scheme S --levels L -o OUT`: the main job.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/global_control.h>

#include "commands.h"
#include "shared_options.h"
#include "framework/io/feature_angle.h"
#include "framework/io/feature_file.h"
#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/io/formats.h"
#include "framework/io/mesh_cleanup.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/engine/refiner.h"
#include "framework/primvar/face_varying.h"
#include "framework/primvar/level_data.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "level_output.h"
#include "limit_output.h"
#include "memory_guard.h"
#include "output_options.h"
#include "progress.h"
#include "curve_refine.h"
#include "piece_refine.h"
#include "process_group.h"

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
  bool in_pieces() const { return pieces_given || !max_memory.empty(); }
};

RefineOptions refine_options(const RefineArgs& a) {
  RefineOptions o;
  o.levels = a.levels;
  o.threads = a.threads;
  o.features = {boundary_from_name(a.boundary), crease_method_from_name(a.crease_method)};
  o.first_step = a.start_level;
  return o;
}

// Level-dependent state is computed level by level up to the start level: a bound keeps
// that finite, and no refinement history is longer than this.
constexpr int kMaxStartLevel = 100;

// The mesh file's option tags (OBJ t interpolateboundary, t creasemethod), where the
// command line does not say otherwise.
RefineArgs with_mesh_options(RefineArgs a, const MeshOptions& tags) {
  if (!a.boundary_given && tags.interpolate_boundary)
    a.boundary = *tags.interpolate_boundary == 0 ? "none" : *tags.interpolate_boundary == 2 ? "edges" : "edges-and-corners";
  if (!a.crease_method_given && tags.crease_method) a.crease_method = *tags.crease_method == "chaikin" ? "chaikin" : "uniform";
  if (!a.fvar_boundary_given && tags.fvar_interpolate_boundary) {
    FaceVaryingLinear mode = face_varying_linear_from_tag(*tags.fvar_interpolate_boundary);
    // OpenSubdiv 2's "propagate corners" is what corners-plus2 adds to corners-plus1.
    if (mode == FaceVaryingLinear::CornersPlus1 && tags.fvar_propagate_corners.value_or(0))
      mode = FaceVaryingLinear::CornersPlus2;
    a.fvar_boundary = face_varying_linear_name(mode);
  }
  return a;
}

bool has_parameter(const SchemeSequence& seq, const std::string& name) {
  for (const auto& scheme : seq.schemes)
    for (const auto& p : scheme->parameters)
      if (p.name == name) return true;
  return false;
}

// OpenSubdiv's smooth triangles (TRI_SUB_SMOOTH) are the scheme parameter "triangles"
// (schemes/catmull-clark.json): --smooth-triangles, or the mesh's t smoothtriangles tag,
// set it unless --param does. "" when nothing changes.
std::string triangles_choice(const RefineArgs& a, const MeshOptions& tags, const SchemeSequence& given) {
  for (const auto& p : a.params)
    if (p.rfind("triangles=", 0) == 0) return "";
  if (a.smooth_triangles) {
    if (!has_parameter(given, "triangles"))
      throw Error(fmt::format("--smooth-triangles: scheme '{}' has no 'triangles' parameter; smooth triangles are a "
                              "Catmull-Clark option (OpenSubdiv's TRI_SUB_SMOOTH), e.g. --scheme catmull-clark",
                              a.scheme));
    return "smooth";
  }
  // As OpenSubdiv, a tag for a scheme without the option is ignored.
  return tags.smooth_triangles && has_parameter(given, "triangles") ? *tags.smooth_triangles : "";
}

ParameterOverrides with_triangles(const RefineArgs& a, const std::string& triangles) {
  ParameterOverrides params = parse_params(a.params);
  params["triangles"] = triangles;
  return params;
}

// The options the refinement used, as tags for an OBJ output (a round trip keeps them).
MeshOptions used_options(const RefineOptions& o, const MeshOptions& tags, const SchemeSequence& seq) {
  MeshOptions used = tags;
  for (const auto& scheme : seq.schemes)
    for (const auto& p : scheme->parameters)
      if (p.name == "triangles") used.smooth_triangles = p.choice;
  used.interpolate_boundary = o.features.boundary == BoundaryInterpolation::None        ? 0
                              : o.features.boundary == BoundaryInterpolation::EdgesOnly ? 2
                                                                                          : 1;
  used.crease_method = o.features.crease_method == CreaseMethod::Chaikin ? "chaikin" : "normal";
  return used;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

FaceVaryingLinear fvar_mode(const RefineArgs& a) {
  for (FaceVaryingLinear m : {FaceVaryingLinear::None, FaceVaryingLinear::CornersOnly, FaceVaryingLinear::CornersPlus1,
                              FaceVaryingLinear::CornersPlus2, FaceVaryingLinear::Boundaries, FaceVaryingLinear::All})
    if (a.fvar_boundary == face_varying_linear_name(m)) return m;
  return FaceVaryingLinear::All;  // the option's check allows nothing else
}

// The mesh's face-varying arrays (OBJ vt) refined with the levels (framework/primvar/
// face_varying.h); normals are left out, as for point data.
void refine_face_varying_arrays(const SchemeSequence& seq, const Hierarchy& h, const MeshData& mesh,
                                const RefineOptions& options, FaceVaryingLinear mode, std::vector<LevelData>& levels,
                                std::vector<std::string>& notes) {
  for (const FaceVaryingArray& a : mesh.face_varying) {
    if (a.role == ArrayRole::Normals) {
      notes.push_back(fmt::format("face-varying array '{}' holds normals, which refinement does not carry; "
                                  "--normals writes the exact limit normals", a.name));
      continue;
    }
    const auto refined = refine_face_varying(seq.runs, h, {a.values, a.indices}, a.components, mode, options);
    for (size_t l = 0; l < levels.size(); ++l)
      levels[l].face_varying.push_back({a.name, a.components, refined[l].values, refined[l].indices, a.role});
  }
}

// The positions and the user's arrays, level by level (framework/primvar/level_data.h):
// point arrays but normals (a note says so), cell arrays, face-varying arrays.
std::vector<LevelData> refine_data(const RefineArgs& a, const SchemeSequence& seq, const Hierarchy& h,
                                   const MeshData& mesh, const RefineOptions& options, Progress& progress,
                                   std::vector<std::string>& notes) {
  std::vector<std::string> dropped;
  std::vector<LevelData> levels{{mesh.positions, carried_point_arrays(mesh.point_data, &dropped), mesh.cell_data}};
  check_finite_arrays(levels.front(), a.mesh);
  for (const auto& name : dropped)
    notes.push_back(fmt::format("point array '{}' holds normals, which refinement does not carry (a mix of unit "
                                "normals is no normal); --normals writes the exact limit normals", name));
  for (int l = 0; l < seq.total_levels; ++l) {
    progress.say(fmt::format("level {}/{}: {} faces", l + 1, seq.total_levels, h.levels[l + 1].face_count()));
    // Straight from the rules (no stencil tables), or a non-linear plugin rule.
    levels.push_back(next_level_data(seq.runs, h, l, levels.back(), options));
  }
  refine_face_varying_arrays(seq, h, mesh, options, fvar_mode(with_mesh_options(a, mesh.options)), levels, notes);
  return levels;
}

// The options written back as OpenSubdiv's tags into OBJ output, the face-varying mode
// among them when the mesh has face-varying data or said one.
MeshOptions tags_to_write(const RefineArgs& a, const RefineOptions& options, const MeshData& mesh,
                          const SchemeSequence& seq) {
  MeshOptions used = used_options(options, mesh.options, seq);
  if (!mesh.face_varying.empty() || used.fvar_interpolate_boundary) {
    used.fvar_interpolate_boundary = int(fvar_mode(with_mesh_options(a, mesh.options)));
    used.fvar_propagate_corners.reset();  // said by the mode written
  }
  return used;
}

// --limit and --normals (limit_output.h), with a note on what had to be approximated.
std::vector<DataArray> apply_limits(const RefineArgs& a, const SchemeSequence& seq, const Hierarchy& h,
                                    const RefineOptions& options, LevelData& finest) {
  LimitArrays limits = limit_arrays(seq, h, options, finest, a.limit);
  const LimitResult& limit = limits.result;
  if ((limit.approximate > 0 || limit.approximate_normals > 0) && !a.quiet)
    fmt::print(stderr,
               "subdiv: note: {} approximates {} position(s) and {} more normal(s) of {} vertices (point data "
               "limit_exact, normal_exact): {}\n",
               a.limit ? "--limit" : "--normals", limit.approximate, limit.approximate_normals, limit.exact.size(),
               fmt::join(limit.approximate_reasons, "; "));
  return std::move(limits.point_data);
}

// Whether the last level can be built with its faces only (RefineOptions::faces_only_last_level),
// as OpenSubdiv builds it by default, for the same output: nothing written reads its edges
// or vertex rings. Those are read by the valence and vertex_class arrays, --limit and
// --normals, face-varying data, and the creases and corners written from the level's
// sharpness tags, which live on its edges and vertices; so a base mesh with any tag,
// boundary (boundary corners are tagged), hole or non-manifold edge keeps full topology.
bool last_level_faces_suffice(const RefineArgs& a, const ArraySelection& arrays, const MeshData& mesh,
                              const Level& base) {
  const std::string ext = lowercase_extension(a.output);
  const bool paraview = ext == ".vtp" || ext == ".pvd";
  if ((paraview && arrays.needs_last_level_edges()) || a.limit || a.normals || !mesh.face_varying.empty())
    return false;
  const auto tagged = [](const std::vector<float>& sharpness) {
    return std::any_of(sharpness.begin(), sharpness.end(), [](float s) { return s > 0.f; });
  };
  const bool boundary = std::any_of(base.vertex_on_boundary.begin(), base.vertex_on_boundary.end(),
                                    [](std::uint8_t b) { return b != 0; });
  return !tagged(base.edge_sharpness) && !tagged(base.vertex_sharpness) && !boundary && base.manifold() &&
         base.face_hole.empty();
}

// --pieces and --max-memory write a .pvtp, and only a .pvtp comes from them; what a piece
// cannot do yet is refused before any work.
void check_piece_options(const RefineArgs& a) {
  const bool pvtp = lowercase_extension(a.output) == ".pvtp";
  if (!a.in_pieces()) {
    if (pvtp)
      throw Error(fmt::format("cannot write '{}': a .pvtp holds a refinement in pieces; add --pieces N (or "
                              "--max-memory SIZE), or write .vtp or .pvd",
                              a.output));
    return;
  }
  if (!pvtp)
    throw Error(fmt::format("--pieces and --max-memory write one .vtp per piece and a .pvtp that lists them, but -o "
                            "'{}' is not a .pvtp; write -o {}.pvtp",
                            a.output, std::filesystem::path(a.output).replace_extension().string()));
  if (a.limit || a.normals)
    throw Error(fmt::format("{} cannot be combined with --pieces or --max-memory yet (limit masks read a ring "
                            "beyond a piece); refine whole, or leave out {}",
                            a.limit ? "--limit" : "--normals", a.limit ? "--limit" : "--normals"));
}

// --pieces N or --max-memory SIZE: see piece_refine.h.
void run_in_pieces(const RefineArgs& a, const SchemeSequence& seq, const MeshData& mesh, const Level& base,
                   const RefineOptions& options, std::chrono::steady_clock::time_point t0) {
  PieceJob job{a.output, a.pieces, a.max_memory.empty() ? 0.0 : parse_memory_size(a.max_memory, "--max-memory"),
               output_choice(a.output_format)};
  if (a.pieces_given && a.pieces < 1)
    throw Error(fmt::format("--pieces {}: a refinement needs at least one piece; ask for 1 to {} pieces", a.pieces,
                            base.face_count()));
  if (a.pieces > base.face_count())
    throw Error(fmt::format("--pieces {}: the mesh has only {} faces to share out; ask for 1 to {} pieces", a.pieces,
                            base.face_count(), base.face_count()));
  std::vector<std::string> notes;
  bool first = true;
  Progress progress(a.timings);
  const RefinePieceData refine = [&](const Hierarchy& h, const MeshData& piece, const RefineOptions& o) {
    std::vector<std::string> piece_notes;  // every piece would say the same: the first one's
    auto levels = refine_data(a, seq, h, piece, o, progress, piece_notes);
    if (first) notes = piece_notes, first = false;
    return levels;
  };
  const PieceSummary done = refine_in_pieces(job, seq, mesh, base, options, refine);
  progress.done();
  if (a.quiet) return;
  for (const auto& note : notes) fmt::print("{}\n", note);
  fmt::print("{}: {} level(s) of {} in {} piece(s) ({}, {} ghost ring(s)){} -> {} faces in {:.3f} s -> {}\n", a.mesh,
             seq.total_levels, a.scheme, done.pieces, done.method, done.rings,
             done.ranks > 1 ? fmt::format(" on {} ranks, this rank", done.ranks) : "", done.faces,
             seconds_since(t0), a.output);
}

void run(const RefineArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  if (is_curve_scheme(a.scheme) && a.in_pieces())
    throw Error(fmt::format("--pieces: '{}' is a curve scheme; refinement in pieces is for surfaces, refine "
                            "polylines whole (leave out --pieces and --max-memory)",
                            a.scheme));
  if (is_curve_scheme(a.scheme))  // polylines: tools/subdiv/curve_refine.cpp
    return refine_curves_command({a.mesh, a.scheme, a.output, a.levels, parse_params(a.params), a.threads, a.quiet});
  check_piece_options(a);
  if (!a.in_pieces()) check_output_path(a.output);
  const OutputChoice output = output_choice(a.output_format);  // a bad --arrays is refused before any work
  // CLI11's range check lets NaN through (every comparison with it is false).
  if (std::isnan(a.feature_angle))
    throw Error("--feature-angle nan is not an angle; give degrees from 0 to 180");
  std::unique_ptr<tbb::global_control> thread_limit;
  if (a.threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, a.threads);
  const SchemeSequence given = load_scheme_sequence(a.scheme, a.levels, parse_params(a.params));
  if (a.levels_given && given.total_levels != a.levels)
    throw Error(fmt::format("--scheme '{}' runs {} level(s), but --levels asks for {}; make the counts add up to {}, "
                            "leave one scheme without :N to take the rest, or drop --levels",
                            a.scheme, given.total_levels, a.levels, a.levels));
  Progress progress(a.timings);
  progress.say(fmt::format("reading {}", a.mesh));
  MeshCleanup cleanup;
  const MeshData mesh = drop_unrefinable(read_mesh(a.mesh), cleanup);
  for (const auto& w : mesh.warnings) fmt::print(stderr, "subdiv: warning: {}\n", w);
  for (const auto& w : cleanup.warnings(a.mesh)) fmt::print(stderr, "subdiv: warning: {}\n", w);
  const std::string triangles = triangles_choice(a, mesh.options, given);
  const SchemeSequence seq = triangles.empty() ? given : load_scheme_sequence(a.scheme, a.levels, with_triangles(a, triangles));
  if (mesh.face_count() == 0)
    throw Error(fmt::format("{}: the mesh has no faces to refine{}", a.mesh,
                            mesh.line_count() ? "; its polylines need a curve scheme (e.g. --scheme chaikin)" : ""));
  Level base = level_from_mesh(mesh, a.mesh);
  std::vector<std::string> notes;
  if (!a.features.empty()) {
    const FeatureTags tags = read_feature_file(a.features);
    apply_feature_tags(tags, base);
    notes.push_back(fmt::format("{}: {} crease edge(s), {} corner(s)", a.features, tags.creases.size(), tags.corners.size()));
  }
  if (a.feature_angle >= 0) {
    const Index sharp = tag_edges_sharper_than(base, mesh.positions, a.feature_angle);
    notes.push_back(fmt::format("--feature-angle {}: {} edge(s) made infinitely sharp", a.feature_angle, sharp));
  }
  if (!a.in_pieces())
    check_fits_in_memory(*seq.schemes.front(), base, seq.total_levels, 0,
                         "ask for fewer levels, or refine in pieces (--pieces N or --max-memory SIZE, -o OUT.pvtp)");

  RefineOptions options = refine_options(with_mesh_options(a, mesh.options));
  if (!a.vertex_params.empty() && cleanup.dropped_vertices > 0)
    throw Error(fmt::format("{}: --vertex-param gives values in the file's vertex order, but unused vertices were "
                            "dropped (see the warning) and the rest renumbered; remove them from the mesh first",
                            a.mesh));
  options.vertex_parameters = read_vertex_params(a.vertex_params, base.vertex_count);
  if (a.in_pieces()) {
    progress.done();
    return run_in_pieces(a, seq, mesh, base, options, t0);
  }
  options.faces_only_last_level = last_level_faces_suffice(a, output.arrays, mesh, base);
  progress.say(fmt::format("refining topology: {} levels of {}{}", seq.total_levels, a.scheme,
                           options.faces_only_last_level ? " (last level: faces only)" : ""));
  Hierarchy h = refine_topology(seq.runs, std::move(base), options);
  for (const auto& w : h.warnings) fmt::print(stderr, "subdiv: warning: {}\n", w);
  std::vector<LevelData> levels = refine_data(a, seq, h, mesh, options, progress, notes);
  std::vector<DataArray> limit_data;
  if (a.limit || a.normals) {
    progress.say(a.limit ? "limit positions and normals" : "limit normals");
    limit_data = apply_limits(a, seq, h, options, levels.back());
  }
  progress.say(fmt::format("writing {}", a.output));
  const Index fine_vertices = h.levels.back().vertex_count, fine_faces = h.levels.back().face_count();
  write_levels(a.output, std::move(h), std::move(levels), options.features, limit_data,
               tags_to_write(a, options, mesh, seq), output);
  progress.done();
  if (!a.quiet) {
    for (const auto& note : notes) fmt::print("{}\n", note);
    fmt::print("{}: {} level(s) of {} -> {} vertices, {} faces in {:.3f} s -> {}\n", a.mesh, seq.total_levels,
               a.scheme, fine_vertices, fine_faces, seconds_since(t0), a.output);
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
                "vertices)");
  cmd->add_flag("--normals", args->normals,
                "Write the exact limit normals of the finest level's vertices as point data 'normal' (the vertices "
                "stay where refinement put them). Normals in the input are not refined: a mix of unit normals is "
                "no normal, so they are left out with a note");
  cmd->add_option("--fvar-boundary", args->fvar_boundary,
                  "Face-varying data (OBJ vt: UVs with seams), as OpenSubdiv's linear-interpolation modes: none "
                  "(smooth everywhere), corners-only, corners-plus1, corners-plus2, boundaries (linear along seams "
                  "and boundaries), all (bilinear, OpenSubdiv's default); a mesh's 't facevaryinginterpolateboundary' "
                  "tag does the same unless this option is given")
      ->check(CLI::IsMember({"none", "corners-only", "corners-plus1", "corners-plus2", "boundaries", "all"}))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  add_output_options(cmd, args->output_format);
  cmd->add_flag("--timings", args->timings,
                "Print each step's wall time and the peak memory so far on stderr (reading, topology, each "
                "level's values, writing)");
  cmd->footer("Example: subdiv refine examples/meshes/cube.obj --scheme catmull-clark --levels 3 -o cube.pvd");
  cmd->add_flag("--smooth-triangles", args->smooth_triangles,
                "Catmull-Clark: OpenSubdiv's smooth triangles (TRI_SUB_SMOOTH), the same as --param "
                "triangles=smooth; a mesh's 't smoothtriangles' tag does the same unless --param says otherwise");
  cmd->callback([args, cmd, levels] {
    args->levels_given = levels->count() > 0;
    args->boundary_given = cmd->count("--boundary") > 0;
    args->crease_method_given = cmd->count("--crease-method") > 0;
    args->fvar_boundary_given = cmd->count("--fvar-boundary") > 0;
    args->pieces_given = cmd->count("--pieces") > 0;
    run(*args);
  });
}

}  // namespace subdiv::cli
