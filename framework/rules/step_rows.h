#pragma once
// The rows of one refinement step, child vertex by child vertex: every child as a weighted
// sum of parent vertices (or, in the step evaluator, of parent vertices and the step's own
// new points, RuleInputs::new_point_base), from the compiled rules, the parent's
// neighbourhoods and its features. The stencil builder (stencil_builder.h) stores them as a
// table; the step evaluator (step_evaluator.h) applies each row as soon as it is built.
// Child vertices are found through their origins (parent vertex, edge, face or corner), so
// any splitter that records origins works, and smoothing passes are steps whose origins
// are the vertices themselves.
#include <atomic>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "framework/refine/child_origins.h"
#include "framework/rules/code_rules.h"
#include "framework/rules/element_rules.h"
#include "framework/features/feature_context.h"
#include "framework/rules/weight_tables.h"

namespace subdiv {

class RowPlanStore;
class StageTimes;

// Vertex rules whose weights differ from vertex to vertex (a scheme's per-vertex
// parameters): vertex v's rules come from tables[group[v]], one table per distinct value.
struct PerVertexTables {
  std::vector<WeightTables> tables;
  std::vector<std::uint32_t> group;  // per parent vertex
};

struct StepContext {
  const Level& parent;
  const ChildOrigins& origins;
  const WeightTables& tables;
  const FeatureContexts& features;
  bool features_refined = true;  // false: crease vertices stay (odd sqrt3 steps)
  std::string source;            // the scheme file, for messages
  const CodeRules* code = nullptr;  // rules written in C++ (plugins); they take precedence
  int level = 0;                    // the level being refined, for code rules
  // Replay learnt rows for smooth interior elements (row_plans.h); the rows are the same
  // either way, false is for tests and measurements.
  bool use_row_plans = true;
  // Compute smooth interior elements with the compiled kernels (smooth_kernels.h) in the
  // step evaluator; false is for tests and measurements.
  bool use_kernels = true;
  // The step writes output that no later step reads and that is larger than the caches (a
  // refinement's last level): the flat kernels write the points of the kind computed last
  // (which no rule of the step reads back) with streaming stores (point_accumulator.h).
  // The same values.
  bool stream_output = false;
  // Where to add the time of each kind's new points (stage_times.h), or null.
  StageTimes* stage_times = nullptr;
  // Set when vertex rules differ per vertex; `tables` then serves the other elements.
  const PerVertexTables* per_vertex = nullptr;
  // Set when `features` are computed on first use (the step evaluator on a level without
  // sharpness tags: its kernels read the topology alone, so on a closed manifold mesh no
  // row ever needs the contexts). Rows built by the rules call need_features() first.
  const std::function<void()>* classify = nullptr;
  void need_features() const {
    if (classify) (*classify)();
  }

  const WeightTables& vertex_tables(Index v) const { return per_vertex ? per_vertex->tables[per_vertex->group[v]] : tables; }
};

// One ChildGroup (element_rules.h) per element kind (indexed by Element).
std::vector<ChildGroup> group_children(const StepContext& s);

// Element kinds with children, in an order where new points a rule uses come before it.
std::vector<Element> build_order(const StepContext& s, const std::vector<ChildGroup>& groups);

// Fills child's row (`row` must be clear). New points the rules use come from `in`.
void fill_row(RowBuilder& row, const StepContext& s, const RuleInputs& in, Index child);

// Rows must be affine and finite.
double weight_sum(std::span<const double> weights);
constexpr double kRowSumTolerance = 1e-9;
inline bool row_sum_ok(double sum) { return sum - 1.0 <= kRowSumTolerance && 1.0 - sum <= kRowSumTolerance; }

// The first row of a group, in group order, that failed row_sum_ok, whatever the threads
// that built the rows; report() rebuilds that row and throws the message naming it.
class FirstBadRow {
public:
  explicit FirstBadRow(Index count) : count_(count), first_(count) {}
  void mark(Index r) {
    Index seen = first_.load();
    while (r < seen && !first_.compare_exchange_weak(seen, r)) {}
  }
  void report_if_any(const StepContext& s, const RuleInputs& in, const ChildGroup& group) const;

private:
  Index count_;
  std::atomic<Index> first_;
};

// Rows per chunk of parallel work: large enough that a chunk's buffers are bulk memory
// (util/bulk_memory.h), returned to the system as soon as they are freed, rather than
// heap blocks that stay; small enough to share out among threads on meshes of some 100k
// elements.
constexpr Index kRowChunk = Index(1) << 16;

// The rows of one group, built in parallel chunks and stored; each row depends only on
// its element, so the result does not depend on the thread count. Smooth interior rows
// replay a plan (row_plans.h) when one fits, which gives the same row. Checks every row.
ChunkedRows build_rows(const StepContext& s, const RuleInputs& in, const ChildGroup& group, RowPlanStore& plans);

}  // namespace subdiv
