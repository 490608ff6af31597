// Builds a Level's edges and CCW vertex rings from polygons, refusing non-manifold input.
#include <algorithm>
#include <fmt/format.h>

#include "framework/topology/level.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// Corner arrays the builder works with: for every corner, its face and the next corner.
struct CornerIndex {
  std::vector<Index> face;          // per corner
  std::vector<Index> vertex_offsets;  // CSR: corners around each vertex (unordered)
  std::vector<Index> vertex_corners;
};

Index next_corner(const Level& level, Index face, Index corner) {
  return corner + 1 == level.face_offsets[face + 1] ? level.face_offsets[face] : corner + 1;
}
Index prev_corner(const Level& level, Index face, Index corner) {
  return corner == level.face_offsets[face] ? level.face_offsets[face + 1] - 1 : corner - 1;
}

void check_faces(const Level& level) {
  for (Index f = 0; f < level.face_count(); ++f) {
    auto verts = level.face(f);
    if (verts.size() < 3)
      throw Error(fmt::format("face {} has {} vertices; a face needs at least 3", f, verts.size()));
    for (size_t i = 0; i < verts.size(); ++i) {
      if (verts[i] < 0 || verts[i] >= level.vertex_count)
        throw Error(fmt::format("face {} names vertex {}, but the mesh has {} vertices", f,
                                verts[i], level.vertex_count));
      for (size_t j = 0; j < i; ++j)
        if (verts[i] == verts[j])
          throw Error(fmt::format("face {} is degenerate: it uses vertex {} twice; remove or fix it", f,
                                  verts[i]));
    }
  }
}

CornerIndex index_corners(const Level& level) {
  CornerIndex ci;
  const Index corners = level.corner_count();
  ci.face.resize(corners);
  for (Index f = 0; f < level.face_count(); ++f)
    std::fill(ci.face.begin() + level.face_offsets[f], ci.face.begin() + level.face_offsets[f + 1], f);
  ci.vertex_offsets.assign(level.vertex_count + 1, 0);
  for (Index v : level.face_vertices) ++ci.vertex_offsets[v + 1];
  for (Index v = 0; v < level.vertex_count; ++v) ci.vertex_offsets[v + 1] += ci.vertex_offsets[v];
  ci.vertex_corners.resize(corners);
  std::vector<Index> fill(ci.vertex_offsets.begin(), ci.vertex_offsets.end() - 1);
  for (Index c = 0; c < corners; ++c) ci.vertex_corners[fill[level.face_vertices[c]]++] = c;
  return ci;
}

// Corner around `from` whose face runs from -> to, or kNone; throws if two faces do.
Index find_half_edge(const Level& level, const CornerIndex& ci, Index from, Index to, Index skip) {
  Index found = kNone;
  for (Index i = ci.vertex_offsets[from]; i < ci.vertex_offsets[from + 1]; ++i) {
    Index c = ci.vertex_corners[i];
    if (c == skip || level.face_vertices[next_corner(level, ci.face[c], c)] != to) continue;
    if (found != kNone || skip != kNone)
      throw Error(fmt::format(
          "non-manifold edge ({}, {}): faces {} and {} both run it in the same direction "
          "(the edge has more than two faces, or the faces are inconsistently oriented); "
          "fix the mesh, for example by splitting the edge or reorienting faces",
          from, to, ci.face[c], ci.face[skip != kNone ? skip : found]));
    found = c;
  }
  return found;
}

void build_edges(Level& level, const CornerIndex& ci) {
  const Index corners = level.corner_count();
  level.face_edges.assign(corners, kNone);
  level.edge_vertices.clear();
  level.edge_faces.clear();
  level.edge_vertices.reserve(corners);
  level.edge_faces.reserve(corners);
  for (Index c = 0; c < corners; ++c) {
    const Index f = ci.face[c];
    const Index from = level.face_vertices[c];
    const Index to = level.face_vertices[next_corner(level, f, c)];
    find_half_edge(level, ci, from, to, c);  // refuses a second face running from -> to
    const Index twin = find_half_edge(level, ci, to, from, kNone);
    if (twin != kNone && twin < c) {
      const Index e = level.face_edges[twin];
      if (ci.face[twin] == f)
        throw Error(fmt::format("face {} uses edge ({}, {}) twice; fix the face", f, from, to));
      level.face_edges[c] = e;
      level.edge_faces[2 * e + 1] = f;
      continue;
    }
    const Index e = level.edge_count();
    level.face_edges[c] = e;
    level.edge_vertices.insert(level.edge_vertices.end(), {from, to});
    level.edge_faces.insert(level.edge_faces.end(), {f, kNone});
  }
}

