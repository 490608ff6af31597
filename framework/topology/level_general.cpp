// The general level builder: non-manifold edges and vertices, inconsistently oriented
// neighbours and faces that repeat a vertex, marked as OpenSubdiv's Vtr marks them
// (opensubdiv/vtr/level.cpp: completeTopologyFromFaceVertices, orientIncidentComponents).
// Only meshes that are not manifold come here, so it favours clarity over speed.
#include <algorithm>
#include <tbb/parallel_for.h>

#include "framework/topology/level.h"
#include "framework/topology/level_rings.h"

namespace subdiv {

namespace {

// The corner of vertex v in face f.
Index corner_of(const Level& level, Index f, Index v) {
  for (Index c = level.face_offsets[f]; c < level.face_offsets[f + 1]; ++c)
    if (level.face_vertices[c] == v) return c;
  return kNone;
}

Index other_face(const Level& level, Index e, Index f) {
  return level.edge_faces[2 * e] == f ? level.edge_faces[2 * e + 1] : level.edge_faces[2 * e];
}

}  // namespace

// Orders the corners around v CCW: the next face CCW lies across the edge entering v.
bool build_ordered_ring(Level& level, const CornerIndex& ci, Index v) {
  const Index begin = ci.vertex_offsets[v], end = ci.vertex_offsets[v + 1];
  const Index count = end - begin;
  const size_t faces_before = level.vertex_faces.size(), edges_before = level.vertex_edges.size();
  auto fail = [&] {
    level.vertex_faces.resize(faces_before);
    level.vertex_face_corner.resize(faces_before);
    level.vertex_edges.resize(edges_before);
    return false;
  };
  Index start = count ? ci.vertex_corners[begin] : kNone;
  bool boundary = false;
  for (Index i = begin; i < end; ++i) {
    const Index c = ci.vertex_corners[i];
    if (!level.edge_on_boundary(level.face_edges[c])) continue;
    if (boundary) return fail();  // two boundaries meet at v: more than one fan
    boundary = true;
    start = c;
  }
  Index c = start;
  for (Index visited = 0; visited < count; ++visited) {
    const Index f = ci.face[c];
    level.vertex_faces.push_back(f);
    level.vertex_face_corner.push_back(LocalIndex(c - level.face_offsets[f]));
    level.vertex_edges.push_back(level.face_edges[c]);
    const Index in_edge = level.face_edges[prev_corner(level, f, c)];
    const Index g = other_face(level, in_edge, f);
    if (g == kNone) {
      level.vertex_edges.push_back(in_edge);
      if (visited + 1 != count) break;
    } else {
      c = corner_of(level, g, v);
      if (c == start && visited + 1 != count) break;
    }
  }
  if (Index(level.vertex_faces.size() - faces_before) != count) return fail();
  level.vertex_on_boundary[v] = boundary;
  level.vertex_face_offsets.push_back(Index(level.vertex_faces.size()));
  level.vertex_ring_offsets.push_back(Index(level.vertex_edges.size()));
  return true;
}

void identify_edges_general(Level& level) {
  const Index corners = level.corner_count();
  std::vector<std::vector<Index>> edges_at(size_t(level.vertex_count));
  std::vector<Index> last_face, face_count;
  level.face_edges.assign(corners, kNone);
  level.edge_vertices.clear();
  level.edge_non_manifold.clear();
  for (Index f = 0; f < level.face_count(); ++f) {
    for (Index c = level.face_offsets[f]; c < level.face_offsets[f + 1]; ++c) {
      const Index v0 = level.face_vertices[c], v1 = level.face_vertices[next_corner(level, f, c)];
      Index e = kNone;
      bool marked = v0 == v1;  // an edge from a vertex to itself always gets its own
      if (!marked)
        for (Index x : edges_at[v0])
          if (level.other_end(x, v0) == v1 && level.edge_vertices[2 * x] != level.edge_vertices[2 * x + 1]) e = x;
      if (e != kNone) {
        if (last_face[e] == f) {
          // The face comes back to an edge it already uses: a new edge, both marked.
          level.edge_non_manifold[e] = 1;
          marked = true;
          e = kNone;
        } else if (face_count[e] > 1 || level.edge_vertices[2 * e] == v0) {
          level.edge_non_manifold[e] = 1;  // a third face, or a second running the same way
        }
      }
      if (e == kNone) {
        e = level.edge_count();
        level.edge_vertices.insert(level.edge_vertices.end(), {v0, v1});
        level.edge_non_manifold.push_back(marked);
        last_face.push_back(kNone);
        face_count.push_back(0);
        edges_at[v0].push_back(e);
        if (v1 != v0) edges_at[v1].push_back(e);
      }
      ++face_count[e];
      last_face[e] = f;
      level.face_edges[c] = e;
    }
  }
}

namespace {

// Edge faces (both forms), and non-manifold marks found from them.
void complete_edges(Level& L, const CornerIndex& ci) {
  const Index E = L.edge_count();
  L.edge_face_offsets.assign(E + 1, 0);
  for (Index e : L.face_edges) ++L.edge_face_offsets[e + 1];
  for (Index e = 0; e < E; ++e) L.edge_face_offsets[e + 1] += L.edge_face_offsets[e];
  std::vector<Index> corner_list(L.edge_face_offsets.back());
  std::vector<Index> fill(L.edge_face_offsets.begin(), L.edge_face_offsets.end() - 1);
  for (Index c = 0; c < L.corner_count(); ++c) corner_list[fill[L.face_edges[c]]++] = c;
  L.edge_face_list.resize(corner_list.size());
  L.edge_faces.assign(2 * size_t(E), kNone);
  for (Index e = 0; e < E; ++e) {
    const Index o = L.edge_face_offsets[e], n = L.edge_face_offsets[e + 1] - o;
    Index* corner = corner_list.data() + o;
    const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
    bool nm = L.edge_non_manifold[e] || a == b || n > 2 || n == 0;
    if (n == 2) nm = nm || ci.face[corner[0]] == ci.face[corner[1]] ||
                     L.face_vertices[corner[0]] == L.face_vertices[corner[1]];
    if (!nm && n >= 1) {
      // Manifold conventions: slot 0 runs the edge forwards, slot 1 backwards.
      if (n == 2 && L.face_vertices[corner[0]] != a) std::swap(corner[0], corner[1]);
      if (n == 1 && L.face_vertices[corner[0]] != a) std::swap(L.edge_vertices[2 * e], L.edge_vertices[2 * e + 1]);
    }
    L.edge_non_manifold[e] = nm;
    for (Index i = 0; i < n; ++i) L.edge_face_list[o + i] = ci.face[corner[i]];
    if (n > 0) L.edge_faces[2 * e] = ci.face[corner[0]];
    if (n > 1) L.edge_faces[2 * e + 1] = ci.face[corner[1]];
  }
}

// A non-manifold vertex's faces and edges, in the order its corners come (no CCW order exists).
void build_unordered_ring(Level& L, const CornerIndex& ci, Index v) {
  const size_t edges_before = L.vertex_edges.size();
  bool boundary = false;
  auto add_edge = [&](Index e) {
    if (std::find(L.vertex_edges.begin() + edges_before, L.vertex_edges.end(), e) != L.vertex_edges.end()) return;
    L.vertex_edges.push_back(e);
    boundary = boundary || L.edge_face_count(e) < 2;
  };
  for (Index i = ci.vertex_offsets[v]; i < ci.vertex_offsets[v + 1]; ++i) {
    const Index c = ci.vertex_corners[i], f = ci.face[c];
    L.vertex_faces.push_back(f);
    L.vertex_face_corner.push_back(LocalIndex(c - L.face_offsets[f]));
    add_edge(L.face_edges[c]);
    add_edge(L.face_edges[prev_corner(L, f, c)]);
  }
  L.vertex_on_boundary[v] = boundary;
  L.vertex_face_offsets.push_back(Index(L.vertex_faces.size()));
  L.vertex_ring_offsets.push_back(Index(L.vertex_edges.size()));
}

}  // namespace

void complete_general_level(Level& L) {
  const Index V = L.vertex_count;
  L.edge_non_manifold.resize(L.edge_count(), 0);
  L.vertex_non_manifold.resize(V, 0);
  const CornerIndex ci = index_corners(L);
  complete_edges(L, ci);
  for (Index e = 0; e < L.edge_count(); ++e)
    if (L.edge_non_manifold[e]) L.vertex_non_manifold[L.edge_vertices[2 * e]] = L.vertex_non_manifold[L.edge_vertices[2 * e + 1]] = 1;
  L.vertex_on_boundary.assign(V, 0);
  L.vertex_faces.clear(), L.vertex_face_corner.clear(), L.vertex_edges.clear();
  L.vertex_face_offsets.assign(1, 0);
  L.vertex_ring_offsets.assign(1, 0);
  for (Index v = 0; v < V; ++v) {
    if (!L.vertex_non_manifold[v] && build_ordered_ring(L, ci, v)) continue;
    L.vertex_non_manifold[v] = 1;  // its faces form more than one fan
    build_unordered_ring(L, ci, v);
  }
  const auto marked = [](const std::vector<std::uint8_t>& m) { return std::find(m.begin(), m.end(), 1) != m.end(); };
  if (!marked(L.edge_non_manifold) && !marked(L.vertex_non_manifold)) {
    L.edge_non_manifold.clear(), L.vertex_non_manifold.clear();
    L.edge_face_offsets.clear(), L.edge_face_list.clear();
  }
}

}  // namespace subdiv
