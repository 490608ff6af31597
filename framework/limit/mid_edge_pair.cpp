#include "framework/limit/mid_edge_pair.h"

#include <fmt/format.h>

#include "framework/util/error.h"

namespace subdiv {
namespace {

// The vertex edges a and b of `parent` share, or kNone.
Index shared_vertex(const Level& parent, Index a, Index b) {
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k)
      if (parent.edge_vertices[size_t(2 * a + i)] == parent.edge_vertices[size_t(2 * b + k)])
        return parent.edge_vertices[size_t(2 * a + i)];
  return kNone;
}

}  // namespace

ChildOrigins mid_edge_pair_origins(const Level& parent, const Level& middle, const Level& grand,
                                   const ChildOrigins& first, const ChildOrigins& second) {
  ChildOrigins o;
  const size_t vertices = second.kind.size();
  o.kind.assign(vertices, OriginKind::Corner);
  o.parent.assign(vertices, kNone);
  o.local.assign(vertices, LocalIndex(0));
  for (size_t x = 0; x < vertices; ++x) {
    // The grand vertex is the middle of a middle edge, whose ends are the middles of two
    // edges of the parent around a corner; the edge's F-face side names the face.
    const Index e1 = second.kind[x] == OriginKind::Edge ? second.parent[x] : kNone;
    if (e1 == kNone) throw Error("internal: a mid-edge step's vertex is not an edge's middle");
    const Index a = first.parent[size_t(middle.edge_vertices[size_t(2 * e1)])];
    const Index b = first.parent[size_t(middle.edge_vertices[size_t(2 * e1 + 1)])];
    Index g = kNone;
    for (int side = 0; side < 2; ++side) {
      const Index f = middle.edge_faces[size_t(2 * e1 + side)];
      if (f != kNone && first.parent_face[size_t(f)] != kNone) g = first.parent_face[size_t(f)];
    }
    const Index v = shared_vertex(parent, a, b);
    if (g == kNone || v == kNone)
      throw Error(fmt::format("internal: the mid-edge steps' point {} stands for no corner", x));
    const auto corners = parent.face(g);
    for (size_t j = 0; j < corners.size(); ++j)
      if (corners[j] == v) o.local[x] = LocalIndex(j);
    o.parent[x] = g;
  }
  // The F-faces come first in each step (refine/dual_split.cpp): grand face t < the middle's
  // face count is the F-face of middle face t, itself g's F-face when t is one of the first.
  o.parent_face.assign(size_t(grand.face_count()), kNone);
  for (Index t = 0; t < middle.face_count() && t < grand.face_count(); ++t)
    if (second.parent_face[size_t(t)] == t) o.parent_face[size_t(t)] = first.parent_face[size_t(t)];
  return o;
}

}  // namespace subdiv
