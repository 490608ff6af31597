#pragma once
// Applying one compiled rule to one parent element: gathers the points of each role in
// canonical order and adds them, with their weights, to a stencil row.
#include "framework/features/feature_context.h"
#include "framework/rules/row_builder.h"
#include "framework/rules/weight_tables.h"

namespace subdiv {

// The child vertices of one element kind, in child order ("rows"), and where each element's
// first child is. The primal splits make one child per element, numbered in element order
// from some first child: such a group is a "run" and stores nothing.
class ChildGroup {
public:
  ChildGroup() = default;  // no children
  // Children first, first + 1, ... of elements 0, 1, ..., count - 1 (count > 0).
  static ChildGroup run(Index first, Index count) {
    ChildGroup g;
    g.first_ = first, g.count_ = count;
    return g;
  }
  // An empty group over `element_count` elements, filled by add() in child order.
  explicit ChildGroup(Index element_count, Index expected_children = 0) : row_of_element_(size_t(element_count), kNone) {
    children_.reserve(size_t(expected_children));
  }
  void add(Index element, Index child) {
    if (row_of_element_[element] == kNone) row_of_element_[element] = Index(children_.size());
    children_.push_back(child);
  }

  Index size() const { return first_ != kNone ? count_ : Index(children_.size()); }
  bool empty() const { return size() == 0; }
  // The child vertex of row r.
  Index child(Index r) const { return first_ != kNone ? first_ + r : children_[r]; }
  // Element e's first row, or kNone when it has no child.
  Index row_of(Index e) const {
    if (first_ != kNone) return e < count_ ? e : kNone;
    return e < Index(row_of_element_.size()) ? row_of_element_[e] : kNone;
  }
  // Element e's (first) child vertex, or kNone.
  Index child_of(Index e) const {
    const Index r = row_of(e);
    return r == kNone ? kNone : child(r);
  }
  // The first child of a run (row r is element r's only child, first_of_run() + r), or kNone.
  Index first_of_run() const { return first_; }

private:
  Index first_ = kNone, count_ = 0;
  std::vector<Index> children_, row_of_element_;
};

// What the rules of one step can see: the parent level, its features, and the new points
// of the step (for terms with "new").
struct RuleInputs {
  const Level& parent;
  const FeatureContexts& features;
  // The step's children by element kind (step_rows.h: group_children): the new point of
  // element e of kind k is row (*groups)[k].row_of(e) of that kind. A term adds it
  // expanded into parent vertices, from the rows stored in blocks[k] (the stencil builder),
  // or, with new_point_base >= 0, as a source of its own, new_point_base + child (the step
  // evaluator, which computes new points before the rules that read them).
  const std::vector<ChildGroup>* groups = nullptr;
  const ChunkedRows* blocks[kElementCount] = {};
  Index new_point_base = -1;
};

void apply_vertex_rule(RowBuilder& row, const RuleInputs& in, Index v, const CompiledRule& rule,
                       const std::array<std::uint16_t, 2>& crease, double scale);
void apply_edge_rule(RowBuilder& row, const RuleInputs& in, Index e, const CompiledRule& rule, double scale);
void apply_face_rule(RowBuilder& row, const RuleInputs& in, Index f, const CompiledRule& rule);
// Corner `corner` (0-based within face f).
void apply_corner_rule(RowBuilder& row, const RuleInputs& in, Index f, int corner, const CompiledRule& rule, double scale);
// A curve rule applied along the segment a -> b (offsets 0 and 1), walking past the ends
// along the feature curve (edge e joins a and b).
void apply_segment_curve_rule(RowBuilder& row, const RuleInputs& in, Index e, Index a, Index b,
                              const CompiledRule& rule, double scale);

}  // namespace subdiv
