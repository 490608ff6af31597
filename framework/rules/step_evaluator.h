#pragma once
// One refinement step applied to per-vertex values without a stencil table: each child's
// row is applied as soon as it is known, as OpenSubdiv's PrimvarRefiner does. Smooth
// interior elements go through the step's compiled kernels (smooth_kernels.h), other rows
// come from learnt plans (row_plans.h) or the rule interpreter (step_rows.h), so nothing of
// the size of a table is built or stored.
//
// New points a rule uses (Catmull-Clark's vertex and edge rules read the new face points)
// are read back from the output, computed first in the rules' dependency order, instead of
// being expanded into parent vertices: fewer terms, and neighbourhoods that never list the
// faces' corners. The values are those of build_step_stencils(step).apply(src, channels)
// up to round-off (kernels and plans sum the same terms as the interpreter; the kernels
// look a uniform weight up once per role). Any thread count gives the same bits.
#include <memory>
#include <span>

#include "framework/rules/row_paths.h"
#include "framework/rules/step_rows.h"

namespace subdiv {

// One step made ready once and applied to any number of value sets (repeated evaluation:
// engine/evaluator.h): its children grouped by element kind, its row plans and its
// compiled kernels are built by the constructor, so apply() only computes points. Keeps a
// reference to `step`, which must outlive it. Plans learnt by one apply() serve the next;
// the values do not depend on them. With `repeated`, the flat kernels also read their
// neighbourhoods off the topology once (FlatKernels::resolve_neighbourhoods): more memory,
// faster applications, the same bits.
class StepEvaluator {
public:
  explicit StepEvaluator(const StepContext& step, bool repeated = false);
  ~StepEvaluator();
  StepEvaluator(const StepEvaluator&) = delete;
  StepEvaluator& operator=(const StepEvaluator&) = delete;

  Index child_count() const;
  // dst (child count x channels) from src (parent vertex count x channels), child-major.
  // With `paths`, adds the children computed by each path. Not to be called concurrently
  // on one evaluator (its rows run in parallel inside).
  void apply(std::span<const double> src, std::span<double> dst, int channels, RowPaths* paths = nullptr);

private:
  struct Prepared;
  const StepContext& step_;
  std::unique_ptr<Prepared> prepared_;
};

// The same for one application: StepEvaluator(step).apply(src, dst, channels, paths).
void apply_step_rows(const StepContext& step, std::span<const double> src, std::span<double> dst, int channels,
                     RowPaths* paths = nullptr);

}  // namespace subdiv
