#include "framework/engine/mesh_pieces.h"

#include <algorithm>
#include <fmt/format.h>
#include <limits>

#include "framework/util/error.h"

namespace subdiv {
namespace {

// True when the faces of v that are in the piece form more than one fan around it: the
// piece would be pinched there, a non-manifold vertex (topology/level.h), and a level with
// one is refined on the general path, whose rings start elsewhere (round-off apart from the
// whole mesh's sums). Only for manifold vertices: a non-manifold one has no fans to follow.
bool pinched(const Level& base, const std::vector<std::uint8_t>& in, Index v) {
  if (base.non_manifold_vertex(v)) return false;
  const auto faces = base.ring_faces(v);
  const size_t n = faces.size();
  int runs = 0;
  for (size_t i = 0; i < n; ++i) {
    // A run starts at a face in the piece whose predecessor (around v) is not.
    const bool has_before = i > 0 || !base.on_boundary(v);
    if (in[faces[i]] && !(has_before && in[faces[(i + n - 1) % n]])) ++runs;
  }
  return runs > 1;
}

// Fills every pinch with the faces around its vertex, until none is left: a few more
// ghost faces, and a manifold piece of a manifold mesh.
void fill_pinches(const Level& base, std::vector<std::uint8_t>& in) {
  for (bool changed = true; changed;) {
    changed = false;
    for (Index v = 0; v < base.vertex_count; ++v)
      if (pinched(base, in, v)) {
        for (Index f : base.ring_faces(v)) in[f] = 1;
        changed = true;
      }
  }
}

// The piece's faces grown by `rings` rings of faces sharing a vertex, as a mask over faces.
std::vector<std::uint8_t> faces_with_ghosts(const Level& base, std::span<const int> face_owner, int piece, int rings) {
  std::vector<std::uint8_t> in(base.face_count(), 0);
  std::vector<Index> frontier;
  for (Index f = 0; f < base.face_count(); ++f)
    if (face_owner[f] == piece) in[f] = 1, frontier.push_back(f);
  std::vector<std::uint8_t> vertex_done(base.vertex_count, 0);
  for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
    std::vector<Index> next;
    for (Index f : frontier)
      for (Index v : base.face(f)) {
        if (vertex_done[v]) continue;
        vertex_done[v] = 1;
        for (Index g : base.ring_faces(v))
          if (!in[g]) in[g] = 1, next.push_back(g);
      }
    frontier = std::move(next);
  }
  fill_pinches(base, in);
  return in;
}

// The base tags on the piece's edges, vertices and faces: edges by the corners that own them.
void copy_tags(const Level& base, MeshPiece& p) {
  Level& L = p.level;
  if (!base.edge_sharpness.empty()) {
    L.edge_sharpness.assign(L.edge_count(), 0.f);
    for (Index f = 0; f < L.face_count(); ++f)
      for (int i = 0; i < L.face_size(f); ++i)
        L.edge_sharpness[L.face_edges[L.face_offsets[f] + i]] =
            base.edge_sharpness[base.face_edges[base.face_offsets[p.base_face[f]] + i]];
  }
  if (!base.vertex_sharpness.empty()) {
    L.vertex_sharpness.resize(L.vertex_count);
    for (Index v = 0; v < L.vertex_count; ++v) L.vertex_sharpness[v] = base.vertex_sharpness[p.base_vertex[v]];
  }
  if (!base.face_hole.empty()) {
    L.face_hole.resize(L.face_count());
    for (Index f = 0; f < L.face_count(); ++f) L.face_hole[f] = base.face_hole[p.base_face[f]];
  }
}

}  // namespace

MeshPiece cut_piece(const Level& base, std::span<const int> face_owner, int piece, int ghost_rings, bool faces_only) {
  if (std::find(face_owner.begin(), face_owner.end(), piece) == face_owner.end())
    throw Error(fmt::format("piece {} has no faces; ask for at most as many pieces as the mesh has faces ({})", piece,
                            base.face_count()));
  const std::vector<std::uint8_t> in = faces_with_ghosts(base, face_owner, piece, ghost_rings);
  MeshPiece p;
  std::vector<Index> local(base.vertex_count, kNone);
  for (Index f = 0; f < base.face_count(); ++f)
    if (in[f]) {
      p.base_face.push_back(f);
      p.face_owner.push_back(face_owner[f]);
      for (Index v : base.face(f)) local[v] = 0;
    }
  for (Index v = 0; v < base.vertex_count; ++v)
    if (local[v] == 0) local[v] = Index(p.base_vertex.size()), p.base_vertex.push_back(v);
  std::vector<Index> offsets{0}, corners;
  offsets.reserve(p.base_face.size() + 1);
  for (Index f : p.base_face) {
    for (Index v : base.face(f)) corners.push_back(local[v]);
    offsets.push_back(Index(corners.size()));
  }
  if (faces_only) {
    p.level.vertex_count = Index(p.base_vertex.size());
    p.level.face_offsets.assign(offsets.begin(), offsets.end());
    p.level.face_vertices.assign(corners.begin(), corners.end());
    return p;
  }
  p.level = build_level(Index(p.base_vertex.size()), offsets, corners);
  copy_tags(base, p);
  return p;
}

Index piece_face_count(const Level& base, std::span<const int> face_owner, int piece, int ghost_rings) {
  const std::vector<std::uint8_t> in = faces_with_ghosts(base, face_owner, piece, ghost_rings);
  return Index(std::count(in.begin(), in.end(), 1));
}

namespace {

// The smallest owner among the faces around a parent element a child vertex comes from.
int vertex_owner(const Level& parent, std::span<const int> owner, OriginKind kind, Index element) {
  int best = std::numeric_limits<int>::max();
  auto take = [&](std::span<const Index> faces) {
    for (Index f : faces) best = std::min(best, owner[f]);
  };
  switch (kind) {
    case OriginKind::Vertex: take(parent.ring_faces(element)); break;
    case OriginKind::Edge: take(parent.faces_of_edge(element)); break;
    case OriginKind::Face:
    case OriginKind::Corner: best = owner[element]; break;
  }
  return best;
}

std::vector<int> child_face_owners(const Level& parent, const Level& child, const ChildOrigins& o,
                                   std::span<const int> owner) {
  std::vector<int> out(child.face_count());
  for (Index f = 0; f < child.face_count(); ++f) {
    if (o.parent_face[f] != kNone) {
      out[f] = owner[o.parent_face[f]];
      continue;
    }
    int best = std::numeric_limits<int>::max();
    for (Index v : child.face(f)) best = std::min(best, vertex_owner(parent, owner, o.kind[v], o.parent[v]));
    out[f] = best;
  }
  return out;
}

}  // namespace

std::vector<int> finest_face_owners(const Hierarchy& h, std::span<const int> base_owner) {
  std::vector<int> owner(base_owner.begin(), base_owner.end());
  for (size_t l = 0; l + 1 < h.levels.size(); ++l)
    owner = child_face_owners(h.levels[l], h.levels[l + 1], h.origins[l], owner);
  return owner;
}

std::vector<double> gather_tuples(std::span<const double> values, int components, std::span<const Index> kept) {
  std::vector<double> out;
  out.reserve(kept.size() * size_t(components));
  for (Index i : kept)
    out.insert(out.end(), values.begin() + ptrdiff_t(i) * components, values.begin() + ptrdiff_t(i + 1) * components);
  return out;
}

}  // namespace subdiv
