#include "framework/refine/primal_topology.h"
#include "framework/util/resize_side_by_side.h"
#include "framework/util/streaming_stores.h"

#include <cstdint>

#include <algorithm>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace subdiv {
namespace {

// The child half of parent edge e that touches its end v.
inline Index half_at(const Level& P, Index e, Index v) { return 2 * e + (P.edge_vertices[2 * e] == v ? 0 : 1); }
// The same for an edge that enters v in a face. They differ only on an edge from a vertex to
// itself (a face that repeats a vertex): the face leaves along its first half and comes back
// along its second, as in OpenSubdiv's Vtr::QuadRefinement.
inline Index half_in(const Level& P, Index e, Index v) { return 2 * e + (P.edge_vertices[2 * e + 1] == v ? 1 : 0); }

// The child of a non-manifold level. OpenSubdiv's Vtr::Refinement passes the marks down
// (the halves of a non-manifold edge, the child of a non-manifold vertex and the new point
// of a non-manifold edge are non-manifold); the general builder does the rest.
void complete_non_manifold_child(const Level& P, Level& C) {
  C.edge_non_manifold.assign(C.edge_count(), 0);
  C.vertex_non_manifold.assign(C.vertex_count, 0);
  for (Index e = 0; e < P.edge_count(); ++e)
    if (P.non_manifold_edge(e)) C.edge_non_manifold[2 * e] = C.edge_non_manifold[2 * e + 1] = C.vertex_non_manifold[P.vertex_count + e] = 1;
  for (Index v = 0; v < P.vertex_count; ++v) C.vertex_non_manifold[v] = P.non_manifold_vertex(v);
  complete_general_level(C);
}

// Corner index (within face f) of vertex v.
inline int local_corner(const Level& P, Index f, Index v) {
  const Index* fv = P.face_vertices.data() + P.face_offsets[f];
  int i = 0;
  while (fv[i] != v) ++i;
  return i;
}

// The parts shared by both splits: child vertices of parent vertices keep their rings,
// with ring face i replaced by the child face at that corner and ring edges by halves.
template <class ChildFaceAtCorner>
void vertex_child_rings(const Level& P, Level& C, ChildFaceAtCorner child_face) {
  tbb::parallel_for(Index(0), P.vertex_count, [&](Index v) {
    const Index fo = P.vertex_face_offsets[v], ro = P.vertex_ring_offsets[v];
    for (Index i = fo; i < P.vertex_face_offsets[v + 1]; ++i) {
      C.vertex_faces[i] = child_face(P.vertex_faces[i], P.vertex_face_corner[i]);
      C.vertex_face_corner[i] = 0;
    }
    for (Index i = ro; i < P.vertex_ring_offsets[v + 1]; ++i) C.vertex_edges[i] = half_at(P, P.vertex_edges[i], v);
    C.vertex_on_boundary[v] = P.vertex_on_boundary[v];
  });
}

// Ring offsets of the child level and its ring arrays, sized. Vertex children keep their
// parents' rings; an edge child has ring faces and edges as given, interior or on the
// boundary; the child of face f (quad split) has a ring face and edge per corner of f. The offsets are closed forms of the boundary edges counted before each edge
// (a parallel scan), so no stage runs over the edges or faces alone, and the arrays' zero-
// fills run side by side.
struct EdgeChildRing {
  Index faces, edges;                    // of an interior edge's child
  Index boundary_faces, boundary_edges;  // of a boundary edge's child
};
void child_ring_offsets(const Level& P, Level& C, EdgeChildRing ring, bool face_children) {
  const Index V = P.vertex_count, E = P.edge_count(), F = P.face_count();
  resize_side_by_side(Sized{C.vertex_face_offsets, size_t(C.vertex_count) + 1},
                      Sized{C.vertex_ring_offsets, size_t(C.vertex_count) + 1});
  tbb::parallel_for(tbb::blocked_range<Index>(0, V + 1, 1 << 14), [&](const tbb::blocked_range<Index>& r) {
    for (Index v = r.begin(); v < r.end(); ++v) {
      C.vertex_face_offsets[v] = P.vertex_face_offsets[v];
      C.vertex_ring_offsets[v] = P.vertex_ring_offsets[v];
    }
  });
  const Index face_base = P.vertex_face_offsets[V], ring_base = P.vertex_ring_offsets[V];
  // Boundary edges counted per block of edges, the counts summed in block order, then each
  // block writes its offsets (a two-pass scan; the same for any thread count).
  constexpr Index kBlock = 1 << 16;
  const Index blocks = (E + kBlock - 1) / kBlock;
  std::vector<Index> boundary_before(size_t(blocks) + 1, 0);
  const Index* edge_face = P.edge_faces.data();
  tbb::parallel_for(Index(0), blocks, [&](Index b) {
    Index boundary = 0;
    for (Index e = b * kBlock, end = std::min(E, e + kBlock); e < end; ++e) boundary += edge_face[2 * e + 1] == kNone;
    boundary_before[b + 1] = boundary;
  });
  for (Index b = 0; b < blocks; ++b) boundary_before[b + 1] += boundary_before[b];
  tbb::parallel_for(Index(0), blocks, [&](Index b) {
    Index* face_offset = C.vertex_face_offsets.data() + V + 1;
    Index* ring_offset = C.vertex_ring_offsets.data() + V + 1;
    Index boundary = boundary_before[b];  // boundary edges up to e
    for (Index e = b * kBlock, end = std::min(E, e + kBlock); e < end; ++e) {
      boundary += edge_face[2 * e + 1] == kNone;
      face_offset[e] = face_base + ring.faces * (e + 1) - (ring.faces - ring.boundary_faces) * boundary;
      ring_offset[e] = ring_base + ring.edges * (e + 1) - (ring.edges - ring.boundary_edges) * boundary;
    }
  });
  if (face_children) {
    const Index face_start = C.vertex_face_offsets[V + E], ring_start = C.vertex_ring_offsets[V + E];
    tbb::parallel_for(tbb::blocked_range<Index>(0, F, 1 << 14), [&](const tbb::blocked_range<Index>& r) {
      for (Index f = r.begin(); f < r.end(); ++f) {
        C.vertex_face_offsets[V + E + f + 1] = face_start + P.face_offsets[f + 1];
        C.vertex_ring_offsets[V + E + f + 1] = ring_start + P.face_offsets[f + 1];
      }
    });
  }
  resize_side_by_side(Sized{C.vertex_faces, size_t(C.vertex_face_offsets.back())},
                      Sized{C.vertex_face_corner, size_t(C.vertex_face_offsets.back())},
                      Sized{C.vertex_edges, size_t(C.vertex_ring_offsets.back())},
                      Sized{C.vertex_on_boundary, size_t(C.vertex_count)});
}

void halves(const Level& P, Level& C, Index first_mid) {
  tbb::parallel_for(Index(0), P.edge_count(), [&](Index e) {
    const Index a = P.edge_vertices[2 * e], b = P.edge_vertices[2 * e + 1], m = first_mid + e;
    C.edge_vertices[4 * e + 0] = a, C.edge_vertices[4 * e + 1] = m;
    C.edge_vertices[4 * e + 2] = m, C.edge_vertices[4 * e + 3] = b;
  });
}

}  // namespace

