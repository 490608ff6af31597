// Direct child topology of the dual splits (dual_topology.h). Every child edge and ring
// follows from the parent's arrays, numbered as build_level (topology/level_manifold.cpp)
// numbers them: an edge belongs to the lower of its two corners and edges are numbered in
// the order of those corners; an interior vertex's ring starts at its lowest corner, a
// boundary vertex's at the corner that leaves along the boundary.
//
// Doo-Sabin. F-face corner c is child vertex c, so its edge c -> next(c) (along the parent
// edge of corner c) is edge c: its twin lies in an E-face, which comes later. E-face k of
// edge a -> b (f0 left, f1 right) is (f1@a, f1@b, f0@b, f0@a): corners 0 and 2 are twins
// of F-face edges, corners 1 and 3 cross b and a towards the V-faces and own edges N+2k and
// N+2k+1. V-face corner j (ring face j's corner) crosses ring edge j+1 towards the E-face
// there; only a boundary V-face's closing edge (its last corner) is its own. Around child
// vertex c (parent vertex v in face f) the faces run, CCW: F(f), the E-face of f's edge
// into v, the V-face of v, the E-face of f's edge out of v; missing ones leave a gap where
// the ring starts.
//
// Mid-edge. F-face corner c is child vertex face_edges[c]; its edge to the next corner's
// crosses the parent vertex between them, towards that vertex's V-face (ring edges CCW), so
// again edge c is corner c's. Around child vertex e (a -> b) the faces run, CCW: F(f0), the
// V-face of a, F(f1), the V-face of b.
#include "framework/refine/dual_topology.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/util/bulk_memory.h"
#include "framework/util/parallel_ranges.h"

namespace subdiv {
namespace {

constexpr Index kGrain = 1 << 13;

// Faces by parent face, with the face in hand (corners of face f run off[f] .. off[f+1]).
template <class Body>
void for_faces(const Level& L, Body body) {
  parallel_ranges(L.face_count(), kGrain, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) body(f);
  });
}

inline Index next_in(const Level& L, Index f, Index c) { return c + 1 == L.face_offsets[f + 1] ? L.face_offsets[f] : c + 1; }
inline Index prev_in(const Level& L, Index f, Index c) { return c == L.face_offsets[f] ? L.face_offsets[f + 1] - 1 : c - 1; }

// The first corner of v in f.
inline Index corner_of(const Level& L, Index f, Index v) {
  Index c = L.face_offsets[f];
  while (L.face_vertices[c] != v) ++c;
  return c;
}

// The corner of f whose edge is e (f runs e out of that corner).
inline Index corner_of_edge(const Level& L, Index f, Index e) {
  Index c = L.face_offsets[f];
  while (L.face_edges[c] != e) ++c;
  return c;
}

// Which parent elements get a face, and where their faces, corners and closing edges go
// (a serial pass: the ranks are prefix counts).
struct DualPlan {
  std::vector<Index> edge_face;    // per edge: rank among E-faces, or kNone
  std::vector<Index> vertex_face;  // per vertex: rank among V-faces, or kNone
  std::vector<Index> vertex_base;  // per vertex with a V-face: its first corner within the V-face block
  std::vector<Index> closing;      // per boundary vertex with a V-face: rank of its closing edge, else kNone
  Index e_faces = 0, v_faces = 0, v_corners = 0, closings = 0;
  bool direct = true;  // whether the full level can be built directly
};

