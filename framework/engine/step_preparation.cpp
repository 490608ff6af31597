#include "framework/engine/step_preparation.h"

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <tbb/task_arena.h>

#include "framework/engine/vertex_parameters.h"
#include "framework/engine/weight_table_cache.h"
#include "framework/rules/end_sectors.h"
#include "framework/rules/kernel_contexts.h"
#include "framework/scheme/step_tables.h"
#include "framework/util/distinct_values.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// The distinct valences of the level's vertices, ascending: the end valences a rule of n0,
// n1 is tabulated at (a fan's hub and rim, not every valence up to the hub's). One parallel
// pass, whose last entry is also the largest valence (Level::max_valence would be another).
std::vector<int> valences_present(const Level& L) {
  return distinct_values(L.vertex_count, Index(1 << 16), [&L](Index v, auto add) { add(L.valence(v)); });
}

}  // namespace

StepInputs prepare_step(const Scheme& scheme, const StepRules& step, const Level& parent, int level,
                        const RefineOptions& options, const VertexParameters& values, bool lazy_features) {
  LevelValences present{valences_present(parent), {}};
  const int max_n = present.valences.empty() ? 0 : present.valences.back(), max_k = parent.max_face_size();
  auto compile = [&](int n, int k, const LevelValences& p) {
    return step_weight_tables(scheme, step, n, k, level, nullptr, &p);
  };
  WeightTableCache* cache = options.evaluation.weight_tables;
  auto tables = [&] {
    return cache ? cache->get(step, level, max_n, max_k, present, compile) : compile(max_n, max_k, present);
  };
  WeightTables compiled = tables();
  // The sector sizes (a pass over every ring of a tagged level) only for rules that read them.
  if (reads_sector_sizes(compiled)) {
    present.sector_sizes = sector_sizes_present(parent);
    compiled = tables();
  }
  StepInputs inputs{std::move(compiled), per_vertex_tables(scheme, step, parent, values, max_n, max_k, level),
                    std::make_unique<StepFeatures>()};
  StepFeatures& f = *inputs.features;
  if (!lazy_features || !without_sharpness_tags(parent)) {
    f.contexts = classify_features(parent, options.features);
    return inputs;
  }
  f.classify = [&parent, features = options.features, &f] {
    // Isolated: while this thread classifies, it must not pick up another row task of the
    // step, which would wait on the same once_flag.
    std::call_once(f.classified, [&] {
      tbb::this_task_arena::isolate([&] { f.contexts = classify_features(parent, features); });
    });
  };
  return inputs;
}

StepContext step_context(const Scheme& scheme, const StepRules& step, const StepInputs& inputs, const Level& parent,
                         const ChildOrigins& origins, bool features_refined, int level, const RefineOptions& options) {
  // Row plans replay one vertex's row for another of the same shape: not when their rules differ.
  const bool plans = options.evaluation.use_row_plans && !inputs.per_vertex;
  StepContext s{parent,      origins,         inputs.tables, inputs.features->contexts, features_refined,
                scheme.path, step.code.get(), level,         plans};
  s.per_vertex = inputs.per_vertex.get();
  s.use_kernels = options.evaluation.use_kernels;
  s.stage_times = options.evaluation.stage_times;
  s.classify = inputs.features->classify ? &inputs.features->classify : nullptr;
  return s;
}

std::vector<const Scheme*> schemes_per_level(std::span<const SchemeRun> runs) {
  std::vector<const Scheme*> per_level;
  for (const SchemeRun& run : runs) {
    if (run.levels < 0) throw Error(fmt::format("scheme {} is given {} levels; give 0 or more", subdiv::quoted(run.scheme->name), run.levels));
    per_level.insert(per_level.end(), size_t(run.levels), run.scheme);
  }
  return per_level;
}

std::shared_ptr<DirectStep> direct_step(const Scheme& scheme, const Hierarchy& h, size_t l, int level,
                                        const RefineOptions& options) {
  if (scheme.steps.size() != 1)
    throw Error(fmt::format("{}: a non-linear scheme has one step (its rule does the whole level)", scheme.path));
  auto direct = std::make_shared<DirectStep>();
  direct->rule = scheme.steps.front().nonlinear;
  direct->features = classify_features(h.levels[l], options.features);
  direct->features_refined = h.features_refined[l];
  direct->level = level;
  return direct;
}

std::vector<double> run_direct_step(const DirectStep& direct, const Hierarchy& h, int step,
                                    std::span<const double> values, int channels) {
  const Level& parent = h.levels[step];
  const Level& child = h.levels[step + 1];
  if (values.size() != size_t(parent.vertex_count) * size_t(channels))
    throw Error(fmt::format("apply_step: {} values for {} vertices of {} channels", values.size(), parent.vertex_count,
                            channels));
  std::vector<double> out(size_t(child.vertex_count) * size_t(channels), std::numeric_limits<double>::quiet_NaN());
  (*direct.rule)({parent, child, h.origins[step], direct.features, direct.features_refined, direct.level}, values,
                 out, channels);
  for (size_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i]))
      throw Error(fmt::format("the non-linear rule of level {} left child vertex {} at {} (every child value must be "
                              "set and finite)", direct.level, i / size_t(channels), out[i]));
  return out;
}

}  // namespace subdiv
