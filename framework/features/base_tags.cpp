#include "framework/features/base_tags.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "framework/features/sharpness.h"

namespace subdiv {
namespace {

void ensure_edge_tags(Level& L) {
  if (L.edge_sharpness.empty()) L.edge_sharpness.assign(L.edge_count(), 0.f);
}
void ensure_vertex_tags(Level& L) {
  if (L.vertex_sharpness.empty()) L.vertex_sharpness.assign(L.vertex_count, 0.f);
}

}  // namespace

Index tag_boundary_holes(Level& L, BoundaryInterpolation mode) {
  if (mode != BoundaryInterpolation::None) return 0;
  Index made = 0;
  for (Index v = 0; v < L.vertex_count; ++v) {
    // Manifold interior vertices have as many edges as faces.
    if (L.valence(v) == L.incident_face_count(v) && !L.non_manifold_vertex(v)) continue;
    bool exclude = false;
    for (Index e : L.ring_edges(v))
      exclude = exclude || (L.edge_face_count(e) == 1 && L.edge_sharp(e) < kInfinitelySharp);
    if (!exclude) continue;
    if (L.face_hole.empty()) L.face_hole.assign(L.face_count(), 0);
    for (Index f : L.ring_faces(v)) made += !L.face_hole[f], L.face_hole[f] = 1;
  }
  return made;
}

void sharpen_non_manifold(Level& L) {
  if (L.manifold()) return;
  ensure_edge_tags(L);
  for (Index e = 0; e < L.edge_count(); ++e)
    if (L.non_manifold_edge(e)) L.edge_sharpness[e] = kInfinitelySharp;
  for (Index v = 0; v < L.vertex_count; ++v) {
    if (!L.non_manifold_vertex(v)) continue;
    int non_manifold_edges = 0, boundary_edges = 0;
    for (Index e : L.ring_edges(v)) non_manifold_edges += L.non_manifold_edge(e), boundary_edges += L.edge_face_count(e) < 2;
    const bool crease = non_manifold_edges == 2 && boundary_edges == 0 && L.incident_face_count(v) > L.valence(v);
    if (crease) continue;
    ensure_vertex_tags(L);
    L.vertex_sharpness[v] = kInfinitelySharp;
  }
}

void tag_boundary_corners(Level& L, BoundaryInterpolation mode) {
  if (mode != BoundaryInterpolation::EdgesAndCorners) return;
  // In parallel (every vertex of the base level is read): whether there is a corner, then
  // the tags.
  const auto is_corner = [&](Index v) { return L.incident_face_count(v) == 1 && L.valence(v) == 2; };
  const tbb::blocked_range<Index> vertices(0, L.vertex_count, 1 << 16);
  const bool any = tbb::parallel_reduce(
      vertices, false,
      [&](const tbb::blocked_range<Index>& r, bool found) {
        for (Index v = r.begin(); v < r.end() && !found; ++v) found = is_corner(v);
        return found;
      },
      [](bool a, bool b) { return a || b; });
  if (!any) return;
  ensure_vertex_tags(L);
  tbb::parallel_for(vertices, [&](const tbb::blocked_range<Index>& r) {
    for (Index v = r.begin(); v < r.end(); ++v)
      if (is_corner(v)) L.vertex_sharpness[v] = kInfinitelySharp;
  });
}

void tag_base_level(Level& base, BoundaryInterpolation mode) {
  tag_boundary_holes(base, mode);
  sharpen_non_manifold(base);
  tag_boundary_corners(base, mode);
}

}  // namespace subdiv
