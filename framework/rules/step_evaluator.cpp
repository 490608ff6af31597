#include "framework/rules/step_evaluator.h"

#include <algorithm>
#include <atomic>
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/rules/row_plans.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// Rows per parallel task: large enough to amortise a planner's setup, small enough to
// balance.
constexpr Index kGrain = 4096;

// out = sum_i weights[i] * src[source_of(i)], summed from zero in row order as
// StencilTable::apply does, so the bits are the same.
template <class SourceOf>
void weighted_sum(size_t count, SourceOf source_of, const double* weights, const double* src, double* out,
                  int channels) {
  if (channels == 3) {
    double sum[3] = {};
    for (size_t i = 0; i < count; ++i) {
      const double w = weights[i];
      const double* p = src + 3 * size_t(source_of(i));
      sum[0] += w * p[0], sum[1] += w * p[1], sum[2] += w * p[2];
    }
    std::copy(sum, sum + 3, out);
    return;
  }
  std::fill(out, out + channels, 0.0);
  for (size_t i = 0; i < count; ++i) {
    const double w = weights[i];
    const double* p = src + size_t(channels) * size_t(source_of(i));
    for (int c = 0; c < channels; ++c) out[c] += w * p[c];
  }
}

void apply_row(const RowBuilder& row, const double* src, double* out, int channels) {
  const auto& indices = row.indices();
  weighted_sum(indices.size(), [&](size_t i) { return indices[i]; }, row.weights().data(), src, out, channels);
}

double row_sum(const RowBuilder& row) {
  double sum = 0.0;
  for (double w : row.weights()) sum += w;
  return sum;
}

// New points that a rule reads, rebuilt where they are read: the row a stored table would
// hold, added entry by entry as RowBuilder::add_row adds a stored row.
class RowsOnDemand final : public NewPointRows {
public:
  RowsOnDemand(const StepContext& s, const RuleInputs& in, const std::vector<ChildGroup>& groups)
      : s_(s), in_(in), groups_(groups) {}
  void add(RowBuilder& row, Element kind, Index r, double scale) const override {
    RowBuilder point;
    fill_row(point, s_, in_, groups_[int(kind)].children[r]);
    for (size_t i = 0; i < point.indices().size(); ++i) row.add(point.indices()[i], scale * point.weights()[i]);
  }

private:
  const StepContext& s_;
  const RuleInputs& in_;
  const std::vector<ChildGroup>& groups_;
};

// Group order[at]'s rows are stored when a later group's rules read its new points and
// take no plans (every row of theirs would rebuild them).
bool store_rows(const StepContext& s, const RowPlanStore& plans, const std::vector<Element>& order, size_t at) {
  for (size_t later = at + 1; later < order.size(); ++later)
    if (uses_new_points(s.tables, order[later], order[at]) && !(s.use_row_plans && plans.enabled[int(order[later])]))
      return true;
  return false;
}

void apply_stored_rows(const ChunkedRows& rows, const ChildGroup& group, const double* src, double* dst, int channels) {
  tbb::parallel_for(tbb::blocked_range<Index>(0, Index(group.children.size()), kGrain), [&](const auto& range) {
    for (Index r = range.begin(); r < range.end(); ++r) {
      const RowBlock& b = rows.chunk_of(r);
      const Index from = b.offsets[rows.local(r)], to = b.offsets[rows.local(r) + 1];
      weighted_sum(size_t(to - from), [&](size_t i) { return b.indices[from + Index(i)]; }, b.weights.data() + from,
                   src, dst + size_t(group.children[r]) * channels, channels);
    }
  });
}

// Each row of the group applied as soon as it is known. Rows are checked as build_rows
// checks them, and the first bad row in group order is reported, whatever the threads.
void apply_group_rows(const StepContext& s, const RuleInputs& in, const ChildGroup& group, RowPlanStore& plans,
                      const double* src, double* dst, int channels) {
  const Index count = Index(group.children.size());
  std::atomic<Index> first_bad{count};
  auto mark_bad = [&](Index r) {
    Index seen = first_bad.load();
    while (r < seen && !first_bad.compare_exchange_weak(seen, r)) {}
  };
  tbb::parallel_for(tbb::blocked_range<Index>(0, count, kGrain), [&](const auto& range) {
    RowBuilder row;
    RowPlanner planner(plans);
    for (Index r = range.begin(); r < range.end(); ++r) {
      const Index child = group.children[r];
      double* out = dst + size_t(child) * channels;
      RowPlanner::Outcome outcome = RowPlanner::Outcome::Generic;
      if (s.use_row_plans)
        if (const RowPlan* plan = planner.find(child, outcome)) {
          const std::vector<Index>& around = planner.around();
          weighted_sum(plan->positions.size(), [&](size_t i) { return around[plan->positions[i]]; },
                       plan->weights.data(), src, out, channels);
          if (!plan->sum_ok) mark_bad(r);
          continue;
        }
      row.clear();
      fill_row(row, s, in, child);
      if (outcome == RowPlanner::Outcome::Learn) planner.learn(row, plans);
      if (!row_sum_ok(row_sum(row))) mark_bad(r);
      apply_row(row, src, out, channels);
    }
  });
  if (first_bad == count) return;
  RowBuilder row;
  fill_row(row, s, in, group.children[first_bad]);
  report_bad_row(s, group.children[first_bad], row_sum(row));
}

}  // namespace

void apply_step_rows(const StepContext& s, std::span<const double> src, std::span<double> dst, int channels) {
  const Index child_count = Index(s.origins.kind.size());
  if (channels < 1 || src.size() < size_t(s.parent.vertex_count) * channels || dst.size() < size_t(child_count) * channels)
    throw Error(fmt::format("apply_step_rows: buffers of {} and {} values do not fit {} parent and {} child vertices "
                            "of {} channels",
                            src.size(), dst.size(), s.parent.vertex_count, child_count, channels));
  const std::vector<ChildGroup> groups = group_children(s);
  RowPlanStore plans(s.parent, s.origins, s.tables, s.features, s.code != nullptr);
  RuleInputs in{s.parent, s.features};
  const RowsOnDemand on_demand(s, in, groups);
  in.on_demand = &on_demand;
  for (int e = 0; e < kElementCount; ++e)
    if (!groups[e].children.empty()) in.block_row_of_element[e] = &groups[e].row_of_element;
  std::vector<ChunkedRows> stored(kElementCount);
  const std::vector<Element> order = build_order(s, groups);
  for (size_t at = 0; at < order.size(); ++at) {
    const int e = int(order[at]);
    if (!store_rows(s, plans, order, at)) {
      apply_group_rows(s, in, groups[e], plans, src.data(), dst.data(), channels);
      continue;
    }
    stored[e] = build_rows(s, in, groups[e], plans);
    in.blocks[e] = &stored[e];
    apply_stored_rows(stored[e], groups[e], src.data(), dst.data(), channels);
  }
}

}  // namespace subdiv