namespace {

// Whether a faces-only last level's corners are written with streaming stores: when they
// are larger than the caches (so nothing would find them there) and 16-byte aligned.
bool streams(const ScratchVector<Index>& face_vertices) {
  return face_vertices.size() * sizeof(Index) >= (size_t(32) << 20) && streaming_stores_wanted() &&
         reinterpret_cast<std::uintptr_t>(face_vertices.data()) % 16 == 0;
}

// Child faces (and, with `edges`, their edges and the edges inside parent faces): child
// face c = (v_i, mid(e_i), face point, mid(e_{i-1})) of parent corner c.
template <bool edges>
Level quad_children(const Level& P) {
  const Index V = P.vertex_count, E = P.edge_count(), F = P.face_count(), N = P.corner_count();
  Level C;
  C.vertex_count = V + E + F;
  if (edges)
    resize_side_by_side(Sized{C.face_offsets, size_t(N) + 1}, Sized{C.face_vertices, 4 * size_t(N)},
                        Sized{C.face_edges, 4 * size_t(N)}, Sized{C.edge_vertices, 2 * size_t(2 * E + N)},
                        Sized{C.edge_faces, 2 * size_t(2 * E + N)});
  else
    resize_side_by_side(Sized{C.face_offsets, size_t(N) + 1}, Sized{C.face_vertices, 4 * size_t(N)});
  // Faces only: the last level, which nothing reads during the refinement, written with
  // streaming stores (util/streaming_stores.h) when its rows of four are 16-byte aligned.
  const bool stream = !edges && streams(C.face_vertices);
  tbb::parallel_for(tbb::blocked_range<Index>(0, F), [&](const tbb::blocked_range<Index>& faces) {
    for (Index f = faces.begin(); f < faces.end(); ++f) {
      const Index o = P.face_offsets[f], k = P.face_size(f);
      for (Index i = 0; i < k; ++i) {
        const Index c = o + i, prev = o + (i + k - 1) % k, next = o + (i + 1) % k;
        const Index v = P.face_vertices[c], e = P.face_edges[c], ep = P.face_edges[prev];
        Index* fv = &C.face_vertices[4 * size_t(c)];
        if (stream) {
          stream_store4(fv, v, V + e, V + E + f, V + ep);
          stream_store(&C.face_offsets[c + 1], 4 * (c + 1));
          continue;
        }
        fv[0] = v, fv[1] = V + e, fv[2] = V + E + f, fv[3] = V + ep;
        C.face_offsets[c + 1] = 4 * (c + 1);
        if (!edges) continue;
        Index* fe = &C.face_edges[4 * size_t(c)];
        fe[0] = half_at(P, e, v), fe[1] = 2 * E + c, fe[2] = 2 * E + prev, fe[3] = half_in(P, ep, v);
        // Inner edge of corner c: mid(e_i) -> face point; its reverse lies in the next corner's face.
        C.edge_vertices[2 * (2 * size_t(E) + c)] = V + e, C.edge_vertices[2 * (2 * size_t(E) + c) + 1] = V + E + f;
        C.edge_faces[2 * (2 * size_t(E) + c)] = c, C.edge_faces[2 * (2 * size_t(E) + c) + 1] = next;
      }
    }
    if (stream) streaming_fence();
  });
  C.face_offsets[0] = 0;
  return C;
}

}  // namespace

