#pragma once
// The engine's driver: refine topology level by level, then carry any per-vertex data to
// the finer levels, through one stencil table per step or straight from the rules.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framework/refine/child_origins.h"
#include "framework/refine/child_tags.h"
#include "framework/rules/code_rules.h"
#include "framework/rules/row_paths.h"
#include "framework/features/feature_context.h"
#include "framework/scheme/scheme_run.h"
#include "framework/stencil/stencil_table.h"
#include "framework/topology/level.h"

namespace subdiv {

class StageTimes;        // rules/stage_times.h
class WeightTableCache;  // engine/weight_table_cache.h

// Parameter name -> one value per vertex of the base mesh.
using VertexParameters = std::map<std::string, std::vector<double>>;

// How step_values and the Evaluator compute values, never what they are: switches for tests
// and benchmarks that compare the engine's evaluation paths or count them. Every setting
// gives the same values; the defaults are the fastest. (The number of threads is the
// caller's: a scoped limit, pipeline/thread_limit.h, or TBB's own global_control.)
struct EvaluationSwitches {
  // Smooth interior rows replayed from learnt plans (rules/row_plans.h): the same rows,
  // faster; off only to compare or measure.
  bool use_row_plans = true;
  // Smooth interior elements computed by the compiled kernels (rules/smooth_kernels.h); off
  // only to compare or measure.
  bool use_kernels = true;
  // Where to count the children computed by kernels, plans and the generic interpreter
  // (rules/row_paths.h), or null.
  RowPaths* row_paths = nullptr;
  // Where to add each stage's wall and CPU time (rules/stage_times.h: topology, weight
  // tables, the step's set-up, each kind of new point), or null; for benchmarks.
  StageTimes* stage_times = nullptr;
  // Where to keep the steps' weight tables for later refinements of the same scheme, or
  // null (each refinement compiles its own); for many small refinements in a row.
  WeightTableCache* weight_tables = nullptr;
};

// How to refine: the surface's shape (features: boundary interpolation and crease method, as
// OpenSubdiv's Sdc::Options), how many levels from which step, what the last level needs,
// and per-vertex parameters.
struct RefineOptions {
  int levels = 1;
  FeatureOptions features;  // boundary interpolation and crease method, as in OpenSubdiv
  // How many steps the input mesh has already been through (schemes whose steps alternate,
  // such as sqrt3's boundary trisection, count from the original mesh; also the level l
  // seen by level-dependent formulas).
  int first_step = 0;
  // Build the last level's faces only (no edges, vertex rings or feature tags), as
  // OpenSubdiv's default UniformOptions does: enough for step_values, the level's data
  // (primvar/level_data.h) and writing the mesh, not for analysis, limit positions,
  // normals or refining further. Taken only where it is safe: the built-in primal splits,
  // with one step and linear rules (smoothing passes and non-linear rules read the new
  // level's rings); otherwise the last level is complete anyway.
  bool faces_only_last_level = false;
  // How values are computed, for tests and benchmarks (see EvaluationSwitches).
  EvaluationSwitches evaluation;
  // Values of the schemes' per-vertex parameters ("per_vertex": true in the scheme file,
  // e.g. Lin et al. 2015's lambda), one per base vertex: a vertex rule reads the value at its
  // vertex; later levels carry them linearly (engine/vertex_parameters.h). Schemes that
  // do not declare a name ignore it; a name no scheme of the run declares is an error.
  VertexParameters vertex_parameters;
};

// A step of a non-linear scheme (plugins, rules/code_rules.h): applied to the values
// directly, since no stencil table can say it.
struct DirectStep {
  std::shared_ptr<const NonlinearRule> rule;
  FeatureContexts features;
  bool features_refined = true;
  int level = 0;
};

struct Hierarchy {
  std::vector<Level> levels;           // levels[0] is the base mesh
  std::vector<ChildOrigins> origins;   // origins[i] describes levels[i + 1]
  std::vector<StencilTable> stencils;  // stencils[i] maps level i values to level i + 1
  std::vector<bool> features_refined;  // per step: were boundaries and creases refined
  // Per step: set when the step is non-linear; stencils[i] is then empty (no rows) and
  // apply_step() runs the rule instead. Empty (or all null) for linear schemes.
  std::vector<std::shared_ptr<const DirectStep>> direct;
  // The per-vertex parameters (RefineOptions::vertex_parameters) on each level a step's
  // passes read, carried once by refine_topology (engine/level_passes.h); empty without any.
  std::vector<VertexParameters> vertex_parameters;
  // What steps did differently from their usual result (SplitResult::warning), one line each.
  std::vector<std::string> warnings;

