#include "framework/limit/adaptive_face_varying.h"

#include <algorithm>
#include <fmt/format.h>

#include "framework/engine/mesh_pieces.h"
#include "framework/features/sharpness.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

void check_same_faces(const Level& vertices, const Level& values) {
  bool same = vertices.face_count() == values.face_count();
  for (Index f = 0; same && f < vertices.face_count(); ++f) same = vertices.face_size(f) == values.face_size(f);
  if (!same)
    throw Error(fmt::format("adaptive refinement: a face-varying channel's value mesh has {} faces against the mesh's "
                            "{} (or faces of other sizes); it must have the mesh's faces, in the same order",
                            values.face_count(), vertices.face_count()));
}

// The tags the modes Boundaries and All renew at every level (primvar/face_varying.h): every
// value on the value mesh's boundary a corner, or every value and edge sharp. A stage's cut is
// not a boundary: a value there is left alone (its vertex is not complete, and no child the
// stage keeps reads its tags).
void tag_linear(Level& values, const AdaptiveStage& vertex_stage, const AdaptiveValueMesh& channel) {
  if (!channel.linear_boundaries && !channel.linear_everywhere) return;
  values.vertex_sharpness.resize(size_t(values.vertex_count), 0.f);
  values.edge_sharpness.resize(size_t(values.edge_count()), 0.f);
  if (channel.linear_everywhere) {
    std::fill(values.vertex_sharpness.begin(), values.vertex_sharpness.end(), kInfinitelySharp);
    std::fill(values.edge_sharpness.begin(), values.edge_sharpness.end(), kInfinitelySharp);
    return;
  }
  const Level& vertices = vertex_stage.level;
  for (size_t c = 0; c < values.face_vertices.size(); ++c) {
    const Index u = values.face_vertices[c];
    if (vertex_stage.complete[size_t(vertices.face_vertices[c])] && values.on_boundary(u))
      values.vertex_sharpness[size_t(u)] = kInfinitelySharp;
  }
}

}  // namespace

AdaptiveValueStage value_base_stage(const Level& base, const AdaptiveValueMesh& channel) {
  if (!channel.level || channel.components < 1 ||
      channel.values.size() != size_t(channel.level->vertex_count) * size_t(channel.components))
    throw Error("adaptive refinement: a face-varying channel needs its value mesh and components values per value");
  check_same_faces(base, *channel.level);
  return {*channel.level, {channel.values.begin(), channel.values.end()}, {}, {}};
}