// `cycle(v)`: the number of corners of v's V-face (its faces, or its ring edges).
template <class Cycle>
DualPlan plan(const Level& L, bool edge_faces, Cycle cycle, DualSkipped* skipped) {
  DualPlan p;
  p.direct = L.manifold();
  if (edge_faces) {
    resize_bulk(p.edge_face, size_t(L.edge_count()));
    for (Index e = 0; e < L.edge_count(); ++e) {
      p.edge_face[e] = kNone;
      if (L.edge_on_boundary(e)) continue;
      if (L.non_manifold_edge(e)) {
        ++skipped->edges;
        continue;
      }
      p.edge_face[e] = p.e_faces++;
    }
  }
  resize_bulk(p.vertex_face, size_t(L.vertex_count));
  resize_bulk(p.vertex_base, size_t(L.vertex_count));
  resize_bulk(p.closing, size_t(L.vertex_count));
  for (Index v = 0; v < L.vertex_count; ++v) {
    p.vertex_face[v] = p.vertex_base[v] = p.closing[v] = kNone;
    if (L.non_manifold_vertex(v)) {
      ++skipped->vertices;
      continue;
    }
    const Index n = cycle(v);
    if (!L.on_boundary(v) && L.incident_face_count(v) > 0 && L.incident_face_count(v) < 3) p.direct = false;
    if (n < 3) continue;
    p.vertex_face[v] = p.v_faces++;
    p.vertex_base[v] = p.v_corners;
    p.v_corners += n;
    if (L.on_boundary(v)) p.closing[v] = p.closings++;
  }
  return p;
}

// Child faces: F-faces with the parent's offsets (corner c holds `f_corner(c)`), then E-faces
// (dual), then V-faces (corner j of v's holds `v_corner(v, j)`).
template <class FCorner, class VCorner>
Level child_faces(const Level& L, const DualPlan& p, Index vertex_count, FCorner f_corner, VCorner v_corner,
                  const std::vector<Index>& cycle_size) {
  const Index F = L.face_count(), N = L.corner_count(), EF = p.e_faces;
  Level C;
  C.vertex_count = vertex_count;
  resize_bulk(C.face_offsets, size_t(F + EF + p.v_faces) + 1);
  resize_bulk(C.face_vertices, size_t(N) + 4 * size_t(EF) + size_t(p.v_corners));
  C.face_offsets[0] = 0;
  for_faces(L, [&](Index f) {
    C.face_offsets[f + 1] = L.face_offsets[f + 1];
    for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c) C.face_vertices[c] = f_corner(c);
  });
  if (EF > 0)
    parallel_ranges(L.edge_count(), kGrain, [&](Index begin, Index end) {
      for (Index e = begin; e < end; ++e) {
        const Index k = p.edge_face[e];
        if (k == kNone) continue;
        // f0 lies left of a->b, so (f1@a, f1@b, f0@b, f0@a) runs CCW.
        const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
        const Index f0 = L.edge_faces[2 * e], f1 = L.edge_faces[2 * e + 1];
        Index* fv = &C.face_vertices[size_t(N) + 4 * size_t(k)];
        fv[0] = corner_of(L, f1, a), fv[1] = corner_of(L, f1, b), fv[2] = corner_of(L, f0, b), fv[3] = corner_of(L, f0, a);
        C.face_offsets[F + k + 1] = N + 4 * (k + 1);
      }
    });
  const Index v_block = N + 4 * EF;
  parallel_ranges(L.vertex_count, kGrain, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) {
      const Index m = p.vertex_face[v];
      if (m == kNone) continue;
      const Index base = v_block + p.vertex_base[v], n = cycle_size[v];
      for (Index j = 0; j < n; ++j) C.face_vertices[base + j] = v_corner(v, j);
      C.face_offsets[F + EF + m + 1] = base + n;
    }
  });
  return C;
}

// One face around a child vertex, in CCW order: the face, the child vertex's corner in it,
// the edge it leaves the vertex along, and whether the face exists.
struct RingSlot {
  Index face;
  Index corner;
  Index out;
  bool present;
};
using Ring4 = RingSlot[4];

int ring_faces(const Ring4& s) { return s[0].present + s[1].present + s[2].present + s[3].present; }

// Writes child vertex v's ring from its four slots (cyclic CCW), from `first` when all are
// present, else from the face after the gap; a boundary ring ends on the edge entering its
// last face, which is the next (missing) slot's out edge.
void write_ring(Level& C, Index v, const Ring4& s, int first) {
  const bool closed = ring_faces(s) == 4;
  int i = first;
  if (!closed)
    for (int j = 0; j < 4; ++j)
      if (s[j].present && !s[(j + 3) % 4].present) i = j;
  Index fo = C.vertex_face_offsets[v], ro = C.vertex_ring_offsets[v];
  for (int k = 0; k < 4 && s[i].present; ++k, i = (i + 1) % 4) {
    C.vertex_faces[fo] = s[i].face;
    C.vertex_face_corner[fo++] = LocalIndex(s[i].corner);
    C.vertex_edges[ro++] = s[i].out;
  }
  if (!closed) C.vertex_edges[ro] = s[i].out;
  C.vertex_on_boundary[v] = !closed;
}

