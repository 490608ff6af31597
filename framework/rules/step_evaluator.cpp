#include "framework/rules/step_evaluator.h"

#include <algorithm>
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/rules/row_plans.h"
#include "framework/rules/smooth_kernels.h"
#include "framework/rules/stage_times.h"
#include "framework/util/error.h"
#include "framework/util/step_progress.h"

namespace subdiv {
namespace {

// Rows per parallel task: large enough to amortise a planner's setup, small enough to
// balance.
constexpr Index kGrain = 4096;

// out = sum_i weights[i] * value of source_of(i), summed from zero in row order.
template <class SourceOf>
void weighted_sum(size_t count, SourceOf source_of, const double* weights, const StepSources& in, double* out) {
  if (in.channels == 3) {
    double sum[3] = {};
    for (size_t i = 0; i < count; ++i) {
      const double w = weights[i];
      const double* p = in.at(source_of(i));
      sum[0] += w * p[0], sum[1] += w * p[1], sum[2] += w * p[2];
    }
    std::copy(sum, sum + 3, out);
    return;
  }
  std::fill(out, out + in.channels, 0.0);
  for (size_t i = 0; i < count; ++i) {
    const double w = weights[i];
    const double* p = in.at(source_of(i));
    for (int c = 0; c < in.channels; ++c) out[c] += w * p[c];
  }
}

// Each row of the group applied as soon as it is known: smooth interior elements through
// the kernels (smooth_kernels.h), others from a learnt plan or the rule interpreter. Rows
// are checked as build_rows checks them, and the first bad row in group order is reported,
// whatever the threads.
void apply_group_rows(const StepContext& s, const RuleInputs& in, Element kind, const ChildGroup& group,
                      const SmoothKernels& kernels, RowPlanStore& plans, const StepSources& sources, double* dst,
                      RowPaths* paths) {
  const Index count = group.size();
  const int channels = sources.channels;
  const bool use_kernels = s.use_kernels && kernels.covers(kind);
  FirstBadRow first_bad(count);
  tbb::parallel_for(tbb::blocked_range<Index>(0, count, kGrain), [&](const auto& range) {
    RowBuilder row;
    RowPlanner planner(plans);
    RowPaths::Counts counted;
    // The kernels first; the rows they leave (and all rows without them) by plan or rule.
    std::vector<Index> left;
    if (use_kernels) {
      Index flat = 0;
      counted.kernel = kernels.run(kind, group, range.begin(), range.end(), sources, dst, left, first_bad, flat);
      counted.flat = flat;
    } else {
      for (Index r = range.begin(); r < range.end(); ++r) left.push_back(r);
    }
    if (!left.empty()) s.need_features();
    for (Index r : left) {
      const Index child = group.child(r);
      double* out = dst + size_t(child) * channels;
      RowPlanner::Outcome outcome = RowPlanner::Outcome::Generic;
      if (s.use_row_plans)
        if (const RowPlan* plan = planner.find(child, outcome)) {
          const std::vector<Index>& around = planner.around();
          weighted_sum(plan->positions.size(), [&](size_t i) { return around[plan->positions[i]]; },
                       plan->weights.data(), sources, out);
          if (!plan->sum_ok) first_bad.mark(r);
          ++counted.plan;
          continue;
        }
      row.clear();
      fill_row(row, s, in, child);
      if (outcome == RowPlanner::Outcome::Learn) planner.learn(row, plans);
      if (!row_sum_ok(weight_sum(row.weights()))) first_bad.mark(r);
      const auto& indices = row.indices();
      weighted_sum(indices.size(), [&](size_t i) { return indices[i]; }, row.weights().data(), sources, out);
      ++counted.generic;
    }
    if (paths) paths->add(counted);
  });
  first_bad.report_if_any(s, in, group);
}

}  // namespace

// What a step needs besides its values, made once: the children by element kind, the
// order the kinds are built in, the row plans and the compiled kernels (which keep
// references to the groups, so the whole is held in place on the heap).
// Hidden, as the kernels it holds (smooth_kernels.h).
struct [[gnu::visibility("hidden")]] StepEvaluator::Prepared {
  explicit Prepared(const StepContext& s)
      : groups(group_children(s)),
        order(build_order(s, groups)),
        plans(s.parent, s.origins, s.tables, s.features, s.code != nullptr, &groups),
        kernels(s, groups) {}
  const std::vector<ChildGroup> groups;
  const std::vector<Element> order;
  RowPlanStore plans;
  SmoothKernels kernels;
};

StepEvaluator::StepEvaluator(const StepContext& step, bool repeated)
    : step_(step), prepared_(std::make_unique<Prepared>(step)) {
  if (repeated && step.use_kernels) prepared_->kernels.resolve_neighbourhoods();
}

StepEvaluator::~StepEvaluator() = default;

Index StepEvaluator::child_count() const { return Index(step_.origins.kind.size()); }

void StepEvaluator::apply(std::span<const double> src, std::span<double> dst, int channels, RowPaths* paths) {
  const StepContext& s = step_;
  if (channels < 1 || src.size() < size_t(s.parent.vertex_count) * channels || dst.size() < size_t(child_count()) * channels)
    throw Error(fmt::format("apply_step_rows: buffers of {} and {} values do not fit {} parent and {} child vertices "
                            "of {} channels",
                            src.size(), dst.size(), s.parent.vertex_count, child_count(), channels));
  Prepared& p = *prepared_;
  // New points are sources: the groups run in build order, so a rule reads new points that
  // are already in dst.
  RuleInputs in{s.parent, s.features};
  in.groups = &p.groups;
  in.new_point_base = s.parent.vertex_count;
  const StepSources sources{src.data(), dst.data(), s.parent.vertex_count, channels};
  double rows = 0, done = 0;
  for (Element e : p.order) rows += double(p.groups[int(e)].size());
  for (Element e : p.order) {
    const StageTimer timer(s.stage_times, s.stage_times ? fmt::format("L{} {} points", s.level + 1, element_name(e)) : std::string());
    apply_group_rows(s, in, e, p.groups[int(e)], p.kernels, p.plans, sources, dst.data(), paths);
    done += double(p.groups[int(e)].size());
    StepProgressScope::tell(rows > 0 ? done / rows : 1.0);  // a front-end's bar moves within the level
  }
}

void apply_step_rows(const StepContext& s, std::span<const double> src, std::span<double> dst, int channels,
                     RowPaths* paths) {
  StepEvaluator(s).apply(src, dst, channels, paths);
}

}  // namespace subdiv
