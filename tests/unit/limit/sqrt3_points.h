#pragma once
// Where the vertices two √3 steps make lie in the triadic parameterisation (docs/limit.md,
// "√3 schemes"), read from the engine's origins: the tests' independent route to the
// (face, u, v) of a refined vertex.
#include <algorithm>
#include <array>
#include <initializer_list>
#include <vector>

#include <doctest/doctest.h>

#include "framework/engine/refiner.h"
#include "framework/limit/limit_surface.h"
#include "support/sanitizers.h"
#include "unit/limit/limit_meshes.h"

namespace subdiv::limit_test::sqrt3 {

inline int corner_of(const Level& L, Index f, Index w) {
  const auto fv = L.face(f);
  for (size_t k = 0; k < fv.size(); ++k)
    if (fv[k] == w) return int(k);
  return -1;
}

// (u, v) in face f of the point t of the way from vertex a to vertex b (both corners of f).
inline std::array<double, 2> on_edge(const Level& L, Index f, Index a, Index b, double t) {
  std::array<double, 3> bary{0, 0, 0};
  bary[size_t(corner_of(L, f, a))] += 1 - t;
  bary[size_t(corner_of(L, f, b))] += t;
  return {bary[1], bary[2]};
}

// The face of L with edge a-b (the first one).
inline Index face_with_edge(const Level& L, Index a, Index b) {
  const Index e = find_edge(L, a, b);
  REQUIRE(e != kNone);
  return L.edge_faces[size_t(2 * e)];
}

// The (face, u, v) of a vertex two √3 steps make, from the engine's origins: a base vertex,
// a level-1 face point (a base face's centroid), a level-2 face point over the third of a
// base edge next to a (the level-1 triangle (a, P(f0), P(f1))), or a trisection point of a
// boundary edge (Kobbelt 2000, section 5) a third of the way from the end it is next to.
struct Where {
  Index face = kNone;
  std::array<double, 2> uv{};
};

inline Where where_two_steps_put(const Level& L, const Hierarchy& h, Index v) {
  const ChildOrigins& o1 = h.origins[0];
  const ChildOrigins& o2 = h.origins[1];
  const Level& L1 = h.levels[1];
  const Index p = o2.parent[size_t(v)];
  if (o2.kind[size_t(v)] == OriginKind::Vertex) {
    if (o1.kind[size_t(p)] == OriginKind::Face) return {o1.parent[size_t(p)], {1.0 / 3, 1.0 / 3}};
    const Index w = o1.parent[size_t(p)];
    const Index f = L.ring_faces(w)[0];
    const std::array<double, 2> c[3] = {{0, 0}, {1, 0}, {0, 1}};
    return {f, c[corner_of(L, f, w)]};
  }
  if (o2.kind[size_t(v)] == OriginKind::Edge) {
    const Index a1 = L1.edge_vertices[size_t(2 * p + o2.local[size_t(v)])];
    const Index b1 = L1.edge_vertices[size_t(2 * p + 1 - o2.local[size_t(v)])];
    REQUIRE(o1.kind[size_t(a1)] == OriginKind::Vertex);
    REQUIRE(o1.kind[size_t(b1)] == OriginKind::Vertex);
    const Index a = o1.parent[size_t(a1)], b = o1.parent[size_t(b1)];
    const Index f = face_with_edge(L, a, b);
    return {f, on_edge(L, f, a, b, 1.0 / 3)};
  }
  REQUIRE(o2.kind[size_t(v)] == OriginKind::Face);
  Index a = kNone;
  std::vector<Index> faces;
  for (Index x : L1.face(p)) {
    if (o1.kind[size_t(x)] == OriginKind::Vertex) a = o1.parent[size_t(x)];
    else faces.push_back(o1.parent[size_t(x)]);
  }
  REQUIRE(faces.size() == 2);
  Index b = kNone;
  for (Index x : L.face(faces[0]))
    if (x != a && corner_of(L, faces[1], x) >= 0) b = x;
  REQUIRE(b != kNone);
  return {faces[0], on_edge(L, faces[0], a, b, 1.0 / 3)};
}

// The largest distance between the limits two faces give at the same point of their shared
// edge, at fractions `ts` along every (not thinned-out) interior edge.
inline double worst_edge_gap(const LimitSurface& s, const Level& L, const std::vector<double>& P,
                             std::initializer_list<double> ts) {
  double worst = 0;
  for (Index e = 0; e < L.edge_count(); ++e) {
    if (subdiv_test::thinned_out(e) || L.edge_on_boundary(e)) continue;
    const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
    const Index f0 = L.edge_faces[size_t(2 * e)], f1 = L.edge_faces[size_t(2 * e + 1)];
    for (double x : ts) {
      const auto u0 = on_edge(L, f0, a, b, x), u1 = on_edge(L, f1, a, b, x);
      worst = std::max(worst, distance(s.evaluate(f0, u0[0], u0[1], P, 3, 0).position,
                                       s.evaluate(f1, u1[0], u1[1], P, 3, 0).position));
    }
  }
  return worst;
}

}  // namespace subdiv::limit_test::sqrt3
