#include "framework/pipeline/refine_pipeline.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "framework/util/step_progress.h"
#include "framework/io/feature_angle.h"
#include "framework/io/feature_file.h"
#include "framework/io/mesh_cleanup.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/io/vertex_values.h"
#include "framework/engine/topology_steps.h"
#include "framework/pipeline/limit_arrays.h"
#include "framework/pipeline/memory_guard.h"
#include "framework/pipeline/rational_weights.h"
#include "framework/pipeline/scheme_source.h"
#include "framework/util/option_spelling.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/scheme/step_tables.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

void say(const RefineRequest& r, const std::string& phase) {
  if (r.progress) r.progress(phase);
}

void say_done(const RefineRequest& r, double done) {
  if (r.progress_fraction) r.progress_fraction(done);
}

// The bar's share of the levels' work: a level's values cost about its faces' worth. When
// topology is made level by level, the faces of levels not made yet (and of a last level
// whose faces wait) are guessed from the last step's growth, so the share told is kept from
// going back when a guess is replaced by the count.
class LevelShares {
 public:
  LevelShares(const Hierarchy& h, int total) : h_(h), total_(total) {}
  // When `finished` levels are done, and the share `next` (0 to 1) of the level after them.
  double done(int finished, double next = 0) {
    const std::vector<double> work = works();
    double all = 0, done = 0;
    for (int l = 1; l <= total_; ++l) {
      all += work[size_t(l)];
      if (l <= finished) done += work[size_t(l)];
      else if (l == finished + 1) done += next * work[size_t(l)];
    }
    told_ = std::max(told_, all > 0 ? done / all : 1.0);
    return told_;
  }

 private:
  std::vector<double> works() const {
    std::vector<double> faces(size_t(total_) + 1, 0);
    size_t known = 0;
    for (size_t l = 0; l < faces.size() && l < h_.levels.size() && (l == 0 || h_.levels[l].face_count() > 0); ++l)
      faces[l] = double(h_.levels[l].face_count()), known = l;
    const double growth = known > 0 && faces[known - 1] > 0 ? faces[known] / faces[known - 1] : 4.0;
    for (size_t l = known + 1; l < faces.size(); ++l) faces[l] = faces[l - 1] * growth;
    for (double& f : faces) f += 1;
    return faces;
  }
  const Hierarchy& h_;
  int total_;
  double told_ = 0;
};

// ---- the scheme ----------------------------------------------------------------------------

// OpenSubdiv's smooth triangles (TRI_SUB_SMOOTH) are the scheme parameter "triangles"
// (schemes/catmull-clark.json): asked for, or the mesh's `t smoothtriangles` tag, sets it
// unless the request's parameters do. "" when nothing changes.
std::string triangles_choice(const RefineRequest& r, const SchemeSequence& given, const std::string& label) {
  if (r.scheme.parameters.count("triangles")) return "";
  if (r.shape.smooth_triangles) {
    if (!declares_parameter(given, "triangles"))
      throw OptionError(fmt::format("{{smooth_triangles}}: scheme {} has no 'triangles' parameter; smooth "
                                    "triangles (OpenSubdiv's TRI_SUB_SMOOTH) need a scheme that declares one "
                                    "({{scheme_list}} lists each scheme's parameters)",
                                    subdiv::quoted(label)));
    return "smooth";
  }
  // As OpenSubdiv, a tag for a scheme without the option is ignored.
  const auto& tag = r.mesh.options.smooth_triangles;
  return tag && declares_parameter(given, "triangles") ? *tag : "";
}

SchemeSequence load_request_scheme(const RefineRequest& r, std::string& label) {
  label = r.scheme.is_json_text ? r.scheme.label : r.scheme.text;
  const SchemeSequence given = load_surface_sequence(r.scheme, r.levels, r.scheme.parameters);
  if (r.levels_given && given.total_levels != r.levels)
    throw OptionError(fmt::format("{{scheme}} {} runs {} level(s), but {{levels}} asks for {}; make the counts add "
                                  "up to {}, leave one scheme without :N to take the rest, or drop {{levels}}",
                                  subdiv::quoted(label), given.total_levels, r.levels, r.levels));
  const std::string triangles = triangles_choice(r, given, label);
  if (triangles.empty()) return given;
  ParameterOverrides with_triangles = r.scheme.parameters;
  with_triangles["triangles"] = triangles;
  return load_surface_sequence(r.scheme, r.levels, with_triangles);
}

