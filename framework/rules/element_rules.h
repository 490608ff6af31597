#pragma once
// Applying one compiled rule to one parent element: gathers the points of each role in
// canonical order and adds them, with their weights, to a stencil row.
#include "framework/rules/feature_context.h"
#include "framework/rules/row_builder.h"
#include "framework/rules/weight_tables.h"

namespace subdiv {

// What the rules of one step can see: the parent level, its features, and the new points
// of the step (for terms with "new").
struct RuleInputs {
  const Level& parent;
  const FeatureContexts& features;
  // New points of element kind k exist where block_row_of_element[k] is set: the new point
  // of element e is row r = (*block_row_of_element[k])[e] of that kind's rows, stored in
  // blocks[k], whose rows a term adds expanded into parent vertices.
  const ChunkedRows* blocks[kElementCount] = {};
  const std::vector<Index>* block_row_of_element[kElementCount] = {};
  // Or, where new points are sources themselves (the step evaluator, which computes them
  // first): a term adds child vertex (*children[k])[r] as source new_point_base + child.
  Index new_point_base = -1;
  const std::vector<Index>* children[kElementCount] = {};
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
