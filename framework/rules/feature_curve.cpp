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

// Crease edges from v along `edge` to the first corner, or 0 when the crease ends otherwise,
// closes on itself, or runs past max_distance first.
int steps_to_corner(const Level& level, const FeatureContexts& features, Index v, Index edge, int max_distance) {
  Index current = v;
  for (int step = 1; step <= max_distance && edge != kNone; ++step) {
    current = level.other_end(edge, current);
    if (features.vertices[current].parent == Context::Corner) return step;
    if (current == v) return 0;
    edge = continue_curve(level, features, current, edge);
  }
  return 0;
}

}  // namespace

CornerDistance distance_to_corner(const Level& level, const FeatureContexts& features, Index v,
                                  const std::array<Index, 2>& edges, int max_distance) {
  const int a = steps_to_corner(level, features, v, edges[0], max_distance);
  const int b = steps_to_corner(level, features, v, edges[1], max_distance);
  const int length = a != 0 && b != 0 ? a + b : 0;
  if (a == 0 && b == 0) return {};
  if (b == 0 || (a != 0 && a <= b)) return {a, 0, length};
  return {b, 1, length};
}

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