Level quad_split_topology(const Level& P) {
  const Index V = P.vertex_count, E = P.edge_count(), F = P.face_count();
  Level C = quad_children<true>(P);
  halves(P, C, V);
  if (!P.manifold()) {
    complete_non_manifold_child(P, C);
    return C;
  }
  // Halves' faces: 2e (a -> mid) runs forward in f0's face at a, backwards in f1's face at a.
  tbb::parallel_for(Index(0), E, [&](Index e) {
    const Index a = P.edge_vertices[2 * e], b = P.edge_vertices[2 * e + 1];
    const Index f0 = P.edge_faces[2 * e], f1 = P.edge_faces[2 * e + 1];
    C.edge_faces[4 * e + 0] = P.face_offsets[f0] + local_corner(P, f0, a);
    C.edge_faces[4 * e + 2] = P.face_offsets[f0] + local_corner(P, f0, b);
    C.edge_faces[4 * e + 1] = f1 == kNone ? kNone : P.face_offsets[f1] + local_corner(P, f1, a);
    C.edge_faces[4 * e + 3] = f1 == kNone ? kNone : P.face_offsets[f1] + local_corner(P, f1, b);
  });
  // Rings: vertex children as their parents; edge children have 4 faces (2 on a boundary);
  // face children have one per corner.
  child_ring_offsets(P, C, {4, 4, 2, 3}, true);
  vertex_child_rings(P, C, [&](Index f, int corner) { return P.face_offsets[f] + corner; });
  tbb::parallel_for(Index(0), E, [&](Index e) {
    const Index a = P.edge_vertices[2 * e], b = P.edge_vertices[2 * e + 1];
    const Index f0 = P.edge_faces[2 * e], f1 = P.edge_faces[2 * e + 1];
    const Index c_a0 = P.face_offsets[f0] + local_corner(P, f0, a), c_b0 = P.face_offsets[f0] + local_corner(P, f0, b);
    Index* rf = &C.vertex_faces[C.vertex_face_offsets[V + e]];
    LocalIndex* rc = &C.vertex_face_corner[C.vertex_face_offsets[V + e]];
    Index* re = &C.vertex_edges[C.vertex_ring_offsets[V + e]];
    if (f1 == kNone) {
      // Starts on the boundary half towards b, ends on the half towards a.
      rf[0] = c_b0, rf[1] = c_a0;
      rc[0] = 3, rc[1] = 1;
      re[0] = 2 * e + 1, re[1] = 2 * E + c_a0, re[2] = 2 * e;
      C.vertex_on_boundary[V + e] = 1;
      return;
    }
    C.vertex_on_boundary[V + e] = 0;
    const Index c_a1 = P.face_offsets[f1] + local_corner(P, f1, a), c_b1 = P.face_offsets[f1] + local_corner(P, f1, b);
    rf[0] = c_a0, rf[1] = c_a1, rf[2] = c_b1, rf[3] = c_b0;
    rc[0] = 1, rc[1] = 3, rc[2] = 1, rc[3] = 3;
    re[0] = 2 * E + c_a0, re[1] = 2 * e, re[2] = 2 * E + c_b1, re[3] = 2 * e + 1;
  });
  tbb::parallel_for(Index(0), F, [&](Index f) {
    const Index o = P.face_offsets[f], k = P.face_size(f);
    Index* rf = &C.vertex_faces[C.vertex_face_offsets[V + E + f]];
    LocalIndex* rc = &C.vertex_face_corner[C.vertex_face_offsets[V + E + f]];
    Index* re = &C.vertex_edges[C.vertex_ring_offsets[V + E + f]];
    for (Index i = 0; i < k; ++i) rf[i] = o + i, rc[i] = 2, re[i] = 2 * E + o + (i + k - 1) % k;
    C.vertex_on_boundary[V + E + f] = 0;
  });
  return C;
}

