#pragma once
// What the kernels (smooth_kernels.h, flat_kernels.h) ask of an element's feature context:
// they compute smooth interior elements only. On a level without sharpness tags that
// follows from topology alone (feature_context.cpp: only boundary and non-manifold edges
// are sharp there, and a vertex only as a boundary corner or without edges), so the
// contexts are not read; the step evaluator relies on this to classify such a level only
// when a row needs the interpreter (engine/refiner.cpp, prepare_step). Callers have already
// left out boundary and non-manifold vertices and edges.
#include "framework/features/dual_features.h"
#include "framework/features/feature_context.h"
#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

// No sharpness tags: contexts follow from topology, and may be left unclassified.
inline bool without_sharpness_tags(const Level& L) { return L.edge_sharpness.empty() && L.vertex_sharpness.empty(); }

// Interior vertex v of valence n takes the smooth rule now and one level down.
inline bool smooth_vertex(const FeatureContexts& F, bool untagged, Index v, int n) {
  if (untagged) return n > 0;
  const VertexContext& vc = F.vertices[v];
  return vc.parent == Context::Smooth && vc.child == Context::Smooth;
}

// Vertex v may have a sector (end_sectors.h): it lies on a boundary or crease, or is a corner.
inline bool feature_vertex(const Level& L, const FeatureContexts& F, bool untagged, Index v) {
  if (untagged) return L.on_boundary(v) || L.non_manifold_vertex(v);
  const Context c = F.vertices[v].parent;
  return c == Context::Crease || c == Context::Corner;
}

// Interior edge e is not (even partly) a crease.
inline bool smooth_edge(const FeatureContexts& F, bool untagged, Index e) {
  return untagged || F.edges[e].crease_weight == 0.f;
}

// The face corner at `vertex` between the face's edges in_edge and out_edge lies on a
// feature: a sharp vertex, or a sharp edge on either side.
inline bool sharp_corner(const Level& L, const FeatureContexts& F, bool untagged, Index vertex, Index out_edge,
                         Index in_edge) {
  if (untagged)
    return L.edge_on_boundary(out_edge) || L.edge_on_boundary(in_edge) || L.non_manifold_edge(out_edge) ||
           L.non_manifold_edge(in_edge);
  return F.vertex_sharpness[vertex] > 0.f || F.edges[out_edge].crease_weight != 0.f ||
         F.edges[in_edge].crease_weight != 0.f;
}

// In the dual split of a level with features (refine/dual_crease_topology.h) every corner
// of a collapsing vertex is that vertex's one child point, whatever its face edges.
inline bool dual_feature_corner(const Level& L, const ChildOrigins& o, Index vertex) {
  return !o.corner_side.empty() && dual_collapses(L, vertex);
}

}  // namespace subdiv