AdaptiveValueStage refine_value_stage(const Scheme& scheme, const AdaptiveStage& vs, const AdaptiveStage& vnext,
                                      AdaptiveValueStage& s, const AdaptiveValueMesh& channel, int ghost_rings,
                                      RefineOptions options, bool last) {
  tag_linear(s.level, vs, channel);
  const Level& L = s.level;
  // The piece: the faces whose children the vertex stage keeps (its computed faces, and ghosts
  // whose children fill a pinch), with the value mesh's ghost rings.
  std::vector<int> owner(size_t(L.face_count()), 1);
  for (Index f : vnext.parent) owner[size_t(f)] = 0;
  MeshPiece piece = cut_piece(L, owner, 0, ghost_rings);
  options.features.boundary = BoundaryInterpolation::EdgesOnly;  // the corners are tagged
  options.faces_only_last_level = last;  // where the engine can: only its faces are read then
  // The piece's level moves into the hierarchy (its levels[0], whose edges the origins name).
  const Hierarchy h = refine(scheme, std::move(piece.level), options);
  const Level& C = h.levels[1];
  const ChildOrigins& o = h.origins[0];
  // Each stage face's children in the piece's refinement: a parent's children follow each
  // other, so its first child and their count.
  std::vector<Index> first_child(size_t(L.face_count()), kNone), child_count(size_t(L.face_count()), 0);
  for (Index i = 0; i < C.face_count(); ++i)
    if (const Index parent = o.parent_face[size_t(i)]; parent != kNone) {
      const size_t f = size_t(piece.base_face[size_t(parent)]);
      if (child_count[f]++ == 0) first_child[f] = i;
      else if (first_child[f] + child_count[f] - 1 != i)
        throw Error("adaptive refinement: the split gave a face's children apart from each other");
    }
  // The vertex stage's faces, taken from the piece's children: the same parent, the same place.
  std::vector<Index> faces;
  faces.reserve(vnext.parent.size());
  for (size_t g = 0; g < vnext.parent.size(); ++g) {
    const size_t f = size_t(vnext.parent[g]);
    const Index r = Index(vnext.rank[g]);
    if (r >= child_count[f] || C.face_size(first_child[f] + r) != vnext.level.face_size(Index(g)))
      throw Error("adaptive refinement: a face-varying channel's child faces are not the mesh's (a split that "
                  "divides a face of the UV islands differently); refine uniformly instead");
    faces.push_back(first_child[f] + r);
  }
  // Those faces as a level: vertices in the piece's order, the piece's tags.
  std::vector<Index> local(size_t(C.vertex_count), kNone), used;
  for (Index i : faces)
    for (Index u : C.face(i)) local[size_t(u)] = 0;
  for (Index u = 0; u < C.vertex_count; ++u)
    if (local[size_t(u)] == 0) local[size_t(u)] = Index(used.size()), used.push_back(u);
  std::vector<Index> offsets{0}, corners;
  for (Index i : faces) {
    for (Index u : C.face(i)) corners.push_back(local[size_t(u)]);
    offsets.push_back(Index(corners.size()));
  }
  AdaptiveValueStage n;
  Level& N = n.level;
  if (last) {
    N.vertex_count = Index(used.size());
    N.face_offsets.assign(offsets.begin(), offsets.end());
    N.face_vertices.assign(corners.begin(), corners.end());
  } else {
    N = build_level(Index(used.size()), offsets, corners);
  }
  if (!last && !C.edge_sharpness.empty()) {
    N.edge_sharpness.assign(size_t(N.edge_count()), 0.f);
    for (size_t g = 0; g < faces.size(); ++g)
      for (int k = 0; k < N.face_size(Index(g)); ++k)
        N.edge_sharpness[size_t(N.face_edge_list(Index(g))[k])] = C.edge_sharp(C.face_edge_list(faces[g])[k]);
  }
  if (!last && !C.vertex_sharpness.empty())
    for (Index u : used) N.vertex_sharpness.push_back(C.vertex_sharp(u));
  if (!last && !C.face_hole.empty())
    for (Index i : faces) N.face_hole.push_back(C.face_hole[size_t(i)]);

  const int components = channel.components;
  std::vector<double> piece_values;
  piece_values.reserve(piece.base_vertex.size() * size_t(components));
  for (Index v : piece.base_vertex)
    piece_values.insert(piece_values.end(), s.values.begin() + std::ptrdiff_t(components) * v,
                        s.values.begin() + std::ptrdiff_t(components) * (v + 1));
  n.values = h.stencils[0].apply_rows(piece_values, used, components);

  s.vertex_child.assign(size_t(L.vertex_count), kNone);
  s.edge_child.assign(size_t(L.edge_count()), kNone);
  const Level& P = h.levels[0];
  for (size_t c = 0; c < used.size(); ++c) {
    const Index from = o.parent[size_t(used[c])];
    if (o.kind[size_t(used[c])] == OriginKind::Vertex) {
      s.vertex_child[size_t(piece.base_vertex[size_t(from)])] = Index(c);
    } else if (o.kind[size_t(used[c])] == OriginKind::Edge) {
      const Index a = piece.base_vertex[size_t(P.edge_vertices[size_t(2 * from)])],
                  b = piece.base_vertex[size_t(P.edge_vertices[size_t(2 * from + 1)])];
      s.edge_child[size_t(find_edge(L, a, b))] = Index(c);
    }
  }
  return n;
}

}  // namespace subdiv
