#include "framework/limit/adaptive_stage.h"

#include <fmt/format.h>

#include "framework/engine/mesh_pieces.h"
#include "framework/limit/face_domain.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

using Uv = std::array<double, 2>;

int position_in(std::span<const Index> list, Index x) {
  for (size_t k = 0; k < list.size(); ++k)
    if (list[k] == x) return int(k);
  return -1;
}

// The faces of `level` within `rings` rings (faces sharing a vertex) of the marked ones.
std::vector<char> grown(const Level& level, std::vector<char> in, int rings) {
  std::vector<Index> frontier;
  for (Index f = 0; f < level.face_count(); ++f)
    if (in[size_t(f)]) frontier.push_back(f);
  for (int r = 0; r < rings; ++r) {
    std::vector<Index> next;
    for (Index f : frontier)
      for (Index v : level.face(f))
        for (Index g : level.ring_faces(v))
          if (!in[size_t(g)]) in[size_t(g)] = 1, next.push_back(g);
    frontier = std::move(next);
  }
  return in;
}

// The faces read by the refinement of `piece` (its g ghost rings) must all be the level's:
// every vertex within g - 1 rings of the piece complete.
void check_inside(const AdaptiveStage& s, const std::vector<char>& piece, int ghost_rings) {
  const std::vector<char> read = grown(s.level, piece, std::max(ghost_rings - 1, 0));
  for (Index f = 0; f < s.level.face_count(); ++f)
    if (read[size_t(f)])
      for (Index v : s.level.face(f))
        if (!s.complete[size_t(v)])
          throw Error("adaptive refinement: a split face's neighbourhood reaches beyond the part of the level that "
                      "was computed (the scheme reads further than its ghost rings say); refine uniformly instead");
}

// Where a child vertex lies in its parent face's base face: at the parent's corner, the middle
// of its edge or its centre, or, in an n-gon of a quad split (the base face's sub-face
// tiles, face_domain.h), in the tile of the child face's own corner `tile`.
Uv child_uv(const AdaptiveStage& s, Index face, OriginKind kind, int corner_a, int corner_b, int tile,
            bool sub_faces) {
  const auto fv = s.level.face(face);
  const size_t n = fv.size(), first = size_t(s.level.face_offsets[size_t(face)]);
  auto uv = [&](int k) { return s.corner_uv[first + size_t(k)]; };
  if (sub_faces) {  // tile origin (c, r): edge tile..tile+1 at (c + 1/2, r), the previous at (c, r + 1/2)
    const Uv o = uv(tile);
    if (kind == OriginKind::Vertex) return o;
    if (kind == OriginKind::Face) return {o[0] + 0.5, o[1] + 0.5};
    const bool next = (corner_a == tile && corner_b == int((size_t(tile) + 1) % n)) ||
                      (corner_b == tile && corner_a == int((size_t(tile) + 1) % n));
    return next ? Uv{o[0] + 0.5, o[1]} : Uv{o[0], o[1] + 0.5};
  }
  if (kind == OriginKind::Vertex) return uv(corner_a);
  if (kind == OriginKind::Edge) return {0.5 * (uv(corner_a)[0] + uv(corner_b)[0]), 0.5 * (uv(corner_a)[1] + uv(corner_b)[1])};
  Uv c{0, 0};
  for (size_t k = 0; k < n; ++k) c[0] += uv(int(k))[0] / double(n), c[1] += uv(int(k))[1] / double(n);
  return c;
}

}  // namespace

AdaptiveStage base_stage(const Level& base, std::span<const double> points, int channels, bool triangles) {
  AdaptiveStage s;
  s.level = base;
  s.points.assign(points.begin(), points.end());
  s.channels = channels;
  s.complete.assign(size_t(base.vertex_count), 1);
  s.candidate.assign(size_t(base.face_count()), 1);
  for (Index f = 0; f < base.face_count(); ++f) {
    s.base_face.push_back(f);
    const int n = base.face_size(f);
    if (triangles && n != 3 && !base.is_hole(f))
      throw Error(fmt::format("adaptive refinement: face {} has {} corners and the scheme refines triangles; "
                              "triangulate the mesh first",
                              f, n));
    if (triangles) {
      s.corner_uv.insert(s.corner_uv.end(), {Uv{0, 0}, Uv{1, 0}, Uv{0, 1}});
      for (int k = 3; k < n; ++k) s.corner_uv.push_back({0, 0});
    } else if (n == 4) {
      s.corner_uv.insert(s.corner_uv.end(), {Uv{0, 0}, Uv{1, 0}, Uv{1, 1}, Uv{0, 1}});
    } else {  // Bfr's QUAD_SUBFACES: corner k at its tile's origin
      const int columns = sub_face_columns(n);
      for (int k = 0; k < n; ++k) s.corner_uv.push_back({double(k % columns), double(k / columns)});
    }
  }
  return s;
}

