#pragma once
// Which rule each parent vertex and edge uses, from boundaries and sharpness tags
// (DeRose, Kass, Truong 1998; the rule logic of OpenSubdiv's Sdc::Scheme and Sdc::Crease).
#include <array>
#include <vector>

#include "framework/features/context.h"
#include "framework/features/feature_options.h"
#include "framework/features/sharpness.h"
#include "framework/topology/level.h"

namespace subdiv {

// An edge's new point is crease_weight * (crease rule) + (1 - crease_weight) * (smooth rule).
// crease_weight is 0 (smooth), 1 (crease), or the edge's sharpness in a transition; that can
// exceed 1 with Chaikin creasing, as in OpenSubdiv.
struct EdgeContext {
  float crease_weight = 0.f;
};

// A vertex's new point is parent_weight * (parent rule) + (1 - parent_weight) * (child
// rule); the child rule is the one the vertex will have after its sharpness decays one
// level. crease_* hold the ring positions of the two sharp edges for crease rules.
struct VertexContext {
  Context parent = Context::Smooth, child = Context::Smooth;
  float parent_weight = 1.f;
  std::array<std::uint16_t, 2> parent_crease{0, 0}, child_crease{0, 0};
};

struct FeatureContexts {
  std::vector<EdgeContext> edges;
  std::vector<VertexContext> vertices;
  std::vector<float> edge_sharpness;    // effective: boundary edges are infinitely sharp
  std::vector<float> vertex_sharpness;  // effective: boundary corners per the options
};

FeatureContexts classify_features(const Level& level, const FeatureOptions& options);

}  // namespace subdiv