// Ring offsets from each child vertex's slots (counted in parallel, summed in order), then
// the rings themselves. `slots(v, s)` fills v's four slots and returns where a closed ring starts.
template <class Slots>
void child_rings(Level& C, Slots slots) {
  const Index V = C.vertex_count;
  resize_bulk(C.vertex_face_offsets, size_t(V) + 1);
  resize_bulk(C.vertex_ring_offsets, size_t(V) + 1);
  resize_bulk(C.vertex_on_boundary, size_t(V));
  parallel_ranges(V, kGrain, [&](Index begin, Index end) {
    Ring4 s;
    for (Index v = begin; v < end; ++v) {
      slots(v, s);
      const int n = ring_faces(s);
      C.vertex_face_offsets[v + 1] = n;
      C.vertex_ring_offsets[v + 1] = n + (n < 4);
    }
  });
  C.vertex_face_offsets[0] = C.vertex_ring_offsets[0] = 0;
  for (Index v = 0; v < V; ++v) {
    C.vertex_face_offsets[v + 1] += C.vertex_face_offsets[v];
    C.vertex_ring_offsets[v + 1] += C.vertex_ring_offsets[v];
  }
  resize_bulk(C.vertex_faces, size_t(C.vertex_face_offsets[V]));
  resize_bulk(C.vertex_face_corner, size_t(C.vertex_face_offsets[V]));
  resize_bulk(C.vertex_edges, size_t(C.vertex_ring_offsets[V]));
  parallel_ranges(V, kGrain, [&](Index begin, Index end) {
    Ring4 s;
    for (Index v = begin; v < end; ++v) write_ring(C, v, s, slots(v, s));
  });
}

// Per parent corner: the place of its face in its vertex's ring.
std::vector<Index> ring_positions(const Level& L) {
  std::vector<Index> pos;
  resize_bulk(pos, size_t(L.corner_count()));
  parallel_ranges(L.vertex_count, kGrain, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
      for (Index i = L.vertex_face_offsets[v]; i < L.vertex_face_offsets[v + 1]; ++i)
        pos[L.face_offsets[L.vertex_faces[i]] + L.vertex_face_corner[i]] = i - L.vertex_face_offsets[v];
  });
  return pos;
}

void size_edges(Level& C, Index edges) {
  resize_bulk(C.face_edges, C.face_vertices.size());
  resize_bulk(C.edge_vertices, 2 * size_t(edges));
  resize_bulk(C.edge_faces, 2 * size_t(edges));
}

