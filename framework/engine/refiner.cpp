#include "framework/engine/refiner.h"

#include <algorithm>
#include <fmt/format.h>
#include <optional>

#include "framework/engine/level_passes.h"
#include "framework/engine/topology_steps.h"
#include "framework/refine/primal_topology.h"
#include "framework/topology/non_manifold_place.h"
#include "framework/util/step_progress.h"
#include "framework/engine/step_preparation.h"
#include "framework/engine/vertex_parameters.h"
#include "framework/features/base_tags.h"
#include "framework/rules/stage_times.h"
#include "framework/rules/stencil_builder.h"
#include "framework/rules/step_evaluator.h"
#include "framework/scheme/scheme.h"
#include "framework/util/bulk_memory.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/util/scratch_vector.h"
#include "framework/util/streaming_stores.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

int needed_face_size(const Scheme& scheme) {
  if (scheme.required_face_size) return scheme.required_face_size;
  return splitter_info(scheme.split()).required_face_size;
}


// Splits that do not handle non-manifold levels (a plugin's that does not opt in through
// SplitterInfo::handles_non_manifold) refuse them clearly; every built-in split handles them.
void check_manifold_for(const Scheme& scheme, const Level& level) {
  if (level.manifold() || splitter_info(scheme.split()).handles_non_manifold) return;
  throw Error(fmt::format("{}: scheme {} uses the {} split, which needs a manifold mesh, but {}; or use a "
                          "scheme with a built-in split, which refine non-manifold meshes",
                          scheme.path, subdiv::quoted(scheme.name), subdiv::quoted(splitter_info(scheme.split()).name),
                          non_manifold_place(level)));
}

// A stage's name for EvaluationSwitches::stage_times: the level it makes, then what it does
// (nothing to format when no one times).
std::string stage(const RefineOptions& options, int level, std::string_view what) {
  return options.evaluation.stage_times ? fmt::format("L{} {}", level, what) : std::string();
}

// One pass's stencils: its parent's values to the values it writes.
StencilTable pass_stencils(const LevelPass& pass, const RefineOptions& options) {
  const StepInputs inputs = prepare_step(*pass.scheme, *pass.rules, *pass.parent, pass.level, options, *pass.parameters);
  return build_step_stencils(step_context(*pass.scheme, *pass.rules, inputs, *pass.parent, *pass.origins,
                                          pass.features_refined, pass.level, options));
}

// Output of at least this many bytes is larger than the caches: written with streaming
// stores when nothing reads it in the refinement (StepContext::stream_output).
constexpr size_t kStreamBytes = size_t(32) << 20;

// One pass applied to values without a table (rules/step_evaluator.h), into `out`.
// `last`: the pass writes the hierarchy's last level, which no later pass reads.
void pass_applied(const LevelPass& pass, const RefineOptions& options, std::span<const double> values,
                  std::span<double> out, int channels, bool last) {
  StageTimes* times = options.evaluation.stage_times;
  std::optional<StageTimer> timer(std::in_place, times, stage(options, pass.level + 1, "weight tables"));
  const StepInputs inputs =
      prepare_step(*pass.scheme, *pass.rules, *pass.parent, pass.level, options, *pass.parameters, /*lazy_features=*/true);
  StepContext context = step_context(*pass.scheme, *pass.rules, inputs, *pass.parent, *pass.origins,
                                     pass.features_refined, pass.level, options);
  context.stream_output = last && out.size() * sizeof(double) >= kStreamBytes && streaming_stores_wanted();
  timer.emplace(times, stage(options, pass.level + 1, "groups, plans, kernels"));
  StepEvaluator rows(context);
  timer.reset();
  rows.apply(values, out, channels, options.evaluation.row_paths);
}

// A child face inside a hole is a hole (OpenSubdiv's Vtr::Refinement passes the face tag on).
void pass_holes_down(const Level& parent, SplitResult& step) {
  if (parent.face_hole.empty()) return;
  const ScratchVector<Index>& from = step.origins.parent_face;
  Level& child = step.child;
  child.face_hole.assign(child.face_count(), 0);
  for (Index f = 0; f < child.face_count() && size_t(f) < from.size(); ++f)
    child.face_hole[f] = from[f] != kNone && parent.face_hole[from[f]];
}

}  // namespace

