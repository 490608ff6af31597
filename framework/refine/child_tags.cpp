#include "framework/refine/child_tags.h"

#include <algorithm>

namespace subdiv {

float decremented_sharpness(float s) { return s >= kInfinitelySharp ? s : std::max(0.f, s - 1.f); }

namespace {

// OpenSubdiv's Chaikin rule (Sdc::Crease::SubdivideEdgeSharpnessAtVertex): the child
// half of edge e next to vertex v takes the 3:1 average of e's sharpness and the mean
// sharpness of v's other semi-sharp edges, minus one.
float chaikin_half(const Level& parent, Index e, Index v) {
  const float s = parent.edge_sharp(e);
  if (s <= 0.f || s >= kInfinitelySharp) return decremented_sharpness(s);
  float sum = 0.f;
  int count = 0;
  for (Index other : parent.ring_edges(v)) {
    if (other == e) continue;
    const float t = parent.edge_sharp(other);
    if (t > 0.f) sum += t, ++count;  // OSD averages over the other creased edges
  }
  if (count == 0) return decremented_sharpness(s);
  return std::max(0.f, (3.f * s + sum / float(count)) / 4.f - 1.f);
}

}  // namespace

float child_edge_sharpness(const Level& parent, Index e, Index v, CreaseMethod method) {
  return method == CreaseMethod::Chaikin ? chaikin_half(parent, e, v)
                                         : decremented_sharpness(parent.edge_sharp(e));
}

void propagate_tags(const Level& parent, SplitResult& result, CreaseMethod method) {
  Level& child = result.child;
  if (!parent.vertex_sharpness.empty()) {
    child.vertex_sharpness.assign(child.vertex_count, 0.f);
    for (Index v = 0; v < parent.vertex_count; ++v)
      child.vertex_sharpness[v] = decremented_sharpness(parent.vertex_sharpness[v]);
  }
  if (parent.edge_sharpness.empty()) return;
  child.edge_sharpness.assign(child.edge_count(), 0.f);
  const Index V = parent.vertex_count;
  for (Index e = 0; e < parent.edge_count(); ++e) {
    if (parent.edge_sharpness[e] <= 0.f) continue;
    for (int end = 0; end < 2; ++end) {
      const Index v = parent.edge_vertices[2 * e + end];
      const Index half = find_edge(child, v, V + e);
      child.edge_sharpness[half] = child_edge_sharpness(parent, e, v, method);
    }
  }
}

}  // namespace subdiv