namespace {

// Child faces (and, with `edges`, their edges and the edges inside parent faces): corner
// face 4f+i = (v_i, mid e_i, mid e_{i-1}); middle face 4f+3 = (mid e_0, mid e_1, mid e_2).
// Inner edge 2E+3f+i runs mid e_i -> mid e_{i-1}: forward in corner face i, backwards in the middle.
template <bool edges>
Level triangle_children(const Level& P) {
  const Index V = P.vertex_count, E = P.edge_count(), F = P.face_count();
  Level C;
  C.vertex_count = V + E;
  if (edges)
    resize_side_by_side(Sized{C.face_offsets, 4 * size_t(F) + 1}, Sized{C.face_vertices, 12 * size_t(F)},
                        Sized{C.face_edges, 12 * size_t(F)}, Sized{C.edge_vertices, 2 * size_t(2 * E + 3 * F)},
                        Sized{C.edge_faces, 2 * size_t(2 * E + 3 * F)});
  else
    resize_side_by_side(Sized{C.face_offsets, 4 * size_t(F) + 1}, Sized{C.face_vertices, 12 * size_t(F)});
  // Faces only: the last level, written with streaming stores (as quad_children) when a
  // face's 12 corners are 16-byte aligned.
  const bool stream = !edges && streams(C.face_vertices);
  tbb::parallel_for(tbb::blocked_range<Index>(0, F), [&](const tbb::blocked_range<Index>& faces) {
    for (Index f = faces.begin(); f < faces.end(); ++f) {
      const Index o = P.face_offsets[f];
      if (stream) {
        // Corner faces (v_i, mid e_i, mid e_{i-1}), then the middle face (mid e_0, mid e_1, mid e_2).
        const Index* pv = P.face_vertices.data() + o;
        const Index m0 = V + P.face_edges[o], m1 = V + P.face_edges[o + 1], m2 = V + P.face_edges[o + 2];
        Index* fv = &C.face_vertices[12 * size_t(f)];
        stream_store4(fv, pv[0], m0, m2, pv[1]);
        stream_store4(fv + 4, m1, m0, pv[2], m2);
        stream_store4(fv + 8, m1, m0, m1, m2);
        for (int t = 0; t < 4; ++t) stream_store(&C.face_offsets[4 * f + t + 1], 3 * (4 * f + t + 1));
        continue;
      }
      for (int i = 0; i < 3; ++i) {
        const int ip = (i + 2) % 3;
        const Index v = P.face_vertices[o + i], e = P.face_edges[o + i], ep = P.face_edges[o + ip];
        const Index cf = 4 * f + i, inner = 2 * E + 3 * f + i;
        Index* fv = &C.face_vertices[3 * size_t(cf)];
        fv[0] = v, fv[1] = V + e, fv[2] = V + ep;
        C.face_vertices[3 * size_t(4 * f + 3) + i] = V + e;
        if (!edges) continue;
        Index* fe = &C.face_edges[3 * size_t(cf)];
        fe[0] = half_at(P, e, v), fe[1] = inner, fe[2] = half_in(P, ep, v);
        C.face_edges[3 * size_t(4 * f + 3) + i] = 2 * E + 3 * f + (i + 1) % 3;
        C.edge_vertices[2 * size_t(inner)] = V + e, C.edge_vertices[2 * size_t(inner) + 1] = V + ep;
        C.edge_faces[2 * size_t(inner)] = cf, C.edge_faces[2 * size_t(inner) + 1] = 4 * f + 3;
      }
      for (int t = 0; t < 4; ++t) C.face_offsets[4 * f + t + 1] = 3 * (4 * f + t + 1);
    }
    if (stream) streaming_fence();
  });
  C.face_offsets[0] = 0;
  return C;
}

}  // namespace