void check_face_sizes(const Scheme& scheme, const Level& base, std::string_view mesh_name, int level) {
  const int needed = needed_face_size(scheme);
  if (!needed || base.all_faces_have_size(needed)) return;  // in parallel; the loop below names the first
  const std::string of = level == 0 ? "the mesh" : fmt::format("level {} (made by the schemes before it)", level);
  for (Index f = 0; f < base.face_count(); ++f)
    if (base.face_size(f) != needed)
      throw OptionError(fmt::format("{}: scheme {} needs {}, but face {} of {} has {} vertices; "
                                    "{} the mesh first or choose a scheme for any polygons ({{scheme_list}} "
                                    "lists them)",
                              mesh_name.empty() ? std::string_view(scheme.path) : mesh_name, subdiv::quoted(scheme.name),
                              needed == 3 ? "triangles" : needed == 4 ? "quads" : fmt::format("{}-gons", needed), f,
                              of, base.face_size(f), needed == 3 ? "triangulate" : needed == 4 ? "quadrangulate" : "remesh"));
}

namespace {

// The base level's topological tags, in OpenSubdiv's order (features/base_tags.h).
void tag_base(Level& base, const RefineOptions& options) {
  StageTimer timer(options.evaluation.stage_times, stage(options, 0, "base tags"));
  tag_base_level(base, options.features.boundary);
}

// The origins of a faces-only split before its faces (topology_steps.h), where the split
// can give them: the primal splits, on a level without holes (holes pass down to faces).
std::optional<ChildOrigins> origins_first(SplitKind kind, const Level& parent) {
  if (!parent.face_hole.empty()) return std::nullopt;
  if (kind == SplitKind::Quad) return quad_split_origins(parent);
  if (kind == SplitKind::Triangle) return triangle_split_origins(parent);
  return std::nullopt;
}

// Adds level h.levels.size(), made by per_level[its index - 1]; true when its faces wait
// (refine_next_level's `faces_later`).
bool add_level(const std::vector<const Scheme*>& per_level, Hierarchy& h, const RefineOptions& options,
               bool faces_later) {
  const size_t l = h.levels.size() - 1;
  const Scheme& scheme = *per_level[l];
  const int made = int(l) + 1;
  StageTimes* times = options.evaluation.stage_times;
  std::optional<StageTimer> timer(std::in_place, times, stage(options, made, "face and manifold checks"));
  if (l == 0 || per_level[l - 1] != per_level[l]) check_face_sizes(scheme, h.levels.back(), {}, int(l));
  check_manifold_for(scheme, h.levels.back());
  // The last level may be faces only (RefineOptions::faces_only_last_level): then it
  // has no edges to carry tags to.
  const bool faces_only = options.faces_only_last_level && l + 1 == per_level.size() && scheme.steps.size() == 1 &&
                          !scheme.steps.front().nonlinear && splitter_info(scheme.split()).split_faces_only;
  timer.emplace(times, stage(options, made, "split"));
  if (faces_only && faces_later) {
    if (std::optional<ChildOrigins> origins = origins_first(scheme.split(), h.levels.back())) {
      Level child;
      child.vertex_count = Index(origins->kind.size());
      h.levels.push_back(std::move(child));
      h.origins.push_back(std::move(*origins));
      h.features_refined.push_back(true);  // as the primal splits say
      return true;
    }
  }
  SplitResult step = split(scheme.split(), h.levels.back(), options.first_step + int(l), faces_only);
  timer.emplace(times, stage(options, made, "tags"));
  if (splitter_info(scheme.split()).engine_propagates_tags && !faces_only)
    propagate_tags(h.levels.back(), step, options.features.crease_method);
  else if (options.features.crease_method == CreaseMethod::Chaikin && !step.averaged_edge_sharpness.empty())
    step.child.edge_sharpness = std::move(step.averaged_edge_sharpness);
  pass_holes_down(h.levels.back(), step);
  timer.reset();
  if (!step.warning.empty()) h.warnings.push_back(fmt::format("level {}: {}", l + 1, step.warning));
  h.levels.push_back(std::move(step.child));
  h.origins.push_back(std::move(step.origins));
  h.features_refined.push_back(step.features_refined);
  return false;
}

}  // namespace

Hierarchy refine_topology(std::span<const SchemeRun> runs, Level base, const RefineOptions& options) {
  const std::vector<const Scheme*> per_level = schemes_per_level(runs);
  Hierarchy h = start_topology(std::move(base), options);
  for (size_t l = 0; l < per_level.size(); ++l) add_level(per_level, h, options, false);
  h.vertex_parameters = carried_parameters(per_level, h, options.vertex_parameters);
  return h;
}

