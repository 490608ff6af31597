#pragma once
// Builds the stencil table of one refinement step: every child vertex as a weighted sum of
// parent vertices, from the compiled rules, the parent's neighbourhoods and its features.
// Child vertices are found through their origins (parent vertex, edge, face or corner), so
// any splitter that records origins works, and smoothing passes are steps whose origins
// are the vertices themselves.
#include <string>

#include "framework/refine/child_origins.h"
#include "framework/rules/code_rules.h"
#include "framework/rules/feature_context.h"
#include "framework/rules/weight_tables.h"
#include "framework/stencil/stencil_table.h"

namespace subdiv {

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

StencilTable build_step_stencils(const StepContext& step);

// Origins of a smoothing pass: child vertex v is parent vertex v.
ChildOrigins identity_origins(const Level& level);

}  // namespace subdiv
