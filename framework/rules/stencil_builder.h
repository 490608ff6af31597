#pragma once
// Builds the stencil table of one refinement step: every child vertex as a weighted sum of
// parent vertices, from the compiled rules, the parent's neighbourhoods and its features.
#include "framework/refine/splitter.h"
#include "framework/rules/feature_context.h"
#include "framework/rules/weight_tables.h"
#include "framework/stencil/stencil_table.h"

namespace subdiv {

// Where each element kind's new points start in the child numbering; kNone: none made.
struct ChildLayout {
  Index first[kElementCount] = {kNone, kNone, kNone};
};
ChildLayout primal_layout(const Level& parent, SplitKind split);

// `source` names the scheme file for error messages.
StencilTable build_step_stencils(const Level& parent, const ChildLayout& layout,
                                 const WeightTables& tables, const FeatureContexts& features,
                                 const std::string& source);

}  // namespace subdiv