// The full Doo-Sabin child of a manifold parent (see the top of the file).
void complete_dual(const Level& L, const DualPlan& p, Level& C) {
  const Index F = L.face_count(), N = L.corner_count(), EF = p.e_faces;
  const Index first_closing = N + 2 * EF, v_block = N + 4 * EF;
  auto v_face = [&](Index v) { return p.vertex_face[v] == kNone ? kNone : F + EF + p.vertex_face[v]; };
  // The E-face edge of e across its end v, and a boundary V-face's closing edge.
  auto across = [&](Index e, Index v) { return N + 2 * p.edge_face[e] + (L.edge_vertices[2 * e] == v ? 1 : 0); };
  auto closing = [&](Index v) { return p.closing[v] == kNone ? kNone : first_closing + p.closing[v]; };
  size_edges(C, N + 2 * EF + p.closings);
  for_faces(L, [&](Index f) {
    for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c) {
      const Index k = p.edge_face[L.face_edges[c]];
      C.face_edges[c] = c;
      C.edge_vertices[2 * c] = c, C.edge_vertices[2 * c + 1] = next_in(L, f, c);
      C.edge_faces[2 * c] = f, C.edge_faces[2 * c + 1] = k == kNone ? kNone : F + k;
    }
  });
  parallel_ranges(L.edge_count(), kGrain, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e) {
      const Index k = p.edge_face[e];
      if (k == kNone) continue;
      const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
      const Index* fv = &C.face_vertices[size_t(N) + 4 * size_t(k)];  // f1@a, f1@b, f0@b, f0@a
      Index* fe = &C.face_edges[size_t(N) + 4 * size_t(k)];
      fe[0] = fv[1], fe[1] = N + 2 * k, fe[2] = fv[3], fe[3] = N + 2 * k + 1;
      C.edge_vertices[2 * (N + 2 * k)] = fv[1], C.edge_vertices[2 * (N + 2 * k) + 1] = fv[2];
      C.edge_vertices[2 * (N + 2 * k + 1)] = fv[3], C.edge_vertices[2 * (N + 2 * k + 1) + 1] = fv[0];
      C.edge_faces[2 * (N + 2 * k)] = C.edge_faces[2 * (N + 2 * k + 1)] = F + k;
      C.edge_faces[2 * (N + 2 * k) + 1] = v_face(b), C.edge_faces[2 * (N + 2 * k + 1) + 1] = v_face(a);
    }
  });
  parallel_ranges(L.vertex_count, kGrain, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) {
      if (p.vertex_face[v] == kNone) continue;
      const Index base = v_block + p.vertex_base[v], n = L.incident_face_count(v);
      const auto ring = L.ring_edges(v);
      for (Index j = 0; j + 1 < n; ++j) C.face_edges[base + j] = across(ring[j + 1], v);
      if (!L.on_boundary(v)) {
        C.face_edges[base + n - 1] = across(ring[0], v);
        continue;
      }
      const Index e = closing(v);
      C.face_edges[base + n - 1] = e;
      C.edge_vertices[2 * e] = C.face_vertices[base + n - 1], C.edge_vertices[2 * e + 1] = C.face_vertices[base];
      C.edge_faces[2 * e] = F + EF + p.vertex_face[v], C.edge_faces[2 * e + 1] = kNone;
    }
  });
  // Child vertex c: parent vertex v in face f. Slots: F(f), E(edge into v), V(v), E(edge out).
  std::vector<Index> face_of;
  resize_bulk(face_of, size_t(N));
  for_faces(L, [&](Index f) { std::fill(&face_of[L.face_offsets[f]], &face_of[L.face_offsets[f + 1]], f); });
  const std::vector<Index> pos = ring_positions(L);
  child_rings(C, [&](Index c, Ring4& s) {
    const Index f = face_of[c], v = L.face_vertices[c], pc = prev_in(L, f, c);
    const Index eo = L.face_edges[c], ei = L.face_edges[pc];
    const Index ko = p.edge_face[eo], ki = p.edge_face[ei];
    const bool has_v = p.vertex_face[v] != kNone;
    const Index out_v = ki != kNone ? across(ei, v) : closing(v), out_eo = ko != kNone ? across(eo, v) : closing(v);
    s[0] = {f, c - L.face_offsets[f], c, true};
    s[1] = {F + ki, L.edge_faces[2 * ei] == f ? 2 : 0, pc, ki != kNone};
    s[2] = {v_face(v), has_v ? pos[c] : 0, out_v, has_v};
    s[3] = {F + ko, L.edge_faces[2 * eo] == f ? 3 : 1, out_eo, ko != kNone};
    return 0;  // corner c of F(f) is the lowest of c's corners
  });
}

