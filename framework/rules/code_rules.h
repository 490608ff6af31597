#pragma once
// Geometry rules written in C++ (plugin schemes), next to the rules of the scheme language.
//
// Linear rules (CodeRules) write stencil rows: the engine calls them once per new point and
// they add (parent vertex, weight) pairs, so a linear plugin scheme still produces stencil
// tables and gets composition, analysis and the fast apply like any JSON scheme. Non-linear
// rules (NonlinearRule) cannot be stencils: the engine refines the topology as usual and
// then hands the rule the parent values to compute the child values directly.
#include <functional>
#include <span>

#include "framework/refine/child_origins.h"
#include "framework/features/feature_context.h"

namespace subdiv {

class RowBuilder;  // rules/row_builder.h, internal

// What a code rule sees: the parent level, its feature contexts (boundaries, creases,
// corners after the --boundary options) and the level being refined (0 for the input).
struct CodeRuleInput {
  const Level& parent;
  const FeatureContexts& features;
  int level = 0;
};

// Where a code rule writes its row: add(v, w) adds w times parent vertex v. The engine
// scales the row when it blends rules (semi-sharp creases) and checks that the weights of
// every finished row are finite and sum to 1.
class RowWriter {
public:
  RowWriter(RowBuilder& row, double scale) : row_(row), scale_(scale) {}
  void add(Index parent_vertex, double weight);  // out of line: RowBuilder stays internal

private:
  RowBuilder& row_;
  double scale_;
};

// Each function gives the new point of one parent element; leave one empty when the
// scheme's splitter makes no new points of that kind. Unless handles_features is set, the
// engine calls them for smooth elements only (vertex contexts smooth and dart, smooth
// edges, the smooth part of semi-sharp ones, corners beside no sharp edge) and refines
// boundaries, creases and corners with the scheme's curve scheme, as it does for JSON
// schemes. With handles_features the functions are called for every context.
struct CodeRules {
  std::function<void(const CodeRuleInput&, Index vertex, Context context, RowWriter& row)> vertex;
  // `local`: which new point of the edge (0 for binary splits).
  std::function<void(const CodeRuleInput&, Index edge, int local, Context context, RowWriter& row)> edge;
  std::function<void(const CodeRuleInput&, Index face, RowWriter& row)> face;
  std::function<void(const CodeRuleInput&, Index face, int corner, Context context, RowWriter& row)> corner;
  bool handles_features = false;
};

// A non-linear step: the topology is already refined (child level and origins as the
// splitter made them); fill every child value. Values are `channels` numbers per vertex
// (3 for positions). Children are in the child level's vertex order.
struct NonlinearStepInput {
  const Level& parent;
  const Level& child;
  const ChildOrigins& origins;
  const FeatureContexts& features;
  bool features_refined = true;
  int level = 0;
};
using NonlinearRule = std::function<void(const NonlinearStepInput&, std::span<const double> parent_values,
                                         std::span<double> child_values, int channels)>;

}  // namespace subdiv
