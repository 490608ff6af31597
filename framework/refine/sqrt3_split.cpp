// sqrt(3) split (Kobbelt 2000, section 5): a new point in every face, joined to
// the face's corners; every old interior edge is flipped to join the two new points beside it.
// Boundary and sharp ("feature") edges are never flipped; Kobbelt's boundary rule alternates:
//
//  - odd steps (the 1st, 3rd, ... counted from the input): the triangle beside a feature
//    edge gets its face point like any other, joined to the edge's two ends, and the
//    triangle (a, b, face point) is kept whole;
//  - even steps: the feature edge a-b is trisected (a, p_a, p_b, b) and the triangle
//    (a, b, c) beside it gets NO face point: it becomes the middle triangle (p_a, p_b, c),
//    and its two other edges are flipped to the trisection point at their end, a-c to
//    p_a-x and b-c to p_b-y, x and y being the new points beside a-c and b-c in the
//    neighbouring triangles.
//
// Two steps therefore make a 1-to-9 split of every triangle, boundary triangles included,
// the boundary has 3x the edges, F' = 3F in every step, and a boundary vertex with k faces
// gets k+1 faces in the odd step and k again in the even one (so regular boundary
// vertices keep valence 4 at even levels). After an odd step every triangle has at most
// one feature edge; a triangle with two or three in an even step (its input did not come
// from an odd sqrt3 step: --start-level 1 on another mesh, or a scheme sequence) keeps its
// face point, joined to its corners and trisection points.
//
// Non-manifold levels (topology/level.h): the flip is defined for an edge with exactly two
// faces that run it in opposite directions, the two triangles it turns into two others.
// An edge with three or more faces, or two that run it the same way, has no such pair, so
// it is treated like the boundary edges of Kobbelt's rule (section 5): kept, as a feature
// edge, each of its faces gets the triangle(s) beside it that a boundary triangle gets, and
// it is trisected in even steps. This matches what the rules already do at such an edge
// (features/base_tags.h makes it infinitely sharp, as OpenSubdiv does), so the result is a
// valid mesh with the same topology (Euler characteristic) as the input; the split says in
// its warning how many non-manifold edges and vertices it met.
#include <algorithm>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "framework/features/sharpness.h"
#include "framework/refine/child_tags.h"
#include "framework/refine/splitter.h"
#include "framework/refine/sqrt3_topology.h"
#include "framework/util/bulk_memory.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

bool is_feature_edge(const Level& L, Index e) {
  return L.edge_on_boundary(e) || L.edge_sharp(e) > 0.f || L.non_manifold_edge(e);
}

// True when face f, at its `occurrence`-th use of edge e (a collapsed face (a, b, b) runs
// a-b twice, once each way), runs e from its first vertex to its second. On a manifold level
// the slot in edge_faces says it; the faces of a non-manifold edge are in no particular order.
bool runs_forward(const Level& L, Index f, Index e, int occurrence) {
  for (Index i = L.face_offsets[f]; i < L.face_offsets[f + 1]; ++i)
    if (L.face_edges[i] == e && occurrence-- == 0) return L.face_vertices[i] == L.edge_vertices[2 * e];
  return false;
}

// Every non-manifold edge is infinitely sharp (features/base_tags.h). The pieces of a parent's
// non-manifold edge inherit that above; a collapsed face ((a, b, b), topology/level_builder.cpp)
// also gives non-manifold edges with no such parent, from its face point to its corners, and
// those get it here, so that the rules find them a crease rule.
void sharpen_new_non_manifold_edges(Level& child) {
  if (child.manifold()) return;
  for (Index e = 0; e < child.edge_count(); ++e) {
    if (!child.non_manifold_edge(e) || child.edge_sharp(e) >= kInfinitelySharp) continue;
    if (child.edge_sharpness.empty()) child.edge_sharpness.assign(child.edge_count(), 0.f);
    child.edge_sharpness[e] = kInfinitelySharp;
  }
}

// The warning of a non-manifold level, or empty.
std::string non_manifold_warning(const Level& L) {
  if (L.manifold()) return {};
  Index edges = 0, vertices = 0;
  for (Index e = 0; e < L.edge_count(); ++e) edges += L.non_manifold_edge(e);
  for (Index v = 0; v < L.vertex_count; ++v) vertices += L.non_manifold_vertex(v);
  return fmt::format("the sqrt3 split does not flip an edge without two consistently oriented faces, so it kept "
                     "{} non-manifold edge(s) as sharp creases (trisected every second step, like a boundary); "
                     "{} non-manifold vertex/vertices took the corner or crease rule",
                     edges, vertices);
}