// ---- shape options: the request's, else the mesh's tags, else the defaults -------------------

FeatureOptions feature_options(const ShapeChoices& shape, const MeshOptions& tags) {
  FeatureOptions o;
  if (shape.boundary) o.boundary = *shape.boundary;
  else if (tags.interpolate_boundary)
    o.boundary = *tags.interpolate_boundary == 0   ? BoundaryInterpolation::None
                 : *tags.interpolate_boundary == 2 ? BoundaryInterpolation::EdgesOnly
                                                   : BoundaryInterpolation::EdgesAndCorners;
  if (shape.crease_method) o.crease_method = *shape.crease_method;
  else if (tags.crease_method) o.crease_method = *tags.crease_method == "chaikin" ? CreaseMethod::Chaikin : CreaseMethod::Uniform;
  return o;
}

FaceVaryingLinear face_varying_mode(const ShapeChoices& shape, const MeshOptions& tags) {
  if (shape.face_varying) return *shape.face_varying;
  if (!tags.fvar_interpolate_boundary) return FaceVaryingLinear::All;
  const FaceVaryingLinear mode = face_varying_linear_from_tag(*tags.fvar_interpolate_boundary);
  // OpenSubdiv 2's "propagate corners" is what corners-plus2 adds to corners-plus1.
  if (mode == FaceVaryingLinear::CornersPlus1 && tags.fvar_propagate_corners.value_or(0))
    return FaceVaryingLinear::CornersPlus2;
  return mode;
}

// The options in force as OpenSubdiv's tags, for OBJ output (a round trip keeps them); the
// face-varying mode among them when the mesh has face-varying data or said one.
MeshOptions tags_in_force(const PreparedRefinement& p) {
  MeshOptions used = p.mesh.options;
  for (const auto& scheme : p.sequence.schemes)
    for (const auto& parameter : scheme->parameters)
      if (parameter.name == "triangles") used.smooth_triangles = parameter.choice;
  const BoundaryInterpolation b = p.options.features.boundary;
  used.interpolate_boundary = b == BoundaryInterpolation::None ? 0 : b == BoundaryInterpolation::EdgesOnly ? 2 : 1;
  used.crease_method = p.options.features.crease_method == CreaseMethod::Chaikin ? "chaikin" : "normal";
  if (!p.mesh.face_varying.empty() || used.fvar_interpolate_boundary) {
    used.fvar_interpolate_boundary = int(p.face_varying);
    used.fvar_propagate_corners.reset();  // said by the mode written
  }
  return used;
}

// ---- the mesh ---------------------------------------------------------------------------------

void check_request(const RefineRequest& r) {
  if (r.levels < 0 || r.levels > 30) throw OptionError(fmt::format("{{levels}} {}: give 0 to 30 levels", r.levels));
  if (r.start_level < 0 || r.start_level > kMaxStartLevel)
    throw OptionError(fmt::format("{{start_level}} {}: give 0 to {}", r.start_level, kMaxStartLevel));
  // NaN passes range checks (every comparison with it is false): refused by name.
  if (std::isnan(r.feature_angle) || r.feature_angle > 180)
    throw OptionError(fmt::format("{{feature_angle}} {} is not an angle; give degrees from 0 to 180", r.feature_angle));
}

Level tagged_base(const RefineRequest& r, const MeshData& mesh, std::vector<std::string>& notes) {
  if (mesh.face_count() == 0)
    throw Error(fmt::format("{}: the mesh has no faces to refine{}", r.mesh_name,
                            mesh.line_count() ? "; its polylines need a curve scheme" : ""));
  Level base = level_from_mesh(mesh, r.mesh_name);
  if (!r.feature_file.empty()) {
    const FeatureTags tags = read_feature_file(r.feature_file);
    apply_feature_tags(tags, base);
    notes.push_back(fmt::format("{}: {} crease edge(s), {} corner(s)", r.feature_file, tags.creases.size(),
                                tags.corners.size()));
  }
  if (r.feature_angle >= 0) {
    const Index sharp = tag_edges_sharper_than(base, mesh.positions, r.feature_angle);
    notes.push_back(fmt::format("{{feature_angle}} {}: {} edge(s) made infinitely sharp", r.feature_angle, sharp));
  }
  return base;
}

