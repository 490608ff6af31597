#include "framework/limit/sqrt3_step_children.h"

#include <array>
#include <optional>
#include <span>

namespace subdiv {
namespace {

constexpr std::array<Uv, 3> kCornerUv{{{0, 0}, {1, 0}, {0, 1}}};

Uv combine(const Uv& a, double wa, const Uv& b, double wb) { return {wa * a[0] + wb * b[0], wa * a[1] + wb * b[1]}; }

// Face f of the parent level seen from its own (u, v): its corners, the faces across its
// edges (edge i runs from corner i to corner i + 1; kNone on a boundary) and their third
// corners.
struct Frame {
  Index face = kNone;
  std::array<Index, 3> corners{};
  std::array<Index, 3> across{};
  std::array<Index, 3> opposite{};
};

Index third_corner(const Level& L, Index g, Index a, Index b) {
  for (Index v : L.face(g))
    if (v != a && v != b) return v;
  return kNone;
}

Frame frame_of(const Level& L, Index f) {
  Frame fr;
  fr.face = f;
  const auto corners = L.face(f);
  const auto edges = L.face_edge_list(f);
  for (size_t i = 0; i < 3; ++i) fr.corners[i] = corners[i];
  for (size_t i = 0; i < 3; ++i) {
    const Index e = edges[i];
    fr.across[i] = L.edge_faces[size_t(2 * e)] == f ? L.edge_faces[size_t(2 * e + 1)] : L.edge_faces[size_t(2 * e)];
    fr.opposite[i] = fr.across[i] == kNone ? kNone : third_corner(L, fr.across[i], fr.corners[i], fr.corners[(i + 1) % 3]);
  }
  return fr;
}

// The index i with list[i] == x, or -1; *count says how many there are.
int index_of(const std::array<Index, 3>& list, Index x, int* count) {
  int found = -1;
  *count = 0;
  for (int i = 0; i < 3; ++i)
    if (list[size_t(i)] == x) found = i, ++*count;
  return found;
}

// The one index i with list[i] == x, or -1 (none, or more than one: ambiguous).
int only_index(const std::array<Index, 3>& list, Index x) {
  int count = 0;
  const int i = index_of(list, x, &count);
  return count == 1 ? i : -1;
}

// A parent vertex in the frame: a corner, or the third corner of a face across an edge,
// unfolded (U_i + U_i+1 - U_i+2). A vertex seen twice (a small closed mesh) is ambiguous.
std::optional<Uv> vertex_uv(const Frame& fr, Index v) {
  int corners = 0, opposites = 0;
  const int corner = index_of(fr.corners, v, &corners), across = index_of(fr.opposite, v, &opposites);
  if (corners + opposites != 1) return std::nullopt;
  if (corner >= 0) return kCornerUv[size_t(corner)];
  const size_t i = size_t(across);
  return combine(combine(kCornerUv[i], 1, kCornerUv[(i + 1) % 3], 1), 1, kCornerUv[(i + 2) % 3], -1);
}

// A child vertex in the frame: a vertex child where its parent is, a face point at the
// centroid of f or of a face across an edge, a trisection point at the third of its edge
// next to the end it belongs to (refine/sqrt3_split.cpp).
std::optional<Uv> child_vertex_uv(const Level& parent, const ChildOrigins& o, const Frame& fr, Index y) {
  const Index p = o.parent[size_t(y)];
  switch (o.kind[size_t(y)]) {
    case OriginKind::Vertex:
      return vertex_uv(fr, p);
    case OriginKind::Face: {
      // By the edge it lies across, not by its third corner, which a small closed mesh may
      // share between faces (the tetrahedron's).
      if (p == fr.face) return Uv{1.0 / 3, 1.0 / 3};
      const int i = only_index(fr.across, p);
      if (i < 0) return std::nullopt;
      const Uv& a = kCornerUv[size_t(i)];
      const Uv& b = kCornerUv[size_t((i + 1) % 3)];
      const Uv& c = kCornerUv[size_t((i + 2) % 3)];
      return Uv{(2 * a[0] + 2 * b[0] - c[0]) / 3, (2 * a[1] + 2 * b[1] - c[1]) / 3};
    }
    case OriginKind::Edge: {
      const std::optional<Uv> near = vertex_uv(fr, parent.edge_vertices[size_t(2 * p + o.local[size_t(y)])]);
      const std::optional<Uv> far = vertex_uv(fr, parent.edge_vertices[size_t(2 * p + 1 - o.local[size_t(y)])]);
      if (!near || !far) return std::nullopt;
      return combine(*near, 2.0 / 3, *far, 1.0 / 3);
    }
    default:
      return std::nullopt;
  }
}

// True when child vertex y is one of the frame's face's own new points: its face point, or a
// point trisecting one of its edges.
bool owned(const Level& parent, const ChildOrigins& o, const Frame& fr, Index y) {
  const Index p = o.parent[size_t(y)];
  if (o.kind[size_t(y)] == OriginKind::Face) return p == fr.face;
  if (o.kind[size_t(y)] != OriginKind::Edge) return false;
  for (Index e : parent.face_edge_list(fr.face))
    if (e == p) return true;
  return false;
}

// The new triangles over a face each have a corner of its own (the face point, or a
// trisection point of its edge: refine/sqrt3_split.cpp). Others, around a vertex of valence
// 3, can have all their corners placed, by unfolding two neighbours that really share an
// edge across two different edges of the face, and would sit over it in the wrong place.
bool over_face(const Level& parent, const ChildOrigins& o, const Frame& fr, std::span<const Index> corners) {
  for (Index y : corners)
    if (owned(parent, o, fr, y)) return true;
  return false;
}

// Child face t in the frame, when it lies over the face and all its corners are placed.
std::optional<ChildFace> child_in(const Level& parent, const Level& child, const ChildOrigins& o, const Frame& fr,
                                  Index t) {
  if (!over_face(parent, o, fr, child.face(t))) return std::nullopt;
  ChildFace c{t, {}};
  for (Index y : child.face(t)) {
    const std::optional<Uv> at = child_vertex_uv(parent, o, fr, y);
    if (!at) return std::nullopt;
    c.corners.push_back(*at);
  }
  return c;
}

// A vertex two steps down in the frame: its middle-level parent's place (a vertex child), the
// centroid of its middle-level face (a face point), or the third of its middle-level edge.
std::optional<Uv> grand_uv(const Level& parent, const Level& middle, const ChildOrigins& first,
                           const ChildOrigins& second, const Frame& fr, Index x) {
  const Index p = second.parent[size_t(x)];
  switch (second.kind[size_t(x)]) {
    case OriginKind::Vertex:
      return child_vertex_uv(parent, first, fr, p);
    case OriginKind::Face: {
      if (!over_face(parent, first, fr, middle.face(p))) return std::nullopt;
      Uv sum{0, 0};
      for (Index y : middle.face(p)) {
        const std::optional<Uv> at = child_vertex_uv(parent, first, fr, y);
        if (!at) return std::nullopt;
        sum = combine(sum, 1, *at, 1);
      }
      return combine(sum, 1.0 / double(middle.face_size(p)), sum, 0);
    }
    case OriginKind::Edge: {
      const Index near = middle.edge_vertices[size_t(2 * p + second.local[size_t(x)])];
      const Index far = middle.edge_vertices[size_t(2 * p + 1 - second.local[size_t(x)])];
      const std::optional<Uv> a = child_vertex_uv(parent, first, fr, near);
      const std::optional<Uv> b = child_vertex_uv(parent, first, fr, far);
      if (!a || !b) return std::nullopt;
      return combine(*a, 2.0 / 3, *b, 1.0 / 3);
    }
    default:
      return std::nullopt;
  }
}

bool inside_triangle(const Uv& p) {
  constexpr double kInside = 1e-12;
  return p[0] >= -kInside && p[1] >= -kInside && p[0] + p[1] <= 1 + kInside;
}

// The face a child face was made from, and the faces across that one's edges: the faces of
// the parent level it can reach over.
std::array<Index, 4> reachable_faces(const Level& parent, const ChildOrigins& o, const std::vector<Frame>& frames,
                                     Index t) {
  const Index made_from = o.parent_face.empty() ? kNone : o.parent_face[size_t(t)];
  if (made_from == kNone || parent.face_size(made_from) != 3) return {kNone, kNone, kNone, kNone};
  const Frame& home = frames[size_t(made_from)];
  return {made_from, home.across[0], home.across[1], home.across[2]};
}

std::vector<Frame> triangle_frames(const Level& parent) {
  std::vector<Frame> frames(size_t(parent.face_count()));
  for (Index f = 0; f < parent.face_count(); ++f)
    if (parent.face_size(f) == 3) frames[size_t(f)] = frame_of(parent, f);
  return frames;
}

}  // namespace

std::vector<std::vector<ChildFace>> sqrt3_pair_children(const Level& parent, const Level& middle, const Level& grand,
                                                        const ChildOrigins& first, const ChildOrigins& second) {
  const std::vector<Frame> frames = triangle_frames(parent);
  std::vector<std::vector<ChildFace>> children(size_t(parent.face_count()));
  for (Index t = 0; t < grand.face_count(); ++t) {
    const Index made_from = second.parent_face.empty() ? kNone : second.parent_face[size_t(t)];
    if (made_from == kNone) continue;
    for (Index f : reachable_faces(parent, first, frames, made_from)) {
      if (f == kNone || parent.face_size(f) != 3) continue;
      ChildFace c{t, {}};
      for (Index x : grand.face(t)) {
        const std::optional<Uv> at = grand_uv(parent, middle, first, second, frames[size_t(f)], x);
        if (!at || !inside_triangle(*at)) break;
        c.corners.push_back(*at);
      }
      if (c.corners.size() == size_t(grand.face_size(t))) {
        children[size_t(f)].push_back(std::move(c));
        break;
      }
    }
  }
  return children;
}

std::vector<std::vector<ChildFace>> sqrt3_step_children(const Level& parent, const Level& child,
                                                        const ChildOrigins& origins) {
  const std::vector<Frame> frames = triangle_frames(parent);
  std::vector<std::vector<ChildFace>> children(size_t(parent.face_count()));
  for (Index t = 0; t < child.face_count(); ++t) {
    // A new triangle is made from one face and reaches at most across that face's edges.
    for (Index f : reachable_faces(parent, origins, frames, t)) {
      if (f == kNone || parent.face_size(f) != 3) continue;
      if (std::optional<ChildFace> c = child_in(parent, child, origins, frames[size_t(f)], t))
        children[size_t(f)].push_back(std::move(*c));
    }
  }
  return children;
}

}  // namespace subdiv
