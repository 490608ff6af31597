// Dual splits. Doo-Sabin (seed 000 §4(b), seed 004): a new point per face corner; the new
// faces are F-faces (one per old face), E-faces (one per interior edge) and V-faces (one
// per vertex whose faces close around it, or per boundary vertex with three or more
// faces). Mid-edge (Peters-Reif 1997): a new point per edge; F-faces and V-faces.
//
// Non-manifold levels (topology/level.h): a dual face needs a CCW cycle around its edge or
// vertex, which a non-manifold edge or vertex does not have, so neither split makes one
// there; the result is a valid mesh with a gap at each such element, and the split says so
// in its warning.
#include <fmt/format.h>

#include "framework/refine/child_tags.h"
#include "framework/refine/splitter.h"

namespace subdiv {
namespace {

struct FaceList {
  std::vector<Index> offsets{0}, corners, parent_face;
  void add(std::initializer_list<Index> vs, Index f) { add_range(vs.begin(), vs.end(), f); }
  template <class It>
  void add_range(It begin, It end, Index f) {
    corners.insert(corners.end(), begin, end);
    offsets.push_back(Index(corners.size()));
    parent_face.push_back(f);
  }
};

// The corner index (into face_vertices) of vertex v in face f.
Index corner_of(const Level& L, Index f, Index v) {
  for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c)
    if (L.face_vertices[c] == v) return c;
  return kNone;
}

// V-face points around v, CCW; empty when they would not make a polygon.
template <class PointOfRing>
void add_vertex_face(FaceList& faces, PointOfRing point, int count) {
  if (count < 3) return;
  std::vector<Index> ring(count);
  for (int i = 0; i < count; ++i) ring[i] = point(i);
  faces.add_range(ring.begin(), ring.end(), kNone);
}

}  // namespace

SplitResult split_dual(const Level& L) {
  FaceList faces;
  // F-faces: the face's own corners (child vertex c is parent corner c).
  for (Index f = 0; f < L.face_count(); ++f) {
    std::vector<Index> own(L.face_size(f));
    for (int i = 0; i < L.face_size(f); ++i) own[i] = L.face_offsets[f] + i;
    faces.add_range(own.begin(), own.end(), f);
  }
  // E-faces: f0 lies left of a->b, so (f1@a, f1@b, f0@b, f0@a) runs CCW.
  Index skipped_edges = 0, skipped_vertices = 0;
  for (Index e = 0; e < L.edge_count(); ++e) {
    if (L.edge_on_boundary(e)) continue;
    if (L.non_manifold_edge(e)) {
      ++skipped_edges;
      continue;
    }
    const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
    const Index f0 = L.edge_faces[2 * e], f1 = L.edge_faces[2 * e + 1];
    faces.add({corner_of(L, f1, a), corner_of(L, f1, b), corner_of(L, f0, b), corner_of(L, f0, a)}, kNone);
  }
  // V-faces: the corners around each vertex, in its CCW ring order.
  for (Index v = 0; v < L.vertex_count; ++v) {
    if (L.non_manifold_vertex(v)) {
      ++skipped_vertices;
      continue;
    }
    const Index first = L.vertex_face_offsets[v];
    add_vertex_face(faces, [&](int i) { return L.face_offsets[L.vertex_faces[first + i]] + L.vertex_face_corner[first + i]; },
                    L.incident_face_count(v));
  }
  ChildOrigins o;
  const Index n = L.corner_count();
  o.kind.assign(n, OriginKind::Corner);
  o.parent.resize(n);
  o.local.resize(n);
  for (Index f = 0; f < L.face_count(); ++f)
    for (int i = 0; i < L.face_size(f); ++i) o.parent[L.face_offsets[f] + i] = f, o.local[L.face_offsets[f] + i] = LocalIndex(i);
  o.parent_face = faces.parent_face;
  SplitResult result{build_level(n, faces.offsets, faces.corners), std::move(o), true};
  if (skipped_edges || skipped_vertices)
    result.warning = fmt::format("the dual split made no face for {} non-manifold edge(s) and {} non-manifold "
                                 "vertex/vertices (they have no cycle of faces around them); the surface has a gap there",
                                 skipped_edges, skipped_vertices);

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

SplitResult split_mid_edge(const Level& L) {
  FaceList faces;
  for (Index f = 0; f < L.face_count(); ++f) {
    const auto edges = L.face_edge_list(f);
    faces.add_range(edges.begin(), edges.end(), f);
  }
  Index skipped = 0;
  for (Index v = 0; v < L.vertex_count; ++v) {
    if (L.non_manifold_vertex(v)) {
      ++skipped;
      continue;
    }
    const auto ring = L.ring_edges(v);
    add_vertex_face(faces, [&](int i) { return ring[i]; }, int(ring.size()));
  }
  ChildOrigins o;
  const Index n = L.edge_count();
  o.kind.assign(n, OriginKind::Edge);
  o.parent.resize(n);
  o.local.assign(n, 0);
  for (Index e = 0; e < n; ++e) o.parent[e] = e;
  o.parent_face = faces.parent_face;
  SplitResult result{build_level(n, faces.offsets, faces.corners), std::move(o), true};
  if (skipped)
    result.warning = fmt::format("the mid-edge split made no face for {} non-manifold vertex/vertices (they have no "
                                 "cycle of edges around them); the surface has a gap there",
                                 skipped);
  return result;
}

}  // namespace subdiv