Hierarchy start_topology(Level base, const RefineOptions& options) {
  tag_base(base, options);
  Hierarchy h;
  h.levels.push_back(std::move(base));
  return h;
}

bool refine_next_level(std::span<const SchemeRun> runs, Hierarchy& h, const RefineOptions& options, bool faces_later) {
  const std::vector<const Scheme*> per_level = schemes_per_level(runs);
  if (h.levels.empty() || h.levels.size() > per_level.size())
    throw Error(fmt::format("refine_next_level: the hierarchy has {} level(s) of {}", h.levels.size(),
                            per_level.size() + 1));
  return add_level(per_level, h, options, faces_later);
}

namespace {

// Whether the quad split (else the triangle split: origins_first) made h's last level.
bool last_made_by_quad_split(std::span<const SchemeRun> runs, const Hierarchy& h) {
  return schemes_per_level(runs)[h.levels.size() - 2]->split() == SplitKind::Quad;
}

}  // namespace

Index deferred_face_count(std::span<const SchemeRun> runs, const Hierarchy& h) {
  const Level& parent = h.levels[h.levels.size() - 2];
  return last_made_by_quad_split(runs, h) ? parent.corner_count() : 4 * parent.face_count();
}

void add_deferred_faces(std::span<const SchemeRun> runs, Hierarchy& h) {
  const Level& parent = h.levels[h.levels.size() - 2];
  const bool quad = last_made_by_quad_split(runs, h);
  Level faces = quad ? quad_split_faces(parent) : triangle_split_faces(parent);
  Level& child = h.levels.back();
  if (faces.vertex_count != child.vertex_count)
    throw Error(fmt::format("add_deferred_faces: {} vertices, but the origins gave {}", faces.vertex_count,
                            child.vertex_count));
  child.face_offsets = std::move(faces.face_offsets);
  child.face_vertices = std::move(faces.face_vertices);
  if (quad) add_quad_parent_faces(parent, h.origins.back());
  else add_triangle_parent_faces(parent, h.origins.back());
}

std::vector<SchemeRun> runs_made(std::span<const SchemeRun> runs, const Hierarchy& h) {
  std::vector<SchemeRun> made;
  int left = int(h.levels.size()) - 1;
  for (const SchemeRun& run : runs) {
    if (left <= 0) break;
    made.push_back({run.scheme, std::min(run.levels, left)});
    left -= made.back().levels;
  }
  return made;
}

void build_stencils(std::span<const SchemeRun> runs, Hierarchy& h, const RefineOptions& options) {
  const LevelPasses passes(runs, h, options, 0, int(h.levels.size()) - 1, "build_stencils");
  std::vector<StencilTable> stencils;
  std::vector<std::shared_ptr<const DirectStep>> direct(size_t(passes.step_count()), nullptr);
  for (int l = 0; l < passes.step_count(); ++l) {
    const std::span<const LevelPass> step = passes.of_step(l);
    if (step.front().nonlinear()) {
      direct[size_t(l)] = direct_step(*step.front().scheme, h, size_t(l), step.front().level, options);
      StencilTable none;  // no rows: apply_step() runs the rule
      none.source_count = h.levels[size_t(l)].vertex_count;
      stencils.push_back(std::move(none));
      continue;
    }
    // Smoothing passes move the new level's vertices; compose them into one table.
    StencilTable table = pass_stencils(step.front(), options);
    for (const LevelPass& smoothing : step.subspan(1)) table = compose(table, pass_stencils(smoothing, options));
    stencils.push_back(std::move(table));
  }
  h.stencils = std::move(stencils);
  h.direct = std::move(direct);
}

Hierarchy refine(std::span<const SchemeRun> runs, Level base, const RefineOptions& options) {
  Hierarchy h = refine_topology(runs, std::move(base), options);
  build_stencils(runs, h, options);
  return h;
}

Hierarchy refine_topology(const Scheme& scheme, Level base, const RefineOptions& options) {
  if (options.levels < 0) throw OptionError(fmt::format("{{levels}} must be 0 or more, not {}", options.levels));
  const SchemeRun run{&scheme, options.levels};
  return refine_topology(std::span(&run, 1), std::move(base), options);
}

void build_stencils(const Scheme& scheme, Hierarchy& h, const RefineOptions& options) {
  const SchemeRun run{&scheme, int(h.levels.size()) - 1};
  build_stencils(std::span(&run, 1), h, options);
}

Hierarchy refine(const Scheme& scheme, Level base, const RefineOptions& options) {
  Hierarchy h = refine_topology(scheme, std::move(base), options);
  build_stencils(scheme, h, options);
  return h;
}