// The corner of vertex v in face f.
Index corner_of(const Level& level, Index f, Index v) {
  for (Index c = level.face_offsets[f]; c < level.face_offsets[f + 1]; ++c)
    if (level.face_vertices[c] == v) return c;
  return kNone;
}

Index other_face(const Level& level, Index e, Index f) {
  return level.edge_faces[2 * e] == f ? level.edge_faces[2 * e + 1] : level.edge_faces[2 * e];
}

// Orders the corners around v CCW: the next face CCW lies across the edge entering v.
void build_ring(Level& level, const CornerIndex& ci, Index v) {
  const Index begin = ci.vertex_offsets[v], end = ci.vertex_offsets[v + 1];
  const Index count = end - begin;
  Index start = count ? ci.vertex_corners[begin] : kNone;
  bool boundary = false;
  for (Index i = begin; i < end; ++i) {
    const Index c = ci.vertex_corners[i];
    if (!level.edge_on_boundary(level.face_edges[c])) continue;
    if (boundary)
      throw Error(fmt::format(
          "non-manifold vertex {}: its faces form more than one fan (two boundaries meet "
          "there); split the vertex so each fan has its own",
          v));
    boundary = true;
    start = c;
  }
  level.vertex_on_boundary[v] = boundary;
  Index c = start;
  for (Index visited = 0; visited < count; ++visited) {
    const Index f = ci.face[c];
    level.vertex_faces.push_back(f);
    level.vertex_face_corner.push_back(std::uint8_t(c - level.face_offsets[f]));
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
  const Index placed = Index(level.vertex_faces.size()) - level.vertex_face_offsets[v];
  if (placed != count)
    throw Error(fmt::format(
        "non-manifold vertex {}: its {} faces form more than one fan around it; split the "
        "vertex so each fan has its own",
        v, count));
  level.vertex_face_offsets.push_back(Index(level.vertex_faces.size()));
  level.vertex_ring_offsets.push_back(Index(level.vertex_edges.size()));
}

}  // namespace

Level build_level(Index vertex_count, std::span<const Index> face_offsets,
                  std::span<const Index> face_vertices) {
  Level level;
  level.vertex_count = vertex_count;
  level.face_offsets.assign(face_offsets.begin(), face_offsets.end());
  level.face_vertices.assign(face_vertices.begin(), face_vertices.end());
  if (level.face_offsets.empty()) level.face_offsets.push_back(0);
  check_faces(level);
  const CornerIndex ci = index_corners(level);
  build_edges(level, ci);
  level.vertex_on_boundary.assign(vertex_count, 0);
  level.vertex_faces.reserve(level.corner_count());
  level.vertex_face_corner.reserve(level.corner_count());
  level.vertex_edges.reserve(level.corner_count() + vertex_count);
  level.vertex_face_offsets.reserve(vertex_count + 1);
  level.vertex_ring_offsets.reserve(vertex_count + 1);
  for (Index v = 0; v < vertex_count; ++v) build_ring(level, ci, v);
  return level;
}

Index find_edge(const Level& level, Index a, Index b) {
  for (Index e : level.ring_edges(a))
    if (level.other_end(e, a) == b) return e;
  return kNone;
}

long euler_characteristic(const Level& level) {
  return long(level.vertex_count) - level.edge_count() + level.face_count();
}

bool Level::all_faces_have_size(int k) const {
  for (Index f = 0; f < face_count(); ++f)
    if (face_size(f) != k) return false;
  return true;
}

int Level::max_face_size() const {
  int m = 0;
  for (Index f = 0; f < face_count(); ++f) m = std::max(m, face_size(f));
  return m;
}

}  // namespace subdiv
