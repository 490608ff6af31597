#include "framework/limit/adaptive_face_varying.h"

#include <algorithm>
#include <fmt/format.h>

#include "framework/engine/mesh_pieces.h"
#include "framework/features/sharpness.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

void check_same_faces(const Level& vertices, const Level& values, const char* what) {
  bool same = vertices.face_count() == values.face_count();
  for (Index f = 0; same && f < vertices.face_count(); ++f) same = vertices.face_size(f) == values.face_size(f);
  if (!same)
    throw Error(fmt::format("adaptive refinement: a face-varying channel's {} are not the mesh's faces ({} against "
                            "{}); the channel's value mesh must have the mesh's faces, in the same order",
                            what, values.face_count(), vertices.face_count()));
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
  check_same_faces(base, *channel.level, "faces");
  return {*channel.level, {channel.values.begin(), channel.values.end()}, {}, {}};
}

AdaptiveValueStage refine_value_stage(const Scheme& scheme, const AdaptiveStage& vs, const AdaptiveStage& vnext,
                                      AdaptiveValueStage& s, const AdaptiveValueMesh& channel, int ghost_rings,
                                      RefineOptions options) {
  tag_linear(s.level, vs, channel);
  const Level& L = s.level;
  std::vector<int> owner(size_t(L.face_count()), 1);
  for (Index f = 0; f < L.face_count(); ++f)
    if (vs.computed[size_t(f)]) owner[size_t(f)] = 0;
  const MeshPiece piece = cut_piece(L, owner, 0, ghost_rings);
  options.features.boundary = BoundaryInterpolation::EdgesOnly;  // the corners are tagged
  const Hierarchy h = refine(scheme, piece.level, options);
  std::vector<int> piece_owner;
  for (Index f : piece.base_face) piece_owner.push_back(owner[size_t(f)]);
  const MeshPiece kept = cut_piece(h.levels[1], finest_face_owners(h, piece_owner), 0, 0);
  const ChildOrigins& o = h.origins[0];
  const int C = channel.components;

  AdaptiveValueStage n;
  n.level = kept.level;
  check_same_faces(vnext.level, n.level, "child faces");
  for (Index g = 0; g < n.level.face_count(); ++g) {
    const Index f = piece.base_face[size_t(o.parent_face[size_t(kept.base_face[size_t(g)])])];
    const auto& children = vs.children[size_t(f)];
    if (std::find(children.begin(), children.end(), g) == children.end())
      throw Error("adaptive refinement: a face-varying channel's child faces are not the mesh's (a split that "
                  "orders its children by more than their parent face); refine uniformly instead");
  }
  std::vector<double> piece_values;
  for (Index v : piece.base_vertex)
    piece_values.insert(piece_values.end(), s.values.begin() + std::ptrdiff_t(C) * v,
                        s.values.begin() + std::ptrdiff_t(C) * (v + 1));
  n.values = gather_tuples(h.stencils[0].apply(piece_values, C), C, kept.base_vertex);

  s.vertex_child.assign(size_t(L.vertex_count), kNone);
  s.edge_child.assign(size_t(L.edge_count()), kNone);
  const Level& P = piece.level;
  for (Index c = 0; c < n.level.vertex_count; ++c) {
    const Index hc = kept.base_vertex[size_t(c)], from = o.parent[size_t(hc)];
    if (o.kind[size_t(hc)] == OriginKind::Vertex) {
      s.vertex_child[size_t(piece.base_vertex[size_t(from)])] = c;
    } else if (o.kind[size_t(hc)] == OriginKind::Edge) {
      const Index a = piece.base_vertex[size_t(P.edge_vertices[size_t(2 * from)])],
                  b = piece.base_vertex[size_t(P.edge_vertices[size_t(2 * from + 1)])];
      s.edge_child[size_t(find_edge(L, a, b))] = c;
    }
  }
  return n;
}

}  // namespace subdiv
