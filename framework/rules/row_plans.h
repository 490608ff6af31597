#pragma once
// Row plans: the stencil row of a smooth interior element, learnt once per neighbourhood
// shape and replayed for every element of that shape.
//
// Away from features and boundaries a rule's row depends only on the shape of the
// element's neighbourhood: the valence, the sizes of the faces around it in ring order,
// the valences at an edge's ends. Listing the neighbourhood's vertices in a canonical
// order (the element's "enumeration"), the row is a fixed list of (position, weight)
// pairs. The first element of each shape is built by the generic rule interpreter and its
// row is recorded against its enumeration; later elements of that shape copy the weights
// and look the indices up, with no formula tables and no merging of repeated sources.
// Rows come out identical to the generic ones, entries in the same order.
//
// A plan is used only where that argument holds: smooth, interior, featureless elements
// whose rules read roles inside the enumeration (and new points whose rows do too), no
// rules written in C++, and neighbourhoods whose enumerated vertices are distinct (on a
// tiny closed mesh a ring can meet itself; such elements take the generic path).
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "framework/refine/child_origins.h"
#include "framework/features/feature_context.h"
#include "framework/rules/row_builder.h"
#include "framework/rules/step_rows.h"
#include "framework/rules/weight_tables.h"

namespace subdiv {

struct RowPlan {
  bool usable = false;  // false: the rule reads outside the enumeration; use the generic path
  std::vector<std::uint16_t> positions;  // into the element's enumeration
  std::vector<double> weights;
  bool sum_ok = true;  // the learnt row is affine and finite (step_rows.h: row_sum_ok)
};

// Which kinds of element can use plans in one step, and the plans learnt so far (shared by
// the threads building the step's rows).
//
// With `new_point_sources` (the step evaluator, RuleInputs::new_point_base), new points are
// sources of their own, numbered parent.vertex_count + child: the enumeration then ends
// with the new face and edge points the rules read, and where the rules read nothing but the
// element's own vertices, ring and new points ("light" kinds) it skips the faces' corners.
// Such rows are the same values as the expanded ones, summed differently.
class RowPlanStore {
public:
  RowPlanStore(const Level& parent, const ChildOrigins& origins, const WeightTables& tables,
               const FeatureContexts& features, bool code_rules,
               const std::vector<ChildGroup>* new_point_sources = nullptr);

  const Level& parent;
  const ChildOrigins& origins;
  const FeatureContexts& features;
  const std::vector<ChildGroup>* sources = nullptr;  // new_point_sources
  bool enabled[kElementCount] = {};
  bool light[kElementCount] = {};
  // With sources: whether the smooth rule of an element kind reads new face / edge points.
  bool reads_face_points[kElementCount] = {}, reads_edge_points[kElementCount] = {};

  // The source number of element e's new point (kind k), or kNone.
  Index new_point(Element k, Index e) const {
    const Index c = (*sources)[int(k)].child_of(e);
    return c == kNone ? kNone : parent.vertex_count + c;
  }

  const RowPlan* find(const std::vector<std::int32_t>& key) const;
  const RowPlan* add(const std::vector<std::int32_t>& key, RowPlan plan);

private:
  mutable std::mutex mutex_;
  std::map<std::vector<std::int32_t>, std::unique_ptr<RowPlan>> plans_;
};

// One thread's use of the store: remembers the plans it has used (a mesh has few shapes)
// and the enumeration of the element being built.
class RowPlanner {
public:
  explicit RowPlanner(const RowPlanStore& store) : store_(store) {}

  enum class Outcome { Appended, Learn, Generic };
  // The plan for child's row (Appended: the row is plan->weights over
  // around()[plan->positions]); or null, and the row must be built generically, then passed
  // to learn() (Learn) or not (Generic).
  const RowPlan* find(Index child, Outcome& outcome);
  // Child's neighbourhood, as enumerated by the last find().
  const std::vector<Index>& around() const { return around_; }
  // Appends child's row to `out` from a plan (Appended), or answers as find() does.
  Outcome try_append(Index child, RowBlock& out);
  // Records the generic row of the child try_append last answered Learn for.
  void learn(const RowBuilder& row, RowPlanStore& store);

private:
  bool describe(Index child);  // fills key_ and around_; false: not eligible
  void describe_vertex(Index v);
  void describe_edge(Index e, int local);
  bool distinct() const;

  const RowPlanStore& store_;
  std::vector<std::int32_t> key_;
  std::vector<Index> around_;
  // Neighbouring elements mostly have the same shape: the last key and its plan are
  // checked before the hash map.
  std::vector<std::int32_t> last_key_;
  const RowPlan* last_plan_ = nullptr;
  struct KeyHash {
    size_t operator()(const std::vector<std::int32_t>& key) const {
      size_t h = key.size();
      for (std::int32_t x : key) h = h * 1000003u ^ std::uint32_t(x);
      return h;
    }
  };
  std::unordered_map<std::vector<std::int32_t>, const RowPlan*, KeyHash> local_;
};

}  // namespace subdiv
