// Direct child topology of the sqrt3 split when every edge is flipped (sqrt3_topology.h),
// numbered as build_level (topology/level_manifold.cpp) numbers it: an edge belongs to the
// lower of its two corners, edges are numbered in the order of those corners, and every
// ring (all interior) starts at its vertex's lowest corner.
//
// Write T(e, v) for the child face of edge e at its end v: (v, P(in), P(out)), "in" being
// the face that runs e into v and "out" the one that runs it out of v (at a: f1 and f0).
// Its corner k is child corner 3T + k. Its middle edge is e's flipped edge, owned by face
// 2e. Its other two edges are spokes: the spoke from v to the point of face g, g holding v
// at parent corner c, is corner 0 of T(edge g runs into v, v) and corner 2 of T(edge g runs
// out of v, v). Around parent vertex v (valence n) the child faces are T(ring edge i, v),
// CCW in ring order; around face point P(f) of f = (v0, v1, v2) with edges e_k = v_k -> v_k+1
// they are T(e0, v0), T(e0, v1), T(e1, v1), T(e1, v2), T(e2, v2), T(e2, v0).
#include "framework/refine/sqrt3_topology.h"

#include <algorithm>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/util/bulk_memory.h"
#include "framework/util/parallel_ranges.h"

namespace subdiv {
namespace {

constexpr Index kGrain = 1 << 13;

// The corner of triangle f at vertex v.
inline Index corner_of(const Level& P, Index f, Index v) {
  const Index o = 3 * f;
  return P.face_vertices[o] == v ? o : P.face_vertices[o + 1] == v ? o + 1 : o + 2;
}
inline Index prev3(Index c) { return c % 3 == 0 ? c + 2 : c - 1; }

// The child face of edge e at its end v.
inline Index face_at(const Level& P, Index e, Index v) { return 2 * e + (P.edge_vertices[2 * e] == v ? 0 : 1); }

// The two child faces holding the spoke of parent corner c (vertex v in face g): the one
// where it runs v -> P(g) (corner 0) and the one where it runs back (corner 2).
struct Spoke {
  Index out_face, back_face;
};
inline Spoke spoke(const Level& P, Index c) {
  const Index v = P.face_vertices[c];
  return {face_at(P, P.face_edges[prev3(c)], v), face_at(P, P.face_edges[c], v)};
}

}  // namespace

bool sqrt3_flips_every_edge(const Level& P) {
  if (!P.manifold() || !P.all_faces_have_size(3)) return false;
  for (Index e = 0; e < P.edge_count(); ++e)
    if (P.edge_on_boundary(e) || P.edge_sharp(e) > 0.f) return false;
  for (Index v = 0; v < P.vertex_count; ++v)
    if (P.incident_face_count(v) > 0 && P.incident_face_count(v) < 3) return false;
  return true;
}

Level sqrt3_flip_topology(const Level& P, bool full, ScratchVector<Index>* parent_face) {
  const Index V = P.vertex_count, E = P.edge_count(), F = P.face_count();
  Level C;
  C.vertex_count = V + F;
  resize_bulk(C.face_offsets, 2 * size_t(E) + 1);
  resize_bulk(C.face_vertices, 6 * size_t(E));
  resize_bulk(*parent_face, 2 * size_t(E));
  parallel_ranges(E, kGrain, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e) {
      const Index a = P.edge_vertices[2 * e], b = P.edge_vertices[2 * e + 1];
      const Index f0 = P.edge_faces[2 * e], f1 = P.edge_faces[2 * e + 1];
      Index* fv = &C.face_vertices[6 * size_t(e)];
      fv[0] = a, fv[1] = V + f1, fv[2] = V + f0, fv[3] = b, fv[4] = V + f0, fv[5] = V + f1;
      C.face_offsets[2 * e + 1] = 6 * e + 3, C.face_offsets[2 * e + 2] = 6 * e + 6;
      (*parent_face)[2 * e] = f0, (*parent_face)[2 * e + 1] = f1;
    }
  });
  C.face_offsets[0] = 0;
  if (!full) return C;

  // Edges: per parent edge, the owners among its six child corners, counted per chunk,
  // summed in chunk order, then numbered. Spokes are kept per parent corner, flips per edge.
  std::vector<Index> spoke_edge, flip_edge;
  resize_bulk(spoke_edge, 3 * size_t(F));
  resize_bulk(flip_edge, size_t(E));
  // The spokes at corners 0 and 2 of edge e's faces: face 2e (at a) runs a -> P(f1) and
  // P(f0) -> a, face 2e+1 (at b) b -> P(f0) and P(f1) -> b.
  auto corner_spokes = [&](Index e, Index (&c)[4]) {
    const Index a = P.edge_vertices[2 * e], b = P.edge_vertices[2 * e + 1];
    const Index f0 = P.edge_faces[2 * e], f1 = P.edge_faces[2 * e + 1];
    c[0] = corner_of(P, f1, a), c[1] = corner_of(P, f0, a), c[2] = corner_of(P, f0, b), c[3] = corner_of(P, f1, b);
  };
  // A spoke's two corners are 0 of one face and 2 of another: the lower face owns it.
  const Index chunks = (E + kGrain - 1) / kGrain;
  std::vector<Index> first_edge(size_t(chunks) + 1, 0);
  auto owners = [&](Index e, bool (&own)[4]) {
    Index c[4];
    corner_spokes(e, c);
    for (int i = 0; i < 4; ++i) {
      const Spoke s = spoke(P, c[i]);
      own[i] = i % 2 == 0 ? s.out_face < s.back_face : s.back_face < s.out_face;
    }
  };
  tbb::parallel_for(Index(0), chunks, [&](Index chunk) {
    Index owned = 0;
    bool own[4];
    for (Index e = chunk * kGrain; e < std::min(E, (chunk + 1) * kGrain); ++e) {
      owners(e, own);
      owned += 1 + own[0] + own[1] + own[2] + own[3];
    }
    first_edge[chunk + 1] = owned;
  });
  for (Index chunk = 0; chunk < chunks; ++chunk) first_edge[chunk + 1] += first_edge[chunk];
  const Index child_edges = first_edge.back();
  resize_bulk(C.edge_vertices, 2 * size_t(child_edges));
  resize_bulk(C.edge_faces, 2 * size_t(child_edges));
  tbb::parallel_for(Index(0), chunks, [&](Index chunk) {
    Index id = first_edge[chunk];
    bool own[4];
    Index c[4];
    auto add_spoke = [&](Index corner) {
      const Spoke s = spoke(P, corner);
      const Index v = P.face_vertices[corner], g = V + corner / 3;
      const bool out_owns = s.out_face < s.back_face;
      spoke_edge[corner] = id;
      C.edge_vertices[2 * id] = out_owns ? v : g, C.edge_vertices[2 * id + 1] = out_owns ? g : v;
      C.edge_faces[2 * id] = out_owns ? s.out_face : s.back_face, C.edge_faces[2 * id + 1] = out_owns ? s.back_face : s.out_face;
      ++id;
    };
    for (Index e = chunk * kGrain; e < std::min(E, (chunk + 1) * kGrain); ++e) {
      owners(e, own);
      corner_spokes(e, c);
      // Child corners 6e .. 6e+5 in order: spoke, flip, spoke; spoke, (flip again), spoke.
      if (own[0]) add_spoke(c[0]);
      flip_edge[e] = id;
      C.edge_vertices[2 * id] = V + P.edge_faces[2 * e + 1], C.edge_vertices[2 * id + 1] = V + P.edge_faces[2 * e];
      C.edge_faces[2 * id] = 2 * e, C.edge_faces[2 * id + 1] = 2 * e + 1;
      ++id;
      if (own[1]) add_spoke(c[1]);
      if (own[2]) add_spoke(c[2]);
      if (own[3]) add_spoke(c[3]);
    }
  });
  resize_bulk(C.face_edges, 6 * size_t(E));
  parallel_ranges(E, kGrain, [&](Index begin, Index end) {
    Index c[4];
    for (Index e = begin; e < end; ++e) {
      corner_spokes(e, c);
      Index* fe = &C.face_edges[6 * size_t(e)];
      fe[0] = spoke_edge[c[0]], fe[1] = flip_edge[e], fe[2] = spoke_edge[c[1]];
      fe[3] = spoke_edge[c[2]], fe[4] = flip_edge[e], fe[5] = spoke_edge[c[3]];
    }
  });

  // Rings: parent vertices keep their ring sizes; face points have six.
  const Index parent_ring = P.vertex_face_offsets[V];
  resize_bulk(C.vertex_face_offsets, size_t(V + F) + 1);
  std::copy(P.vertex_face_offsets.begin(), P.vertex_face_offsets.end(), C.vertex_face_offsets.begin());
  parallel_ranges(F, kGrain, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) C.vertex_face_offsets[V + f + 1] = parent_ring + 6 * (f + 1);
  });
  C.vertex_ring_offsets = C.vertex_face_offsets;  // closed: as many ring edges as faces
  const size_t slots = size_t(C.vertex_face_offsets.back());
  resize_bulk(C.vertex_faces, slots);
  resize_bulk(C.vertex_face_corner, slots);
  resize_bulk(C.vertex_edges, slots);
  assign_bulk(C.vertex_on_boundary, size_t(V + F), std::uint8_t(0));
  parallel_ranges(V, kGrain, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) {
      const Index o = P.vertex_face_offsets[v], n = P.vertex_face_offsets[v + 1] - o;
      if (n == 0) continue;
      const Index* ring = &P.vertex_edges[P.vertex_ring_offsets[v]];
      Index start = 0;
      for (Index i = 1; i < n; ++i)
        if (face_at(P, ring[i], v) < face_at(P, ring[start], v)) start = i;
      for (Index k = 0; k < n; ++k) {
        const Index i = (start + k) % n, before = (i + n - 1) % n;  // ring face i-1 holds T_i's out spoke
        C.vertex_faces[o + k] = face_at(P, ring[i], v);
        C.vertex_face_corner[o + k] = 0;
        C.vertex_edges[o + k] = spoke_edge[P.face_offsets[P.vertex_faces[o + before]] + P.vertex_face_corner[o + before]];
      }
    }
  });
  parallel_ranges(F, kGrain, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) {
      Index face[6], corner[6], edge[6];
      for (int k = 0; k < 3; ++k) {
        const Index c = 3 * f + k, e = P.face_edges[c];
        const Index from = P.face_vertices[c], to = P.face_vertices[3 * f + (k + 1) % 3];
        face[2 * k] = face_at(P, e, from), corner[2 * k] = 2, edge[2 * k] = spoke_edge[c];
        face[2 * k + 1] = face_at(P, e, to), corner[2 * k + 1] = 1, edge[2 * k + 1] = flip_edge[e];
      }
      const int start = int(std::min_element(face, face + 6) - face);
      const Index o = C.vertex_face_offsets[V + f];
      for (int k = 0; k < 6; ++k) {
        const int i = (start + k) % 6;
        C.vertex_faces[o + k] = face[i], C.vertex_face_corner[o + k] = LocalIndex(corner[i]), C.vertex_edges[o + k] = edge[i];
      }
    }
  });
  return C;
}

}  // namespace subdiv
