// sqrt(3) split (Kobbelt 2000; seed 000 §4): a new point in every face, joined to the face's
// corners; every old interior edge is flipped to join the two new points beside it.
// Boundary and sharp edges are not flipped: in odd steps (counted from 1 at the input) the
// triangle beside them is kept whole, in even steps the edge is trisected, so two steps
// give a 1-to-9 split of boundary triangles as well (Kobbelt's boundary rule).
#include <fmt/format.h>

#include "framework/refine/child_tags.h"
#include "framework/refine/splitter.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

bool is_feature_edge(const Level& L, Index e) {
  return L.edge_on_boundary(e) || L.edge_sharp(e) > 0.f;
}

struct Sqrt3Builder {
  const Level& L;
  bool trisect;
  Index face_point_base;
  std::vector<Index> trisection_base;  // per edge: first of its two new points, or kNone
  std::vector<Index> offsets{0}, corners;
  std::vector<Index> parent_face;

  void add_triangle(Index a, Index b, Index c, Index f) {
    corners.insert(corners.end(), {a, b, c});
    offsets.push_back(Index(corners.size()));
    parent_face.push_back(f);
  }

  // The triangles between face f's new point and its feature edge e, run by f from a to b.
  void add_feature_side(Index e, Index f, Index a, Index b) {
    const Index c = face_point_base + f;
    if (!trisect) return add_triangle(a, b, c, f);
    // New points sit at 1/3 and 2/3 along the edge's own direction.
    const bool forward = L.edge_vertices[2 * e] == a;
    const Index p_near_a = trisection_base[e] + (forward ? 0 : 1);
    const Index p_near_b = trisection_base[e] + (forward ? 1 : 0);
    add_triangle(a, p_near_a, c, f);
    add_triangle(p_near_a, p_near_b, c, f);
    add_triangle(p_near_b, b, c, f);
  }

  void add_edge(Index e) {
    const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
    const Index f0 = L.edge_faces[2 * e], f1 = L.edge_faces[2 * e + 1];
    if (is_feature_edge(L, e)) {
      add_feature_side(e, f0, a, b);
      if (f1 != kNone) add_feature_side(e, f1, b, a);
      return;
    }
    // f0 lies left of a->b: the flipped edge joins c0 (left) and c1 (right).
    const Index c0 = face_point_base + f0, c1 = face_point_base + f1;
    add_triangle(a, c1, c0, f0);
    add_triangle(b, c0, c1, f1);
  }
};

}  // namespace

SplitResult split_sqrt3(const Level& parent, int step_index) {
  const Index V = parent.vertex_count, F = parent.face_count();
  for (Index f = 0; f < F; ++f)
    if (parent.face_size(f) != 3)
      throw Error(fmt::format("the sqrt3 split needs triangles, but face {} has {} vertices", f, parent.face_size(f)));
  Sqrt3Builder b{parent, step_index % 2 == 1, V, std::vector<Index>(parent.edge_count(), kNone), {0}, {}, {}};
  ChildOrigins o;
  auto add_origin = [&](OriginKind kind, Index p, std::uint8_t local) {
    o.kind.push_back(kind), o.parent.push_back(p), o.local.push_back(local);
  };
  for (Index v = 0; v < V; ++v) add_origin(OriginKind::Vertex, v, 0);
  for (Index f = 0; f < F; ++f) add_origin(OriginKind::Face, f, 0);
  Index next = V + F;
  if (b.trisect)
    for (Index e = 0; e < parent.edge_count(); ++e)
      if (is_feature_edge(parent, e)) {
        b.trisection_base[e] = next;
        next += 2;
        add_origin(OriginKind::Edge, e, 0), add_origin(OriginKind::Edge, e, 1);
      }
  for (Index e = 0; e < parent.edge_count(); ++e) b.add_edge(e);
  o.parent_face = std::move(b.parent_face);
  SplitResult result{build_level(next, b.offsets, b.corners), std::move(o), b.trisect};

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
      if (b.trisect) chain.insert(chain.end(), {b.trisection_base[e], b.trisection_base[e] + 1});
      chain.push_back(bb);
      for (size_t i = 0; i + 1 < chain.size(); ++i)
        child.edge_sharpness[find_edge(child, chain[i], chain[i + 1])] = s;
    }
  }
  return result;
}

}  // namespace subdiv