  bool linear() const {
    for (const auto& d : direct)
      if (d) return false;
    return true;
  }
};

// Throws subdiv::OptionError naming the first face whose size the scheme cannot refine (a
// triangle scheme on quads) and the fix; refinement checks it, and so does whatever takes a
// mesh for a scheme without refining it first (the limit surface). The message starts with
// `mesh_name` (the mesh's file or name, where the caller knows it), else with the scheme's
// file; `level` > 0: the faces are those of that level (a sequence's later scheme).
void check_face_sizes(const Scheme& scheme, const Level& base, std::string_view mesh_name = {}, int level = 0);

// Refines topology only (levels and origins), as OpenSubdiv's RefineUniform does.
Hierarchy refine_topology(const Scheme& scheme, Level base, const RefineOptions& options);
Hierarchy refine_topology(std::span<const SchemeRun> runs, Level base, const RefineOptions& options);
// Builds the stencil tables for a refined hierarchy.
void build_stencils(const Scheme& scheme, Hierarchy& hierarchy, const RefineOptions& options);
void build_stencils(std::span<const SchemeRun> runs, Hierarchy& hierarchy, const RefineOptions& options);
// Both of the above. With runs, options.levels is ignored: the runs say how many.
Hierarchy refine(const Scheme& scheme, Level base, const RefineOptions& options);
Hierarchy refine(std::span<const SchemeRun> runs, Level base, const RefineOptions& options);

// Values (channels per vertex) of level `step` carried to level step + 1: through the
// stencil table, or the non-linear rule of a direct step.
std::vector<double> apply_step(const Hierarchy& hierarchy, int step, std::span<const double> values, int channels);

// Values of level `step` carried to level step + 1 straight from the rules, with no stencil
// table (rules/step_evaluator.h): needs only refine_topology's hierarchy, and is faster
// and smaller than build_stencils + apply_step. The same values to round-off: the same
// bits where the rules use no new points; new points a rule uses are read back rather than
// expanded, and smoothing passes are applied one after another rather than composed, which
// changes the last bits. The same bits for any thread count.
std::vector<double> step_values(std::span<const SchemeRun> runs, const Hierarchy& topology, int step,
                                std::span<const double> values, int channels, const RefineOptions& options);
std::vector<double> step_values(const Scheme& scheme, const Hierarchy& topology, int step,
                                std::span<const double> values, int channels, const RefineOptions& options);
// The same into `out` (the next level's vertex count x channels), memory the caller owns and
// may reuse: every value is written, so it need not be zero-filled first (an
// std::vector's resize fills it on one thread; subdiv::ScratchVector, util/scratch_vector.h,
// leaves it to the step's parallel loops to touch first).
void step_values(std::span<const SchemeRun> runs, const Hierarchy& topology, int step, std::span<const double> values,
                 std::span<double> out, int channels, const RefineOptions& options);
void step_values(const Scheme& scheme, const Hierarchy& topology, int step, std::span<const double> values,
                 std::span<double> out, int channels, const RefineOptions& options);

// Values (channels per vertex) of the base level carried to level `to_level`.
std::vector<double> interpolate(const Hierarchy& hierarchy, int to_level,
                                std::span<const double> base_values, int channels);

}  // namespace subdiv
