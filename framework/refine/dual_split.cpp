// Dual splits. Doo-Sabin (Doo & Sabin 1978; boundaries: Nasri 1987): a new point per face corner; the new
// faces are F-faces (one per old face), E-faces (one per interior edge) and V-faces (one
// per vertex whose faces close around it, or per boundary vertex with three or more
// faces). Mid-edge (Peters-Reif 1997): a new point per edge; F-faces and V-faces.
//
// Non-manifold levels (topology/level.h): a dual face needs a CCW cycle around its edge or
// vertex, which a non-manifold edge or vertex does not have, so neither split makes one
// there; the result is a valid mesh with a gap at each such element, and the split says so
// in its warning.
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "framework/features/dual_features.h"
#include "framework/features/sharpness.h"
#include "framework/refine/dual_crease_topology.h"
#include "framework/refine/dual_topology.h"
#include "framework/refine/mid_edge_crease_topology.h"
#include "framework/refine/splitter.h"
#include "framework/util/bulk_memory.h"

namespace subdiv {
namespace {

// The corner index (into face_vertices) of vertex v in face f.
Index corner_of(const Level& L, Index f, Index v) {
  for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c)
    if (L.face_vertices[c] == v) return c;
  return kNone;
}

// Child vertex i comes from element i of `kind` (a corner: its face and place in it; an edge).
// Child faces after the F-faces lie in no single parent face.
ChildOrigins dual_origins(const Level& L, OriginKind kind, Index child_faces) {
  ChildOrigins o;
  const Index n = kind == OriginKind::Corner ? L.corner_count() : L.edge_count();
  const Index F = L.face_count();
  assign_bulk(o.kind, size_t(n), kind);
  resize_bulk(o.parent, size_t(n));
  assign_bulk(o.local, size_t(n), LocalIndex(0));
  assign_bulk(o.parent_face, size_t(child_faces), kNone);
  tbb::parallel_for(Index(0), F, [&](Index f) { o.parent_face[f] = f; });
  if (kind == OriginKind::Corner)
    tbb::parallel_for(Index(0), F, [&](Index f) {
      for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c)
        o.parent[c] = f, o.local[c] = LocalIndex(c - L.face_offsets[f]);
    });
  else
    tbb::parallel_for(Index(0), n, [&](Index e) { o.parent[e] = e; });
  // One run: child i is element i's (so the rules need not scan the origins to see it).
  o.runs.emplace();
  if (n > 0) o.runs->first[int(kind)] = 0, o.runs->count[int(kind)] = n;
  return o;
}

// Interior creases and corners: the sides of each sharp edge glued along their crease
// points, corners collapsed (refine/dual_crease_topology.h).
SplitResult feature_result(const Level& L, bool full) {
  Index skipped = 0;
  DualFeatureSplit split = dual_feature_split(L, full, &skipped);
  SplitResult result{std::move(split.child), std::move(split.origins), true, {}};
  result.averaged_edge_sharpness = std::move(split.averaged_edge_sharpness);
  if (skipped)
    result.warning = fmt::format("the dual split made no face for {} non-manifold vertex/vertices (they have no "
                                 "cycle of faces around them); the surface has a gap there",
                                 skipped);
  return result;
}

SplitResult dual_result(const Level& L, bool full) {
  if (dual_needs_feature_topology(L)) return feature_result(L, full);
  DualSkipped skipped;
  Level child = dual_split_topology(L, full, &skipped);
  const Index child_faces = child.face_count();
  SplitResult result{std::move(child), dual_origins(L, OriginKind::Corner, child_faces), true, {}};
  if (skipped.edges || skipped.vertices)
    result.warning = fmt::format("the dual split made no face for {} non-manifold edge(s) and {} non-manifold "
                                 "vertex/vertices (they have no cycle of faces around them); the surface has a gap there",
                                 skipped.edges, skipped.vertices);
  return result;
}

SplitResult mid_edge_result(const Level& L, bool full) {
  // Interior creases cut the V-faces into sectors (refine/mid_edge_crease_topology.h).
  DualSkipped skipped;
  std::vector<float> averaged;
  Level child = mid_edge_needs_crease_topology(L) ? mid_edge_crease_split(L, full, &skipped.vertices, &averaged)
                                                  : mid_edge_split_topology(L, full, &skipped);
  const Index child_faces = child.face_count();
  SplitResult result{std::move(child), dual_origins(L, OriginKind::Edge, child_faces), true, {}};
  result.averaged_edge_sharpness = std::move(averaged);
  if (skipped.vertices)
    result.warning = fmt::format("the mid-edge split made no face for {} non-manifold vertex/vertices (they have no "
                                 "cycle of edges around them); the surface has a gap there",
                                 skipped.vertices);
  return result;
}

}  // namespace

SplitResult split_dual(const Level& L) {
  if (dual_needs_feature_topology(L)) return feature_result(L, true);
  SplitResult result = dual_result(L, true);
  // A sharp edge's E-face keeps the sharpness on its two long sides (the F-face edges
  // along the old edge), so the crease stays a crease in the dual mesh.
  if (!L.edge_sharpness.empty()) {
    Level& child = result.child;
    child.edge_sharpness.assign(child.edge_count(), 0.f);
    for (Index e = 0; e < L.edge_count(); ++e) {
      if (L.edge_sharpness[e] <= 0.f || L.edge_on_boundary(e)) continue;
      const float s = decremented_sharpness(L.edge_sharpness[e]);
      const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
      for (Index f : {L.edge_faces[2 * e], L.edge_faces[2 * e + 1]}) {
        const Index half = find_edge(child, corner_of(L, f, a), corner_of(L, f, b));
        if (half != kNone) child.edge_sharpness[half] = s;
      }
    }
  }
  return result;
}

SplitResult split_dual_faces(const Level& L) { return dual_result(L, false); }

SplitResult split_mid_edge(const Level& L) { return mid_edge_result(L, true); }
SplitResult split_mid_edge_faces(const Level& L) { return mid_edge_result(L, false); }

}  // namespace subdiv
