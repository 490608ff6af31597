#pragma once
// Applying one compiled rule to one parent element: gathers the points of each role in
// canonical order and adds them, with their weights, to a stencil row.
#include "framework/features/feature_context.h"
#include "framework/rules/row_builder.h"
#include "framework/rules/weight_tables.h"

namespace subdiv {

// The child vertices of one element kind, and where each element's first child is.
struct ChildGroup {
  std::vector<Index> children;        // child vertex indices, in child order
  std::vector<Index> row_of_element;  // element -> row in this group (index into children), or kNone
};

// What the rules of one step can see: the parent level, its features, and the new points
// of the step (for terms with "new").
struct RuleInputs {
  const Level& parent;
  const FeatureContexts& features;
  // The step's children by element kind (step_rows.h: group_children): the new point of
  // element e of kind k is row (*groups)[k].row_of_element[e] of that kind. A term adds it
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
