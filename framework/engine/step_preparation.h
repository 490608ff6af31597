#pragma once
// What the driver (refiner.cpp) and repeated evaluation (evaluator.cpp) prepare for a step
// before any values pass through it: the step's weight tables, its per-vertex rules and
// feature contexts, the StepContext the rules read, and non-linear steps' rules. Internal
// to the engine layer (not installed).
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/rules/step_rows.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_run.h"

namespace subdiv {

// The step's feature contexts, and (when they are left for the first row that needs them,
// StepContext::classify) what computes them in place, once. Held on the heap: the step's
// context points into it while StepInputs moves.
struct StepFeatures {
  FeatureContexts contexts;
  std::once_flag classified;
  std::function<void()> classify;  // empty: `contexts` are ready
};

// What one step's rows need besides the topology: its weight tables (and, with per-vertex
// parameters, its vertex rules per vertex) and feature contexts.
struct StepInputs {
  WeightTables tables;
  std::unique_ptr<PerVertexTables> per_vertex;
  std::unique_ptr<StepFeatures> features;
};

// `values`: the per-vertex parameters on `parent`. With `lazy_features`, a level without
// sharpness tags gets its feature contexts only when a row first needs them: the kernels
// compute its smooth points from topology alone, so a closed manifold mesh never does, and
// classifying every vertex and edge is a tenth of a step. Keeps a reference to `parent`.
StepInputs prepare_step(const Scheme& scheme, const StepRules& step, const Level& parent, int level,
                        const RefineOptions& options, const VertexParameters& values, bool lazy_features = false);

// The context the rules read; it refers to `inputs`, `parent` and `origins`.
StepContext step_context(const Scheme& scheme, const StepRules& step, const StepInputs& inputs, const Level& parent,
                         const ChildOrigins& origins, bool features_refined, int level, const RefineOptions& options);

// The scheme of each level, in order.
std::vector<const Scheme*> schemes_per_level(std::span<const SchemeRun> runs);

// A non-linear step (plugins): no table says it, its rule is run on the values.
std::shared_ptr<DirectStep> direct_step(const Scheme& scheme, const Hierarchy& h, size_t l, int level,
                                        const RefineOptions& options);
std::vector<double> run_direct_step(const DirectStep& direct, const Hierarchy& h, int step,
                                    std::span<const double> values, int channels);

}  // namespace subdiv