struct Sqrt3Builder {
  const Level& L;
  bool trisect;
  std::vector<Index> face_point;        // per face: its new point, or kNone (even steps:
                                        // a triangle with exactly one feature edge)
  std::vector<Index> face_feature_edge;  // per face without a face point: its feature edge
  std::vector<Index> trisection_base;    // per edge: first of its two new points, or kNone
  std::vector<Index> offsets{0}, corners;
  std::vector<Index> parent_face;

  void add_triangle(Index a, Index b, Index c, Index f) {
    corners.insert(corners.end(), {a, b, c});
    offsets.push_back(Index(corners.size()));
    parent_face.push_back(f);
  }

  // The trisection point of feature edge e next to its end v.
  Index trisection_point(Index e, Index v) const {
    return trisection_base[e] + (L.edge_vertices[2 * e] == v ? 0 : 1);
  }

  // The new point that stands for face f across its (non-feature) edge e: the face point,
  // or, in a triangle without one, the trisection point of its feature edge at the end the
  // two edges share.
  Index representative(Index f, Index e) const {
    if (face_point[f] != kNone) return face_point[f];
    const Index fe = face_feature_edge[f];
    const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
    const Index shared = (a == L.edge_vertices[2 * fe] || a == L.edge_vertices[2 * fe + 1]) ? a : b;
    return trisection_point(fe, shared);
  }

  // The triangles of face f beside its feature edge e, run by f from a to b.
  void add_feature_side(Index e, Index f, Index a, Index b) {
    if (face_point[f] == kNone) {
      // The middle triangle (p_a, p_b, c) of a triangle without a face point.
      const Index c = third_vertex(f, a, b);
      return add_triangle(trisection_point(e, a), trisection_point(e, b), c, f);
    }
    const Index c = face_point[f];
    if (!trisect) return add_triangle(a, b, c, f);
    // An edge from a vertex to itself (a collapsed face's) is run from its first point to its
    // second: its two ends cannot tell them apart.
    const bool loop = a == b;
    const Index p_near_a = loop ? trisection_base[e] : trisection_point(e, a);
    const Index p_near_b = loop ? trisection_base[e] + 1 : trisection_point(e, b);
    add_triangle(a, p_near_a, c, f);
    add_triangle(p_near_a, p_near_b, c, f);
    add_triangle(p_near_b, b, c, f);
  }

  Index third_vertex(Index f, Index a, Index b) const {
    for (Index i = L.face_offsets[f]; i < L.face_offsets[f + 1]; ++i)
      if (L.face_vertices[i] != a && L.face_vertices[i] != b) return L.face_vertices[i];
    return kNone;
  }

  void add_edge(Index e) {
    const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
    const Index f0 = L.edge_faces[2 * e], f1 = L.edge_faces[2 * e + 1];
    if (L.non_manifold_edge(e)) {
      const auto faces = L.faces_of_edge(e);  // a face that uses e twice is listed twice
      for (size_t i = 0; i < faces.size(); ++i) {
        const int occurrence = int(std::count(faces.begin(), faces.begin() + i, faces[i]));
        runs_forward(L, faces[i], e, occurrence) ? add_feature_side(e, faces[i], a, b) : add_feature_side(e, faces[i], b, a);
      }
      return;
    }
    if (is_feature_edge(L, e)) {
      add_feature_side(e, f0, a, b);
      if (f1 != kNone) add_feature_side(e, f1, b, a);
      return;
    }
    // f0 lies left of a->b: the flipped edge joins c0 (left) and c1 (right).
    const Index c0 = representative(f0, e), c1 = representative(f1, e);
    add_triangle(a, c1, c0, f0);
    add_triangle(b, c0, c1, f1);
  }
};

// The common case (sqrt3_topology.h): every edge flipped, children laid out in runs.
SplitResult flip_children(const Level& parent, bool trisect, bool full, std::vector<Index>* trisection_base) {
  const Index V = parent.vertex_count, F = parent.face_count();
  ChildOrigins o;
  resize_bulk(o.kind, size_t(V + F));
  resize_bulk(o.parent, size_t(V + F));
  assign_bulk(o.local, size_t(V + F), LocalIndex(0));
  tbb::parallel_for(Index(0), V + F, [&](Index i) {
    o.kind[i] = i < V ? OriginKind::Vertex : OriginKind::Face;
    o.parent[i] = i < V ? i : i - V;
  });
  o.runs.emplace();
  if (V > 0) o.runs->first[int(OriginKind::Vertex)] = 0, o.runs->count[int(OriginKind::Vertex)] = V;
  if (F > 0) o.runs->first[int(OriginKind::Face)] = V, o.runs->count[int(OriginKind::Face)] = F;
  Level child = sqrt3_flip_topology(parent, full, &o.parent_face);
  trisection_base->assign(parent.edge_count(), kNone);
  return {std::move(child), std::move(o), trisect, {}};
}

