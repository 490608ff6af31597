#include "framework/refine/child_tags.h"

#include "framework/features/sharpness.h"

namespace subdiv {

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
    // Boundary edges are sharp by topology at every level; their tags are not propagated.
    if (parent.edge_sharpness[e] <= 0.f || parent.edge_on_boundary(e)) continue;
    for (int end = 0; end < 2; ++end) {
      const Index v = parent.edge_vertices[2 * e + end];
      // Every child edge joining v to e's new point: one, or both halves of an edge from a
      // vertex to itself.
      for (Index half : child.ring_edges(v))
        if (child.other_end(half, v) == V + e) child.edge_sharpness[half] = child_edge_sharpness(parent, e, v, method);
    }
  }
}

}  // namespace subdiv
