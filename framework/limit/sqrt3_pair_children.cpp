#include "framework/limit/sqrt3_pair_children.h"

#include <array>
#include <optional>

namespace subdiv {
namespace {

constexpr std::array<Uv, 3> kCornerUv{{{0, 0}, {1, 0}, {0, 1}}};
constexpr double kInside = 1e-12;

Uv combine(const Uv& a, double wa, const Uv& b, double wb) { return {wa * a[0] + wb * b[0], wa * a[1] + wb * b[1]}; }

// Face g of the parent level seen from its own (u, v): its corners and the faces across its
// edges (edge i runs from corner i to corner i + 1; kNone on a boundary).
struct Frame {
  Index face = kNone;
  std::array<Index, 3> corners{};
  std::array<Index, 3> across{};
};

Frame frame_of(const Level& L, Index g) {
  Frame fr;
  fr.face = g;
  const auto corners = L.face(g);
  const auto edges = L.face_edge_list(g);
  for (size_t i = 0; i < 3; ++i) {
    fr.corners[i] = corners[i];
    const Index e = edges[i];
    fr.across[i] = L.edge_faces[size_t(2 * e)] == g ? L.edge_faces[size_t(2 * e + 1)] : L.edge_faces[size_t(2 * e)];
  }
  return fr;
}

// The one index i with list[i] == x, or -1 (none, or more than one: ambiguous).
int only_index(const std::array<Index, 3>& list, Index x) {
  int found = -1;
  for (int i = 0; i < 3; ++i)
    if (list[size_t(i)] == x) {
      if (found >= 0) return -1;
      found = i;
    }
  return found;
}

// Where a vertex of the middle level lies in the frame's (u, v), if it is one of the points
// the frame's nine children use: a child of its corners, its centroid, the centroid of a face
// across an edge (that face unfolded across the edge: its third corner at U_i + U_i+1 - U_i+2),
// or a point a third along one of its edges.
std::optional<Uv> middle_uv(const Level& parent, const ChildOrigins& o, const Frame& fr, Index y) {
  const Index p = o.parent[size_t(y)];
  switch (o.kind[size_t(y)]) {
    case OriginKind::Vertex: {
      const int i = only_index(fr.corners, p);
      if (i < 0) return std::nullopt;
      return kCornerUv[size_t(i)];
    }
    case OriginKind::Face: {
      if (p == fr.face) return Uv{1.0 / 3, 1.0 / 3};
      const int i = only_index(fr.across, p);
      if (i < 0) return std::nullopt;
      const Uv& a = kCornerUv[size_t(i)];
      const Uv& b = kCornerUv[size_t((i + 1) % 3)];
      const Uv& c = kCornerUv[size_t((i + 2) % 3)];
      return Uv{(2 * a[0] + 2 * b[0] - c[0]) / 3, (2 * a[1] + 2 * b[1] - c[1]) / 3};
    }
    case OriginKind::Edge: {
      const Index near = parent.edge_vertices[size_t(2 * p + o.local[size_t(y)])];
      const Index far = parent.edge_vertices[size_t(2 * p + 1 - o.local[size_t(y)])];
      const int i = only_index(fr.corners, near), k = only_index(fr.corners, far);
      if (i < 0 || k < 0) return std::nullopt;
      return combine(kCornerUv[size_t(i)], 2.0 / 3, kCornerUv[size_t(k)], 1.0 / 3);
    }
    default:
      return std::nullopt;
  }
}

// Where a vertex of the grand level lies in the frame's (u, v): its middle-level parent's
// place (a vertex child), the centroid of its middle-level face (a face point), or the third
// of its middle-level edge (a trisection point).
std::optional<Uv> grand_uv(const Level& parent, const Level& middle, const ChildOrigins& first,
                           const ChildOrigins& second, const Frame& fr, Index x) {
  const Index p = second.parent[size_t(x)];
  switch (second.kind[size_t(x)]) {
    case OriginKind::Vertex:
      return middle_uv(parent, first, fr, p);
    case OriginKind::Face: {
      Uv sum{0, 0};
      const auto corners = middle.face(p);
      for (Index y : corners) {
        const std::optional<Uv> at = middle_uv(parent, first, fr, y);
        if (!at) return std::nullopt;
        sum = combine(sum, 1, *at, 1);
      }
      return combine(sum, 1.0 / double(corners.size()), sum, 0);
    }
    case OriginKind::Edge: {
      const Index near = middle.edge_vertices[size_t(2 * p + second.local[size_t(x)])];
      const Index far = middle.edge_vertices[size_t(2 * p + 1 - second.local[size_t(x)])];
      const std::optional<Uv> a = middle_uv(parent, first, fr, near), b = middle_uv(parent, first, fr, far);
      if (!a || !b) return std::nullopt;
      return combine(*a, 2.0 / 3, *b, 1.0 / 3);
    }
    default:
      return std::nullopt;
  }
}

bool inside_triangle(const Uv& p) { return p[0] >= -kInside && p[1] >= -kInside && p[0] + p[1] <= 1 + kInside; }

// Face t of the grand level in frame fr: its corners' (u, v) when all are known and inside.
std::optional<ChildFace> child_in(const Level& parent, const Level& middle, const Level& grand,
                                  const ChildOrigins& first, const ChildOrigins& second, const Frame& fr, Index t) {
  ChildFace child{t, {}};
  for (Index x : grand.face(t)) {
    const std::optional<Uv> at = grand_uv(parent, middle, first, second, fr, x);
    if (!at || !inside_triangle(*at)) return std::nullopt;
    child.corners.push_back(*at);
  }
  return child;
}

}  // namespace

std::vector<std::vector<ChildFace>> sqrt3_pair_children(const Level& parent, const Level& middle, const Level& grand,
                                                        const ChildOrigins& first, const ChildOrigins& second) {
  std::vector<std::vector<ChildFace>> children(size_t(parent.face_count()));
  for (Index t = 0; t < grand.face_count(); ++t) {
    // The face t was made from lies in one of two parent faces (a flipped edge's triangle
    // straddles the edge): its recorded parent or a face across one of that one's edges.
    const Index made_from = second.parent_face.empty() ? kNone : second.parent_face[size_t(t)];
    const Index g0 = made_from == kNone || first.parent_face.empty() ? kNone : first.parent_face[size_t(made_from)];
    if (g0 == kNone || parent.face_size(g0) != 3) continue;
    const Frame home = frame_of(parent, g0);
    std::array<Index, 4> candidates{g0, home.across[0], home.across[1], home.across[2]};
    for (Index g : candidates) {
      if (g == kNone || parent.face_size(g) != 3) continue;
      if (std::optional<ChildFace> c = child_in(parent, middle, grand, first, second, frame_of(parent, g), t)) {
        children[size_t(g)].push_back(std::move(*c));
        break;
      }
    }
  }
  return children;
}

}  // namespace subdiv