// The child's faces and origins, and (with `full`) its edges and rings; the trisection
// points' first index per feature edge in *trisection_base.
SplitResult sqrt3_children(const Level& parent, int step_index, bool full, std::vector<Index>* trisection_base) {
  const Index V = parent.vertex_count, F = parent.face_count(), E = parent.edge_count();
  for (Index f = 0; f < F; ++f)
    if (parent.face_size(f) != 3)
      throw Error(fmt::format("the sqrt3 split needs triangles, but face {} has {} vertices", f, parent.face_size(f)));
  const bool trisect = step_index % 2 == 1;
  if (sqrt3_flips_every_edge(parent)) return flip_children(parent, trisect, full, trisection_base);
  Sqrt3Builder b{parent, trisect, std::vector<Index>(F, kNone), std::vector<Index>(F, kNone),
                 std::vector<Index>(E, kNone), {0}, {}, {}};
  ChildOrigins o;
  auto add_origin = [&](OriginKind kind, Index p, LocalIndex local) {
    o.kind.push_back(kind), o.parent.push_back(p), o.local.push_back(local);
  };
  for (Index v = 0; v < V; ++v) add_origin(OriginKind::Vertex, v, 0);
  // In trisecting steps a triangle with exactly one feature edge gets no face point.
  if (trisect)
    for (Index f = 0; f < F; ++f) {
      int features = 0;
      for (Index i = parent.face_offsets[f]; i < parent.face_offsets[f + 1]; ++i)
        if (is_feature_edge(parent, parent.face_edges[i])) ++features, b.face_feature_edge[f] = parent.face_edges[i];
      if (features != 1) b.face_feature_edge[f] = kNone;
    }
  Index next = V;
  for (Index f = 0; f < F; ++f)
    if (b.face_feature_edge[f] == kNone) b.face_point[f] = next++, add_origin(OriginKind::Face, f, 0);
  if (trisect)
    for (Index e = 0; e < E; ++e)
      if (is_feature_edge(parent, e)) {
        b.trisection_base[e] = next;
        next += 2;
        add_origin(OriginKind::Edge, e, 0), add_origin(OriginKind::Edge, e, 1);
      }
  for (Index e = 0; e < E; ++e) b.add_edge(e);
  o.parent_face.assign(b.parent_face.begin(), b.parent_face.end());
  Level child;
  if (full) {
    child = build_level(next, b.offsets, b.corners);
  } else {
    child.vertex_count = next;
    child.face_offsets.assign(b.offsets.begin(), b.offsets.end());
    child.face_vertices.assign(b.corners.begin(), b.corners.end());
  }
  *trisection_base = std::move(b.trisection_base);
  return {std::move(child), std::move(o), trisect, non_manifold_warning(parent)};
}

}  // namespace

SplitResult split_sqrt3_faces(const Level& parent, int step_index) {
  std::vector<Index> trisection_base;
  return sqrt3_children(parent, step_index, false, &trisection_base);
}

SplitResult split_sqrt3(const Level& parent, int step_index) {
  const Index V = parent.vertex_count;
  const bool trisect = step_index % 2 == 1;
  std::vector<Index> trisection_base;
  SplitResult result = sqrt3_children(parent, step_index, true, &trisection_base);

  // Feature tags: a sharp edge's pieces keep its (decremented) sharpness.
  Level& child = result.child;
  if (!parent.vertex_sharpness.empty()) {
    child.vertex_sharpness.assign(child.vertex_count, 0.f);
    for (Index v = 0; v < V; ++v) child.vertex_sharpness[v] = decremented_sharpness(parent.vertex_sharpness[v]);
  }
  if (!parent.edge_sharpness.empty()) {
    child.edge_sharpness.assign(child.edge_count(), 0.f);
    for (Index e = 0; e < parent.edge_count(); ++e) {
      if (parent.edge_sharpness[e] <= 0.f || parent.edge_on_boundary(e)) continue;
      const float s = decremented_sharpness(parent.edge_sharpness[e]);
      const Index a = parent.edge_vertices[2 * e], bb = parent.edge_vertices[2 * e + 1];
      std::vector<Index> chain{a};
      if (trisect) chain.insert(chain.end(), {trisection_base[e], trisection_base[e] + 1});
      chain.push_back(bb);
      for (size_t i = 0; i + 1 < chain.size(); ++i)
        if (const Index piece = find_edge(child, chain[i], chain[i + 1]); piece != kNone) child.edge_sharpness[piece] = s;
    }
  }
  sharpen_new_non_manifold_edges(child);
  return result;
}

}  // namespace subdiv