Level triangle_split_topology(const Level& P) {
  const Index V = P.vertex_count, E = P.edge_count();
  Level C = triangle_children<true>(P);
  halves(P, C, V);
  if (!P.manifold()) {
    complete_non_manifold_child(P, C);
    return C;
  }
  tbb::parallel_for(Index(0), E, [&](Index e) {
    const Index a = P.edge_vertices[2 * e], b = P.edge_vertices[2 * e + 1];
    const Index f0 = P.edge_faces[2 * e], f1 = P.edge_faces[2 * e + 1];
    C.edge_faces[4 * e + 0] = 4 * f0 + local_corner(P, f0, a);
    C.edge_faces[4 * e + 2] = 4 * f0 + local_corner(P, f0, b);
    C.edge_faces[4 * e + 1] = f1 == kNone ? kNone : 4 * f1 + local_corner(P, f1, a);
    C.edge_faces[4 * e + 3] = f1 == kNone ? kNone : 4 * f1 + local_corner(P, f1, b);
  });
  child_ring_offsets(P, C, {6, 6, 3, 4}, false);
  vertex_child_rings(P, C, [&](Index f, int corner) { return 4 * f + corner; });
  tbb::parallel_for(Index(0), E, [&](Index e) {
    const Index a = P.edge_vertices[2 * e], b = P.edge_vertices[2 * e + 1];
    const Index f0 = P.edge_faces[2 * e], f1 = P.edge_faces[2 * e + 1];
    const int ia0 = local_corner(P, f0, a), ib0 = local_corner(P, f0, b);
    Index* rf = &C.vertex_faces[C.vertex_face_offsets[V + e]];
    LocalIndex* rc = &C.vertex_face_corner[C.vertex_face_offsets[V + e]];
    Index* re = &C.vertex_edges[C.vertex_ring_offsets[V + e]];
    const Index in0 = 2 * E + 3 * f0;
    if (f1 == kNone) {
      rf[0] = 4 * f0 + ib0, rf[1] = 4 * f0 + 3, rf[2] = 4 * f0 + ia0;
      rc[0] = 2, rc[1] = LocalIndex(ia0), rc[2] = 1;
      re[0] = 2 * e + 1, re[1] = in0 + ib0, re[2] = in0 + ia0, re[3] = 2 * e;
      C.vertex_on_boundary[V + e] = 1;
      return;
    }
    C.vertex_on_boundary[V + e] = 0;
    const int ia1 = local_corner(P, f1, a), ib1 = local_corner(P, f1, b);
    const Index in1 = 2 * E + 3 * f1;
    rf[0] = 4 * f0 + ia0, rf[1] = 4 * f1 + ia1, rf[2] = 4 * f1 + 3, rf[3] = 4 * f1 + ib1, rf[4] = 4 * f0 + ib0, rf[5] = 4 * f0 + 3;
    rc[0] = 1, rc[1] = 2, rc[2] = LocalIndex(ib1), rc[3] = 1, rc[4] = 2, rc[5] = LocalIndex(ia0);
    re[0] = in0 + ia0, re[1] = 2 * e, re[2] = in1 + ia1, re[3] = in1 + ib1, re[4] = 2 * e + 1, re[5] = in0 + ib0;
  });
  return C;
}

Level quad_split_faces(const Level& P) { return quad_children<false>(P); }
Level triangle_split_faces(const Level& P) { return triangle_children<false>(P); }

}  // namespace subdiv