// Whether the last level can be built with its faces only (RefineOptions::
// faces_only_last_level), as OpenSubdiv builds it by default, for the same result: nothing
// asked for reads its edges or vertex rings. Those are read by the valence and vertex_class
// arrays, limit positions and normals, face-varying data, and the creases and corners taken
// from the level's sharpness tags, which live on its edges and vertices; so a base mesh with
// any tag, boundary (boundary corners are tagged), hole or non-manifold edge keeps them.
bool last_level_faces_suffice(const RefineRequest& r, const MeshData& mesh, const Level& base) {
  if ((r.described_arrays && r.described_arrays->needs_last_level_edges()) || r.limit_positions || r.limit_normals ||
      !mesh.face_varying.empty())
    return false;
  const auto tagged = [](const std::vector<float>& sharpness) {
    return std::any_of(sharpness.begin(), sharpness.end(), [](float s) { return s > 0.f; });
  };
  const bool boundary = std::any_of(base.vertex_on_boundary.begin(), base.vertex_on_boundary.end(),
                                    [](std::uint8_t b) { return b != 0; });
  return !tagged(base.edge_sharpness) && !tagged(base.vertex_sharpness) && !boundary && base.manifold() &&
         base.face_hole.empty();
}

// ---- rational weights (rational_weights.h) ----------------------------------------------------

void find_weights(const RefineRequest& r, PreparedRefinement& p) {
  const std::optional<size_t> at = find_rational_weights(p.mesh.point_data, r.weights_array, r.mesh_name);
  if (!at) return;
  p.weights_name = p.mesh.point_data[*at].name;
  p.rational = !all_weights_one(p.mesh.point_data[*at].values);
  for (const auto& scheme : p.sequence.schemes)
    if (p.rational && !scheme->linear())
      throw Error(fmt::format("{}: the rational weights {} need a linear scheme, but {} has a non-linear step (a "
                              "plugin rule), which does not commute with projecting (w·p, w); drop the weights or "
                              "choose a linear scheme",
                              r.mesh_name, subdiv::quoted(p.weights_name), subdiv::quoted(scheme->name)));
}

DataArray* weights_of(LevelData& level, const std::string& name) {
  for (DataArray& a : level.point_data)
    if (a.name == name) return &a;
  return nullptr;
}

// Every kept level projected back from (w·p, w); the input level takes its own positions,
// so it is the input bit for bit.
void project_levels(std::vector<LevelData>& levels, const std::string& name, const std::vector<double>& input) {
  for (size_t l = 0; l < levels.size(); ++l) {
    if (levels[l].positions.empty()) continue;
    if (l == 0) levels[l].positions = input;
    else from_homogeneous(levels[l].positions, weights_of(levels[l], name)->values);
  }
}

// The refined weights are written as "weight" (OBJ: the fourth coordinate), whatever the
// input called them, unless another array has that name.
std::string output_weights_name(const PreparedRefinement& p) {
  if (p.weights_name.empty() || p.weights_name == kWeightArrayName) return p.weights_name;
  for (const DataArray& a : p.mesh.point_data)
    if (a.name == kWeightArrayName) return p.weights_name;
  return kWeightArrayName;
}

void rename_weights(std::vector<LevelData>& levels, const PreparedRefinement& p) {
  const std::string name = output_weights_name(p);
  if (name == p.weights_name) return;
  for (LevelData& level : levels)
    if (DataArray* w = weights_of(level, p.weights_name)) w->name = name;
}

// ---- limits -----------------------------------------------------------------------------------

std::string limit_note(const RefineRequest& r, const LimitResult& limit) {
  if (limit.approximate == 0 && limit.approximate_normals == 0) return "";
  return fmt::format("{} approximates {} position(s) and {} more normal(s) of {} vertices (point data limit_exact, "
                     "normal_exact): {}",
                     r.limit_positions ? "{limit}" : "{normals}", limit.approximate,
                     limit.approximate_normals, limit.exact.size(), fmt::join(limit.approximate_reasons, "; "));
}

// Finite coordinates can leave double range under a scheme whose weights are not all
// positive (butterfly's -1/16): refused here, for every front-end, rather than written.
void check_refined_points(const LevelData& refined, int level, const std::vector<double>& base, const RefineRequest& r) {
  const auto bad = std::find_if(refined.positions.begin(), refined.positions.end(), [](double x) { return !std::isfinite(x); });
  if (bad == refined.positions.end()) return;
  double largest = 0;
  for (double x : base) largest = std::max(largest, std::abs(x));
  throw Error(fmt::format("{}: level {}: refined point {} has a non-finite coordinate ({}): the input's coordinates "
                          "(up to {:g}) leave the range of double precision under the scheme's weights; scale the mesh "
                          "down (e.g. to unit size) and the result back up",
                          r.mesh_name, level, (bad - refined.positions.begin()) / 3, *bad, largest));
}