AdaptiveStage refine_stage(const Scheme& scheme, AdaptiveStage& s, int rings, int ghost_rings,
                           const RefineOptions& options, bool triangles, bool last) {
  const Level& L = s.level;
  const std::vector<char> computed = grown(L, s.split, rings);
  check_inside(s, computed, ghost_rings);
  std::vector<int> owner(size_t(L.face_count()), 1);
  for (Index f = 0; f < L.face_count(); ++f)
    if (computed[size_t(f)]) owner[size_t(f)] = 0;
  MeshPiece piece = cut_piece(L, owner, 0, ghost_rings);
  // The piece's level moves into the hierarchy (its levels[0], whose edges the origins name).
  const Hierarchy h = refine(scheme, std::move(piece.level), options);
  std::vector<int> piece_owner;
  piece_owner.reserve(piece.base_face.size());
  for (Index f : piece.base_face) piece_owner.push_back(owner[size_t(f)]);
  const std::vector<int> child_owner = finest_face_owners(h, piece_owner);
  MeshPiece kept = cut_piece(h.levels[1], child_owner, 0, 0, last);
  const ChildOrigins& o = h.origins[0];
  const Level& P = h.levels[0];

  AdaptiveStage n;
  n.level = std::move(kept.level);
  std::vector<double> piece_points;
  const int C = s.channels;
  piece_points.reserve(piece.base_vertex.size() * size_t(C));
  for (Index v : piece.base_vertex)
    piece_points.insert(piece_points.end(), s.points.begin() + C * v, s.points.begin() + C * v + C);
  n.points = h.stencils[0].apply_rows(piece_points, kept.base_vertex, C);
  n.channels = C;

  // Each child vertex's parent element in the stage, and whether it is complete.
  s.vertex_child.assign(size_t(L.vertex_count), kNone);
  s.edge_child.assign(size_t(L.edge_count()), kNone);
  s.children.assign(size_t(L.face_count()), {});
  auto all_computed = [&](std::span<const Index> faces) {
    for (Index f : faces)
      if (!computed[size_t(f)]) return false;
    return true;
  };
  std::vector<Index> parent_vertex_a(size_t(n.level.vertex_count), kNone), parent_vertex_b = parent_vertex_a;
  n.complete.assign(size_t(n.level.vertex_count), 0);
  for (Index c = 0; c < n.level.vertex_count; ++c) {
    const Index hc = kept.base_vertex[size_t(c)], from = o.parent[size_t(hc)];
    switch (o.kind[size_t(hc)]) {
      case OriginKind::Vertex: {
        const Index v = piece.base_vertex[size_t(from)];
        s.vertex_child[size_t(v)] = c;
        parent_vertex_a[size_t(c)] = v;
        n.complete[size_t(c)] = s.complete[size_t(v)] && all_computed(L.ring_faces(v));
        break;
      }
      case OriginKind::Edge: {
        const Index a = piece.base_vertex[size_t(P.edge_vertices[size_t(2 * from)])],
                    b = piece.base_vertex[size_t(P.edge_vertices[size_t(2 * from + 1)])];
        const Index e = find_edge(L, a, b);
        s.edge_child[size_t(e)] = c;
        parent_vertex_a[size_t(c)] = a, parent_vertex_b[size_t(c)] = b;
        const bool known = L.edge_face_count(e) == 2 || (s.complete[size_t(a)] && s.complete[size_t(b)]);
        n.complete[size_t(c)] = known && all_computed(L.faces_of_edge(e));
        break;
      }
      default: n.complete[size_t(c)] = 1; break;
    }
  }
  // Each child face's parent, base face, corners' (u, v), and whether it may be split.
  std::vector<int> rank_in_parent(size_t(h.levels[1].face_count()), 0);  // a parent's children follow each other
  for (Index i = 1; i < h.levels[1].face_count(); ++i)
    if (o.parent_face[size_t(i)] == o.parent_face[size_t(i - 1)])
      rank_in_parent[size_t(i)] = rank_in_parent[size_t(i - 1)] + 1;
  for (Index g = 0; g < n.level.face_count(); ++g) {
    const Index f = piece.base_face[size_t(o.parent_face[size_t(kept.base_face[size_t(g)])])];
    s.children[size_t(f)].push_back(g);
    n.parent.push_back(f);
    n.rank.push_back(rank_in_parent[size_t(kept.base_face[size_t(g)])]);
    n.base_face.push_back(s.base_face[size_t(f)]);
    n.candidate.push_back(s.split[size_t(f)]);
    const auto fv = L.face(f);
    const bool sub_faces = !triangles && fv.size() != 4;
    int tile = -1;
    for (Index c : n.level.face(g))
      if (o.kind[size_t(kept.base_vertex[size_t(c)])] == OriginKind::Vertex)
        tile = position_in(fv, parent_vertex_a[size_t(c)]);
    for (Index c : n.level.face(g)) {
      const OriginKind kind = o.kind[size_t(kept.base_vertex[size_t(c)])];
      const int ka = kind == OriginKind::Face ? -1 : position_in(fv, parent_vertex_a[size_t(c)]);
      const int kb = kind == OriginKind::Edge ? position_in(fv, parent_vertex_b[size_t(c)]) : -1;
      n.corner_uv.push_back(child_uv(s, f, kind, ka, kb, tile, sub_faces));
    }
  }
  return n;
}

}  // namespace subdiv
