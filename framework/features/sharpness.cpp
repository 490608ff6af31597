#include "framework/features/sharpness.h"

#include <algorithm>

namespace subdiv {

float decremented_sharpness(float s) {
  if (s <= 0.f) return 0.f;
  if (s >= kInfinitelySharp) return kInfinitelySharp;
  return s > 1.f ? s - 1.f : 0.f;
}

namespace {

// Chaikin's decay (DeRose, Kass & Truong 1998) of one semi-sharp edge of sharpness s among
// `count` semi-sharp edges whose sharpness sums to `sum` (s included), with OpenSubdiv's
// float operations in its order.
float averaged_decay(float s, float sum, int count) {
  if (count > 1) {
    const float others = (sum - s) / float(count - 1);
    s = 0.75f * s + 0.25f * others;
  }
  s -= 1.0f;
  return s > 0.f ? s : 0.f;
}

float effective_sharpness(const Level& level, Index e) {
  return level.edge_on_boundary(e) ? kInfinitelySharp : level.edge_sharp(e);
}

}  // namespace

void subdivide_sharpness_around_vertex(std::span<const float> parent, std::span<float> child, CreaseMethod method) {
  const size_t n = parent.size();
  if (method == CreaseMethod::Uniform || n < 2) {
    for (size_t i = 0; i < n; ++i) child[i] = decremented_sharpness(parent[i]);
    return;
  }
  float sum = 0.f;
  int count = 0;
  for (float s : parent)
    if (is_semi_sharp(s)) sum += s, ++count;
  for (size_t i = 0; i < n; ++i)
    child[i] = is_semi_sharp(parent[i]) ? averaged_decay(parent[i], sum, count) : decremented_sharpness(parent[i]);
}

float child_edge_sharpness(const Level& parent, Index e, Index v, CreaseMethod method) {
  const float s = effective_sharpness(parent, e);
  const auto ring = parent.ring_edges(v);
  if (method == CreaseMethod::Uniform || ring.size() < 2 || !is_semi_sharp(s)) return decremented_sharpness(s);
  float sum = 0.f;
  int count = 0;
  for (Index other : ring)
    if (const float t = effective_sharpness(parent, other); is_semi_sharp(t)) sum += t, ++count;
  return averaged_decay(s, sum, count);
}

}  // namespace subdiv