// ---- memory: coarser levels released ---------------------------------------------------------

// A step's values read only its parent and child levels and the child's origins
// (engine/refiner.cpp, step_values). Unless the request keeps every level, or reads the
// whole hierarchy later (face-varying data is refined through every level after the
// points; limits start from it), each coarser level's topology goes back as soon as the
// next level's values are made: at level 3 of a 1M-face mesh, levels 0-1 and their origins
// are some 0.9 GB, and level 2 about 2.9 GB more while the last level is written. What stays:
// every level's vertex and face counts (face_offsets), the tags, and what the described arrays
// read (origin kinds of the finest level, parent faces for parent_face and base_face).
bool releases_coarser_levels(const RefineRequest& r, const MeshData& mesh) {
  return !r.keep_all_levels && mesh.face_varying.empty() && !r.limit_positions && !r.limit_normals;
}

template <class V>
void release(V& v) {
  V().swap(v);
}

// Unless the request says which arrays are described, parent faces are kept (4 bytes a
// face): a describer that reads them must never find them gone.
bool parent_faces_read(const RefineRequest& r) {
  return !r.described_arrays || r.described_arrays->has("parent_face") || r.described_arrays->has("base_face");
}

void release_faces(Level& L) { release(L.face_vertices), release(L.face_edges), release(L.edge_vertices); }

// With `faces_wait`, the level's faces, face edges and edge ends stay for the next level's
// deferred faces (add_deferred_faces), released by release_faces after.
void release_step(Hierarchy& h, int step, const RefineRequest& r, bool faces_wait) {
  Level& L = h.levels[size_t(step)];
  if (!faces_wait) release_faces(L);
  release(L.edge_faces);
  release(L.vertex_ring_offsets), release(L.vertex_edges), release(L.vertex_face_offsets);
  release(L.vertex_faces), release(L.vertex_face_corner), release(L.vertex_on_boundary);
  ChildOrigins& o = h.origins[size_t(step)];
  release(o.parent), release(o.local), release(o.corner_side);
  const bool finest_next = size_t(step) + 2 == h.levels.size();
  if (!finest_next) release(o.kind);
  if (!parent_faces_read(r)) release(o.parent_face);
}

}  // namespace

PreparedRefinement prepare_refinement(RefineRequest& r) {
  check_request(r);
  PreparedRefinement p;
  p.sequence = load_request_scheme(r, p.scheme_label);
  if (!r.mesh_file.empty()) {
    say(r, fmt::format("reading {}", r.mesh_file));
    r.mesh = read_mesh(r.mesh_file, r.progress_fraction);  // a bar while a large file is read
    if (r.mesh_name.empty()) r.mesh_name = r.mesh_file;
  }
  MeshCleanup cleanup;
  p.mesh = drop_unrefinable(std::move(r.mesh), cleanup);
  p.warnings = p.mesh.warnings;
  for (auto& w : cleanup.warnings(r.mesh_name)) p.warnings.push_back(std::move(w));
  const bool per_vertex = !r.vertex_parameters.empty() || !r.vertex_parameter_files.empty();
  if (per_vertex && cleanup.dropped_vertices > 0)
    throw OptionError(fmt::format("{}: {{vertex_param}} gives values in the input's vertex order, but unused "
                                  "vertices were dropped (see the warning) and the rest renumbered; remove them from "
                                  "the mesh first",
                                  r.mesh_name));
  find_weights(r, p);
  p.base = tagged_base(r, p.mesh, p.notes);
  // A triangle scheme on quads: named with the mesh's file or name here (the engine checks
  // every level again, naming the scheme's file).
  if (!r.mesh_name.empty()) check_face_sizes(*p.sequence.schemes.front(), p.base, r.mesh_name);
  p.options.levels = p.sequence.total_levels;
  p.options.features = feature_options(r.shape, p.mesh.options);
  p.options.first_step = r.start_level;
  p.options.vertex_parameters = r.vertex_parameters;
  for (auto& [name, values] : read_vertex_parameter_files(r.vertex_parameter_files, p.base.vertex_count))
    p.options.vertex_parameters[name] = std::move(values);
  p.face_varying = face_varying_mode(r.shape, p.mesh.options);
  p.tags = tags_in_force(p);
  return p;
}

