#pragma once
// The rows of one refinement step, child vertex by child vertex: every child as a weighted
// sum of parent vertices (or, in the step evaluator, of parent vertices and the step's own
// new points, RuleInputs::new_point_base), from the compiled rules, the parent's
// neighbourhoods and its features. The stencil builder (stencil_builder.h) stores them as a
// table; the step evaluator (step_evaluator.h) applies each row as soon as it is built.
// Child vertices are found through their origins (parent vertex, edge, face or corner), so
// any splitter that records origins works, and smoothing passes are steps whose origins
// are the vertices themselves.
#include <string>
#include <vector>

#include "framework/refine/child_origins.h"
#include "framework/rules/code_rules.h"
#include "framework/rules/element_rules.h"
#include "framework/rules/feature_context.h"
#include "framework/rules/weight_tables.h"

namespace subdiv {

class RowPlanStore;

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
};

// The child vertices of one element kind, and where each element's first child is.
struct ChildGroup {
  std::vector<Index> children;        // child vertex indices, in child order
  std::vector<Index> row_of_element;  // element -> row in this group (index into children), or kNone
};

// One group per element kind (indexed by Element).
std::vector<ChildGroup> group_children(const StepContext& s);

// Element kinds with children, in an order where new points a rule uses come before it.
std::vector<Element> build_order(const StepContext& s, const std::vector<ChildGroup>& groups);

// Fills child's row (`row` must be clear). New points the rules use come from `in`.
void fill_row(RowBuilder& row, const StepContext& s, const RuleInputs& in, Index child);

// Rows must be affine and finite.
bool row_sum_ok(double sum);
[[noreturn]] void report_bad_row(const StepContext& s, Index child, double sum);

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
