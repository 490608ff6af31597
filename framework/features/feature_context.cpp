#include "framework/features/feature_context.h"

#include <algorithm>
#include <tbb/parallel_for.h>

#include "framework/util/resize_side_by_side.h"

namespace subdiv {
namespace {

// Sdc::Crease::DetermineVertexVertexRule: a sharp vertex is a corner; otherwise count the
// sharp (s > 0) incident edges.
Context vertex_rule(float vertex_sharpness, const float* edge_sharpness, int valence) {
  if (vertex_sharpness > 0.f) return Context::Corner;
  int sharp = 0;
  for (int i = 0; i < valence; ++i) sharp += edge_sharpness[i] > 0.f;
  return sharp == 0 ? Context::Smooth : sharp == 1 ? Context::Dart
         : sharp == 2 ? Context::Crease : Context::Corner;
}

std::array<std::uint16_t, 2> crease_pair(const float* edge_sharpness, int valence) {
  std::array<std::uint16_t, 2> pair{0, 0};
  int found = 0;
  for (int i = 0; i < valence && found < 2; ++i)
    if (edge_sharpness[i] > 0.f) pair[found++] = std::uint16_t(i);
  return pair;
}

// Sdc::Crease::ComputeFractionalWeightAtVertex: the mean sharpness of the features that
// decay to smooth this level, clamped to 1.
float fractional_weight(float pv, float cv, const float* pe, const float* ce, int valence) {
  int count = 0;
  float sum = 0.f;
  if (pv > 0.f && cv <= 0.f) ++count, sum += pv;
  for (int i = 0; i < valence; ++i)
    if (pe[i] > 0.f && ce[i] <= 0.f) ++count, sum += pe[i];
  if (count == 0) return 0.f;
  return std::min(1.f, sum / float(count));
}

std::vector<float> effective_edge_sharpness(const Level& level) {
  std::vector<float> s(level.edge_count());
  tbb::parallel_for(Index(0), level.edge_count(), [&](Index e) {
    s[e] = level.edge_on_boundary(e) ? kInfinitelySharp : level.edge_sharp(e);
  });
  return s;
}

std::vector<float> effective_vertex_sharpness(const Level& level, BoundaryInterpolation mode) {
  std::vector<float> s(level.vertex_count);
  tbb::parallel_for(Index(0), level.vertex_count, [&](Index v) {
    s[v] = level.vertex_sharp(v);
    // A topological corner: one face, two edges (Far's isTopologicalCorner).
    const bool boundary_corner = mode == BoundaryInterpolation::EdgesAndCorners &&
                                 level.incident_face_count(v) == 1 && level.valence(v) == 2;
    if (boundary_corner || level.valence(v) == 0) s[v] = kInfinitelySharp;
  });
  return s;
}

VertexContext classify_vertex(const Level& level, const FeatureContexts& fc, Index v,
                              CreaseMethod method) {
  const auto ring = level.ring_edges(v);
  const int n = int(ring.size());
  float parent_edges[64], child_edges[64];
  std::vector<float> heap_parent, heap_child;
  float* pe = parent_edges;
  float* ce = child_edges;
  if (n > 64) heap_parent.resize(n), heap_child.resize(n), pe = heap_parent.data(), ce = heap_child.data();
  for (int i = 0; i < n; ++i) pe[i] = fc.edge_sharpness[ring[i]];

  VertexContext vc;
  const float pv = fc.vertex_sharpness[v];
  vc.parent = vertex_rule(pv, pe, n);
  vc.parent_crease = crease_pair(pe, n);
  vc.child = vc.parent, vc.child_crease = vc.parent_crease;
  if (vc.parent == Context::Smooth || vc.parent == Context::Dart) return vc;

  // The rule the vertex has one level down (Sdc::Scheme::ComputeVertexVertexMask with the
  // child's sharpness from Sdc::Crease::SubdivideEdgeSharpnessesAroundVertex).
  const float cv = decremented_sharpness(pv);
  subdivide_sharpness_around_vertex({pe, size_t(n)}, {ce, size_t(n)}, method);
  vc.child = vertex_rule(cv, ce, n);
  vc.child_crease = crease_pair(ce, n);
  if (vc.child != vc.parent) vc.parent_weight = fractional_weight(pv, cv, pe, ce, n);
  return vc;
}

// Sdc::Scheme::ComputeEdgeVertexMask as Far::PrimvarRefiner calls it: a smooth edge takes
// the smooth rule; a sharp one the crease rule if the new vertex is a crease vertex one
// level down (both child halves sharp), and otherwise the blend
// s * (crease rule) + (1 - s) * (smooth rule) with s the edge's sharpness. Uniform
// creasing reaches the blend only for s <= 1; Chaikin creasing can reach it for s > 1 too
// (a child half next to a less sharp crease decays to 0), and OpenSubdiv then does not
// clamp s, so neither do we.
EdgeContext classify_edge(const Level& level, const FeatureContexts& fc, Index e, CreaseMethod method) {
  const float s = fc.edge_sharpness[e];
  if (s <= 0.f) return {0.f};
  if (s >= kInfinitelySharp) return {1.f};
  const bool child_crease = child_edge_sharpness(level, e, level.edge_vertices[2 * e], method) > 0.f &&
                            child_edge_sharpness(level, e, level.edge_vertices[2 * e + 1], method) > 0.f;
  return {child_crease ? 1.f : s};
}

}  // namespace

FeatureContexts classify_features(const Level& level, const FeatureOptions& options) {
  FeatureContexts fc;
  fc.edge_sharpness = effective_edge_sharpness(level);
  fc.vertex_sharpness = effective_vertex_sharpness(level, options.boundary);
  resize_side_by_side(Sized{fc.edges, size_t(level.edge_count())}, Sized{fc.vertices, size_t(level.vertex_count)});
  tbb::parallel_for(Index(0), level.edge_count(), [&](Index e) {
    fc.edges[e] = classify_edge(level, fc, e, options.crease_method);
  });
  // Without sharpness tags, an interior vertex that is not sharp has no sharp edge: smooth
  // (the default context), found without reading its ring.
  const bool untagged = level.edge_sharpness.empty();
  tbb::parallel_for(Index(0), level.vertex_count, [&](Index v) {
    if (untagged && !level.on_boundary(v) && fc.vertex_sharpness[v] <= 0.f) return;
    fc.vertices[v] = classify_vertex(level, fc, v, options.crease_method);
  });
  return fc;
}

}  // namespace subdiv