namespace {

// Whether each level's topology is made just before its values (engine/topology_steps.h)
// rather than all levels first: when coarser levels are released (each is then gone before
// the level after next is made) and no per-vertex parameter is carried through the levels.
bool topology_level_by_level(const RefineRequest& r, const MeshData& mesh, const RefineOptions& options) {
  return releases_coarser_levels(r, mesh) && options.vertex_parameters.empty();
}

// A face-varying array refined with the levels. Its seams refine as boundaries (and in the
// mode `all` every edge as a crease), so a scheme without boundary rules fails here on a
// closed mesh that refines: the message says that the data, not the mesh, needs them.
std::vector<FaceVaryingLevel> refined_face_varying(const SchemeSequence& seq, const Hierarchy& h,
                                                   const FaceVaryingArray& a, FaceVaryingLinear mode,
                                                   const RefineOptions& options) {
  try {
    return refine_face_varying(seq.runs, h, {a.values, a.indices}, a.components, mode, options);
  } catch (const Error& e) {
    const bool rules_missing = std::any_of(seq.runs.begin(), seq.runs.end(),
                                           [](const SchemeRun& run) { return !has_feature_rules(*run.scheme); });
    if (!rules_missing) throw Error(fmt::format("face-varying array {}: {}", subdiv::quoted(a.name), e.what()));
    throw Error(fmt::format("face-varying array {} (UVs: OBJ vt): {}. Its seams refine as boundaries (face-varying "
                            "interpolation {}); a scheme without boundary rules cannot refine it: give the scheme a "
                            "\"curve\", or remove the array from the input",
                            subdiv::quoted(a.name), e.what(), face_varying_linear_name(mode)));
  }
}

// refine_level_data; with `releasing` (h itself), each coarser level's topology is released
// once the next level's values are made, where the request lets it (releases_coarser_levels);
// with `stepwise` too, h holds the base level alone and each level's topology is made here,
// just before its values, and a faces-only last level's faces after its values, once its
// parent's rings and edges are gone (at level 3 of a 1M-quad mesh, 1.28 GB of faces and
// 0.26 GB of parent faces are not alive with level 2's 1.9 GB of topology).
std::vector<LevelData> level_data(const PreparedRefinement& p, const Hierarchy& h, Hierarchy* releasing, bool stepwise,
                                  const MeshData& mesh, const RefineOptions& options, const RefineRequest& r,
                                  LevelDataNotes& said) {
  const SchemeSequence& seq = p.sequence;
  std::vector<std::string> dropped;
  std::vector<LevelData> levels{{mesh.positions, carried_point_arrays(mesh.point_data, &dropped), mesh.cell_data, {}}};
  check_finite_arrays(levels.front(), r.mesh_name);
  for (const auto& name : dropped)
    said.notes.push_back(fmt::format("point array {} holds normals, which refinement does not carry (a mix of unit "
                                     "normals is no normal); {{normals}} writes the exact limit normals",
                                     subdiv::quoted(name)));
  said.dropped_arrays.insert(said.dropped_arrays.end(), dropped.begin(), dropped.end());
  // Rational: the positions become (w·p, w)'s first three coordinates; the weights are
  // refined with them as point data, by the same rules, in the same pass.
  if (p.rational) to_homogeneous(levels.front().positions, weights_of(levels.front(), p.weights_name)->values);
  if (seq.total_levels > 0) say_done(r, 0.0);
  // The bar moves within a level too: the engine tells each pass of the level's step (the
  // level's end is told below, once its points are checked).
  int level = 0;
  LevelShares shares(h, seq.total_levels);
  const StepProgressScope::Report within = [&](double share) {
    if (share < 1) say_done(r, shares.done(level, share));
  };
  std::optional<StepProgressScope> passes;
  if (r.progress_fraction) passes.emplace(within);
  const bool releases = releasing && releases_coarser_levels(r, mesh);
  for (int l = 0; l < seq.total_levels; ++l) {
    bool faces_later = false;
    if (stepwise) {
      // A last level without cell data to inherit (which reads its faces) may wait for its faces.
      const bool may_wait = l + 1 == seq.total_levels && levels.back().cell_data.empty();
      faces_later = refine_next_level(seq.runs, *releasing, options, may_wait);
    }
    say(r, fmt::format("level {}/{}: {} faces", l + 1, seq.total_levels,
                       faces_later ? deferred_face_count(seq.runs, h) : h.levels[size_t(l) + 1].face_count()));
    level = l;
    const std::vector<SchemeRun> runs = stepwise ? runs_made(seq.runs, h) : seq.runs;
    levels.push_back(next_level_data(runs, h, l, levels.back(), options));
    check_refined_points(levels.back(), l + 1, mesh.positions, r);
    if (!r.keep_all_levels) levels[size_t(l)] = {};
    if (releases) release_step(*releasing, l, r, faces_later);
    if (faces_later) {
      add_deferred_faces(seq.runs, *releasing);
      release_faces(releasing->levels[size_t(l)]);
      if (!parent_faces_read(r)) release(releasing->origins[size_t(l)].parent_face);
    }
    say_done(r, shares.done(l + 1));
  }
  passes.reset();  // the face-varying steps below are not the levels' bar
  if (p.rational) project_levels(levels, p.weights_name, mesh.positions);
  rename_weights(levels, p);
  for (const FaceVaryingArray& a : mesh.face_varying) {
    if (a.role == ArrayRole::Normals) {
      said.dropped_arrays.push_back(a.name);
      said.notes.push_back(fmt::format("face-varying array {} holds normals, which refinement does not carry; "
                                       "{{normals}} writes the exact limit normals",
                                       subdiv::quoted(a.name)));
      continue;
    }
    const auto refined = refined_face_varying(seq, h, a, p.face_varying, options);
    for (size_t l = 0; l < levels.size(); ++l)
      if (r.keep_all_levels || l + 1 == levels.size())
        levels[l].face_varying.push_back({a.name, a.components, refined[l].values, refined[l].indices, a.role});
  }
  return levels;
}

}  // namespace