// The full mid-edge child of a manifold parent (see the top of the file).
void complete_mid_edge(const Level& L, const DualPlan& p, Level& C) {
  const Index F = L.face_count(), N = L.corner_count();
  auto v_face = [&](Index v) { return p.vertex_face[v] == kNone ? kNone : F + p.vertex_face[v]; };
  auto closing = [&](Index v) { return p.closing[v] == kNone ? kNone : N + p.closing[v]; };
  size_edges(C, N + p.closings);
  for_faces(L, [&](Index f) {
    for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c) {
      const Index next = next_in(L, f, c);
      C.face_edges[c] = c;
      C.edge_vertices[2 * c] = L.face_edges[c], C.edge_vertices[2 * c + 1] = L.face_edges[next];
      C.edge_faces[2 * c] = f, C.edge_faces[2 * c + 1] = v_face(L.face_vertices[next]);
    }
  });
  parallel_ranges(L.vertex_count, kGrain, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) {
      if (p.vertex_face[v] == kNone) continue;
      const Index base = N + p.vertex_base[v], fo = L.vertex_face_offsets[v], n = L.incident_face_count(v);
      // V-face corner j runs ring edge j -> j+1 across ring face j, whose edge into v runs the other way.
      for (Index j = 0; j < n; ++j) {
        const Index f = L.vertex_faces[fo + j];
        C.face_edges[base + j] = prev_in(L, f, L.face_offsets[f] + L.vertex_face_corner[fo + j]);
      }
      if (!L.on_boundary(v)) continue;
      const Index e = closing(v);
      C.face_edges[base + n] = e;
      C.edge_vertices[2 * e] = C.face_vertices[base + n], C.edge_vertices[2 * e + 1] = C.face_vertices[base];
      C.edge_faces[2 * e] = F + p.vertex_face[v], C.edge_faces[2 * e + 1] = kNone;
    }
  });
  // Child vertex e (a -> b). Slots: F(f0), V(a), F(f1), V(b).
  const std::vector<Index> pos = ring_positions(L);
  child_rings(C, [&](Index e, Ring4& s) {
    const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
    const Index f0 = L.edge_faces[2 * e], f1 = L.edge_faces[2 * e + 1];
    const Index c0 = corner_of_edge(L, f0, e), c1 = f1 == kNone ? kNone : corner_of_edge(L, f1, e);
    const bool has_a = p.vertex_face[a] != kNone, has_b = p.vertex_face[b] != kNone;
    s[0] = {f0, c0 - L.face_offsets[f0], c0, true};
    s[1] = {v_face(a), has_a ? pos[c0] : 0, prev_in(L, f0, c0), has_a};
    // On the boundary a's V-face enters e's child along its closing edge (e is a's ring edge 0).
    s[2] = {f1, f1 == kNone ? 0 : c1 - L.face_offsets[f1], f1 == kNone ? closing(a) : c1, f1 != kNone};
    s[3] = {v_face(b), f1 == kNone ? L.incident_face_count(b) : pos[c1], f1 == kNone ? closing(b) : prev_in(L, f1, c1),
            has_b};
    return f1 != kNone && c1 < c0 ? 2 : 0;
  });
}

}  // namespace

Level dual_split_topology(const Level& L, bool full, DualSkipped* skipped) {
  std::vector<Index> cycle;
  resize_bulk(cycle, size_t(L.vertex_count));
  for (Index v = 0; v < L.vertex_count; ++v) cycle[v] = L.incident_face_count(v);
  const DualPlan p = plan(L, true, [&](Index v) { return cycle[v]; }, skipped);
  Level C = child_faces(
      L, p, L.corner_count(), [](Index c) { return c; },
      [&](Index v, Index j) {
        const Index i = L.vertex_face_offsets[v] + j;
        return L.face_offsets[L.vertex_faces[i]] + L.vertex_face_corner[i];
      },
      cycle);
  if (!full) return C;
  if (p.direct) {
    complete_dual(L, p, C);
    return C;
  }
  return build_level(C.vertex_count, C.face_offsets, C.face_vertices);
}

Level mid_edge_split_topology(const Level& L, bool full, DualSkipped* skipped) {
  std::vector<Index> cycle;
  resize_bulk(cycle, size_t(L.vertex_count));
  for (Index v = 0; v < L.vertex_count; ++v) cycle[v] = L.valence(v);
  const DualPlan p = plan(L, false, [&](Index v) { return cycle[v]; }, skipped);
  Level C = child_faces(
      L, p, L.edge_count(), [&](Index c) { return L.face_edges[c]; },
      [&](Index v, Index j) { return L.vertex_edges[L.vertex_ring_offsets[v] + j]; }, cycle);
  if (!full) return C;
  if (p.direct) {
    complete_mid_edge(L, p, C);
    return C;
  }
  return build_level(C.vertex_count, C.face_offsets, C.face_vertices);
}

}  // namespace subdiv
