#include "framework/interpolation/interpolatory_limit.h"

namespace subdiv {

StencilTable InterpolatoryLimit::stencils_at(const Level& level, int) const {
  StencilTable t;
  t.source_count = level.vertex_count;
  t.offsets.reserve(size_t(level.vertex_count) + 1);
  for (Index v = 0; v < level.vertex_count; ++v) {
    t.indices.push_back(v);
    t.weights.push_back(1.0);
    t.offsets.push_back(Index(t.indices.size()));
  }
  return t;
}

}  // namespace subdiv