std::vector<LevelData> refine_level_data(const PreparedRefinement& p, const Hierarchy& h, const MeshData& mesh,
                                         const RefineOptions& options, const RefineRequest& r, LevelDataNotes& said) {
  return level_data(p, h, nullptr, false, mesh, options, r, said);
}

bool last_level_faces_suffice(const RefineRequest& request, const PreparedRefinement& prepared) {
  return last_level_faces_suffice(request, prepared.mesh, prepared.base);
}

RefineResult run_refinement(PreparedRefinement&& p, const RefineRequest& r) {
  check_fits_in_memory(*p.sequence.schemes.front(), p.base, p.sequence.total_levels, r.memory_budget,
                       r.memory_advice);
  RefineResult out;
  p.options.faces_only_last_level = last_level_faces_suffice(r, p.mesh, p.base);
  const bool stepwise = topology_level_by_level(r, p.mesh, p.options);
  say(r, fmt::format("refining topology: {} levels of {}{}{}", p.sequence.total_levels, p.scheme_label,
                     stepwise ? ", each level's just before its points" : "",
                     p.options.faces_only_last_level ? " (last level: faces only)" : ""));
  out.hierarchy = stepwise ? start_topology(std::move(p.base), p.options)
                           : refine_topology(p.sequence.runs, std::move(p.base), p.options);
  LevelDataNotes said;
  out.levels = level_data(p, out.hierarchy, &out.hierarchy, stepwise, p.mesh, p.options, r, said);
  out.warnings = std::move(p.warnings);
  out.warnings.insert(out.warnings.end(), out.hierarchy.warnings.begin(), out.hierarchy.warnings.end());
  out.notes = std::move(p.notes);
  out.notes.insert(out.notes.end(), said.notes.begin(), said.notes.end());
  out.dropped_arrays = std::move(said.dropped_arrays);
  if (r.limit_positions || r.limit_normals) {
    say(r, r.limit_positions ? "limit positions and normals" : "limit normals");
    LimitArrays limits = limit_arrays(p.sequence, out.hierarchy, p.options, out.levels.back(), r.limit_positions,
                                      r.mesh_name,
                                      p.rational ? output_weights_name(p) : std::string());
    out.finest_point_data = std::move(limits.point_data);
    out.warnings.insert(out.warnings.end(), limits.warnings.begin(), limits.warnings.end());
    out.limit_warnings = std::move(limits.warnings);
    limits.result.positions.clear(), limits.result.normals.clear();
    out.limit_note = limit_note(r, limits.result);
    out.limit = std::move(limits.result);
  }
  out.sequence = std::move(p.sequence);
  out.scheme_label = std::move(p.scheme_label);
  out.features = p.options.features;
  out.tags = std::move(p.tags);
  return out;
}

RefineResult refine_mesh(RefineRequest request) {
  PreparedRefinement prepared = prepare_refinement(request);
  return run_refinement(std::move(prepared), request);
}

}  // namespace subdiv
