#pragma once
// The passes of a refinement's steps, in order: what build_stencils turns into tables,
// step_values applies to one step's values and the Evaluator makes ready once. A linear
// step is its split's rows on the parent level, then each smoothing pass on the new level
// (identity origins, features refined); a non-linear step is its rule. Internal to the
// engine layer (not installed).
#include <memory>
#include <span>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_run.h"

namespace subdiv {

struct LevelPass {
  const Scheme* scheme = nullptr;
  const StepRules* rules = nullptr;  // null: a non-linear step, its rule run on the values
  int step = 0;                      // the hierarchy's step: level `step` to level step + 1
  int level = 0;                     // RefineOptions::first_step + step, as level-dependent formulas see it
  bool smoothing = false;            // a smoothing pass on the new level (not the split's rows)
  const Level* parent = nullptr;     // the level whose values the pass reads
  const ChildOrigins* origins = nullptr;  // where each value the pass writes comes from
  bool features_refined = true;
  const VertexParameters* parameters = nullptr;  // the per-vertex parameters on *parent
  Index target_count = 0;                        // values (vertices) the pass writes

  bool nonlinear() const { return rules == nullptr; }
};

class LevelPasses {
public:
  // The passes of steps [first, last) of `h` refined by `runs`. Checks that the runs match
  // the hierarchy and the per-vertex parameters (check_vertex_parameters); `caller` names
  // the function in messages. The passes refer to `h`, the runs' schemes and this object.
  LevelPasses(std::span<const SchemeRun> runs, const Hierarchy& h, const RefineOptions& options, int first, int last,
              const char* caller);
  LevelPasses(const LevelPasses&) = delete;
  LevelPasses& operator=(const LevelPasses&) = delete;

  std::span<const LevelPass> all() const { return passes_; }
  // The passes of one step (first <= step < last), the split's first.
  std::span<const LevelPass> of_step(int step) const;
  // Steps the hierarchy has (runs' levels).
  int step_count() const { return step_count_; }

private:
  const VertexParameters* parameters_on(size_t level);

  const Hierarchy& h_;
  const RefineOptions& options_;
  int first_ = 0, step_count_ = 0;
  bool hierarchy_parameters_ = false;  // the hierarchy holds these options' parameters
  std::vector<LevelPass> passes_;
  std::vector<size_t> step_begin_;  // index of each step's first pass, and the end
  std::vector<std::unique_ptr<ChildOrigins>> identity_;  // per step with smoothing passes
  // Per-vertex parameters carried here when the hierarchy does not hold them for these options.
  std::vector<std::unique_ptr<VertexParameters>> carried_;
};

// Per-vertex parameters on every level refine_topology builds that a pass reads (levels the
// steps' passes read: each parent, and a new level with smoothing passes); the others empty.
// Empty when there are none, or when their counts do not match the base (the step
// functions then refuse them with check_vertex_parameters' message).
std::vector<VertexParameters> carried_parameters(const std::vector<const Scheme*>& per_level, const Hierarchy& h,
                                                 const VertexParameters& base);

}  // namespace subdiv
