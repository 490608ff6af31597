#include "framework/rules/feature_curve.h"

namespace subdiv {
namespace {

// The curve edge leaving u other than `arrived_by`, or kNone where the curve ends
// (u is a corner, a dart end or an isolated feature point).
Index continue_curve(const Level& level, const FeatureContexts& features, Index u, Index arrived_by) {
  const VertexContext& vc = features.vertices[u];
  if (vc.parent != Context::Crease) return kNone;
  const auto ring = level.ring_edges(u);
  const Index a = ring[vc.parent_crease[0]], b = ring[vc.parent_crease[1]];
  return a == arrived_by ? b : a;
}

}  // namespace

void add_curve_point(RowBuilder& row, const Level& level, const FeatureContexts& features,
                     Index v, Index edge, int steps, double weight) {
  Index previous = v, current = v;
  for (int step = 0; step < steps; ++step) {
    if (edge == kNone) {
      // Linear extrapolation from the last two points reached.
      const double d = steps - step;
      row.add(current, weight * (1.0 + d));
      row.add(previous, -weight * d);
      return;
    }
    previous = current;
    current = level.other_end(edge, current);
    if (step + 1 < steps) edge = continue_curve(level, features, current, edge);
  }
  row.add(current, weight);
}

}  // namespace subdiv