std::vector<double> interpolate(const Hierarchy& h, int to_level, std::span<const double> base_values, int channels) {
  if (to_level < 0 || to_level > int(h.stencils.size()))
    throw Error(fmt::format("interpolate: level {} is not in 0..{}", to_level, h.stencils.size()));
  std::vector<double> values(base_values.begin(), base_values.end());
  for (int l = 0; l < to_level; ++l) values = apply_step(h, l, values, channels);
  return values;
}

std::vector<double> apply_step(const Hierarchy& h, int step, std::span<const double> values, int channels) {
  if (step < 0 || step >= int(h.stencils.size()))
    throw Error(fmt::format("apply_step: step {} is not in 0..{}", step, int(h.stencils.size()) - 1));
  const DirectStep* direct = size_t(step) < h.direct.size() ? h.direct[step].get() : nullptr;
  if (!direct) return h.stencils[step].apply(values, channels);
  return run_direct_step(*direct, h, step, values, channels);
}

void step_values(std::span<const SchemeRun> runs, const Hierarchy& h, int step, std::span<const double> values,
                 std::span<double> out, int channels, const RefineOptions& options) {
  if (step < 0 || step + 1 >= int(h.levels.size()))
    throw Error(fmt::format("step_values: step {} is not in 0..{}", step, int(h.levels.size()) - 2));
  std::optional<StageTimer> timer(std::in_place, options.evaluation.stage_times, stage(options, step + 1, "passes"));
  const LevelPasses prepared(runs, h, options, step, step + 1, "step_values");
  timer.reset();
  if (values.size() != size_t(h.levels[step].vertex_count) * size_t(channels))
    throw Error(fmt::format("step_values: {} values for {} vertices of {} channels", values.size(),
                            h.levels[step].vertex_count, channels));
  const Level& child = h.levels[step + 1];
  if (out.size() != size_t(child.vertex_count) * size_t(channels))
    throw Error(fmt::format("step_values: room for {} values, but level {} has {} vertices of {} channels", out.size(),
                            step + 1, child.vertex_count, channels));
  const std::span<const LevelPass> passes = prepared.of_step(step);
  if (passes.front().nonlinear()) {
    const std::vector<double> direct = run_direct_step(
        *direct_step(*passes.front().scheme, h, size_t(step), passes.front().level, options), h, step, values, channels);
    std::copy(direct.begin(), direct.end(), out.begin());
    return;
  }
  // Smoothing passes, one after another (build_stencils composes their tables instead, so
  // the last bits may differ), between `out` and one scratch level: the last pass writes `out`.
  const size_t count = passes.size();
  ScratchVector<double> scratch(count > 1 ? out.size() : 0);
  const auto target = [&](size_t s) { return (count - 1 - s) % 2 == 0 ? out : std::span<double>(scratch); };
  const bool last_level = size_t(step) + 2 == h.levels.size();
  for (size_t s = 0; s < count; ++s) {
    const StepProgressScope::Report part = StepProgressScope::part(s, count);
    const StepProgressScope within(part);  // the pass tells its own rows' share
    pass_applied(passes[s], options, s == 0 ? values : target(s - 1), target(s), channels,
                 last_level && s + 1 == count);
  }
}

void step_values(const Scheme& scheme, const Hierarchy& h, int step, std::span<const double> values,
                 std::span<double> out, int channels, const RefineOptions& options) {
  const SchemeRun run{&scheme, int(h.levels.size()) - 1};
  step_values(std::span(&run, 1), h, step, values, out, channels, options);
}

std::vector<double> step_values(std::span<const SchemeRun> runs, const Hierarchy& h, int step,
                                std::span<const double> values, int channels, const RefineOptions& options) {
  if (step < 0 || step + 1 >= int(h.levels.size()))
    throw Error(fmt::format("step_values: step {} is not in 0..{}", step, int(h.levels.size()) - 2));
  std::vector<double> out;
  resize_bulk(out, size_t(h.levels[size_t(step) + 1].vertex_count) * size_t(std::max(channels, 0)));
  step_values(runs, h, step, values, out, channels, options);
  return out;
}

std::vector<double> step_values(const Scheme& scheme, const Hierarchy& h, int step, std::span<const double> values,
                                int channels, const RefineOptions& options) {
  const SchemeRun run{&scheme, int(h.levels.size()) - 1};
  return step_values(std::span(&run, 1), h, step, values, channels, options);
}

}  // namespace subdiv
