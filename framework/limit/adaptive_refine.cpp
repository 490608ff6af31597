#include "framework/limit/adaptive_refine.h"

#include <fmt/format.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// What a regular patch may not contain: a vertex whose faces are not the regular number
// (inside: 4 quads or 6 triangles; on a boundary: 2 or 3, or a boundary corner of 1 or 2
// when corners are sharp), a non-manifold vertex, a crease through it, a sharp vertex.
bool feature_vertex(const Level& L, Index v, bool triangles, const FeatureOptions& features) {
  if (L.non_manifold_vertex(v) || L.vertex_sharp(v) > 0) return true;
  for (Index e : L.ring_edges(v))
    if (L.edge_sharp(e) > 0 && !L.edge_on_boundary(e)) return true;
  const int faces = L.incident_face_count(v);
  if (!L.on_boundary(v)) return faces != (triangles ? 6 : 4);
  if (faces == (triangles ? 3 : 2)) return false;
  return !(faces == (triangles ? 2 : 1) && features.boundary == BoundaryInterpolation::EdgesAndCorners);
}

struct Adaptive {
  const Hierarchy& h;
  int levels;
  std::vector<std::vector<char>> refined;       // per level, per face
  std::vector<std::vector<Index>> vertex_child;  // per level < L, per vertex: its child vertex
  std::vector<std::vector<Index>> edge_child;    // per level < L, per edge: its middle vertex
  std::vector<std::vector<Index>> finest;        // per level, per vertex: its descendant at level L
  std::vector<std::vector<std::vector<Index>>> children;  // per level < L, per face: its child faces
  AdaptiveMesh out;

  // The vertices along edge (a, b) of level l from a up to b (b excluded), at the finest
  // level either side of the edge was refined to.
  void chain(int l, Index a, Index b, std::vector<Index>& corners) const {
    const Level& L = h.levels[size_t(l)];
    if (l < levels) {
      const Index e = find_edge(L, a, b);
      bool split = false;
      for (int k = 0; k < L.edge_face_count(e); ++k)
        split = split || refined[size_t(l)][size_t(L.edge_faces[size_t(2 * e + k)])];
      if (split) {
        const Index m = edge_child[size_t(l)][size_t(e)];
        chain(l + 1, vertex_child[size_t(l)][size_t(a)], m, corners);
        chain(l + 1, m, vertex_child[size_t(l)][size_t(b)], corners);
        return;
      }
    }
    corners.push_back(finest[size_t(l)][size_t(a)]);
  }

  void emit(int l, Index f, Index base_face) {
    const Level& L = h.levels[size_t(l)];
    if (refined[size_t(l)][size_t(f)]) {
      for (Index c : children[size_t(l)][size_t(f)]) emit(l + 1, c, base_face);
      return;
    }
    const auto fv = L.face(f);
    for (size_t k = 0; k < fv.size(); ++k) chain(l, fv[k], fv[(k + 1) % fv.size()], out.face_vertices);
    out.face_offsets.push_back(Index(out.face_vertices.size()));
    out.face_level.push_back(l);
    out.base_face.push_back(base_face);
  }
};

}  // namespace

AdaptiveMesh refine_adaptive(const Scheme& scheme, const Level& base, std::span<const double> positions, int levels,
                             const FeatureOptions& features, bool limit) {
  const SplitKind split = scheme.split();
  if (split != SplitKind::Quad && split != SplitKind::Triangle)
    throw Error(fmt::format("scheme '{}': adaptive refinement is implemented for the binary quad and triangle splits "
                            "only so far",
                            scheme.name));
  if (levels < 0 || levels > 12) throw Error(fmt::format("adaptive refinement to level {}: give 0 to 12", levels));
  const bool triangles = split == SplitKind::Triangle;
  RefineOptions ro;
  ro.levels = levels;
  ro.features = features;
  const Hierarchy h = refine(scheme, base, ro);
  Adaptive a{h, levels, {}, {}, {}, {}, {}, {}};
  for (int l = 0; l < levels; ++l) {
    const Level& L = h.levels[size_t(l)];
    const ChildOrigins& o = h.origins[size_t(l)];
    std::vector<Index> vc(size_t(L.vertex_count), kNone), ec(size_t(L.edge_count()), kNone);
    for (size_t c = 0; c < o.kind.size(); ++c) {
      if (o.kind[c] == OriginKind::Vertex) vc[size_t(o.parent[c])] = Index(c);
      if (o.kind[c] == OriginKind::Edge) ec[size_t(o.parent[c])] = Index(c);
    }
    std::vector<char> feature(size_t(L.vertex_count));
    for (Index v = 0; v < L.vertex_count; ++v) feature[size_t(v)] = feature_vertex(L, v, triangles, features);
    std::vector<char> refine_face(size_t(L.face_count()), 0);
    for (Index f = 0; f < L.face_count(); ++f) {
      if (L.is_hole(f)) continue;
      bool irregular = L.face_size(f) != (triangles ? 3 : 4);
      for (Index v : L.face(f)) irregular = irregular || feature[size_t(v)];
      refine_face[size_t(f)] = irregular;
    }
    a.refined.push_back(std::move(refine_face));
    std::vector<std::vector<Index>> children(size_t(L.face_count()));
    for (size_t c = 0; c < o.parent_face.size(); ++c)
      if (o.parent_face[c] != kNone) children[size_t(o.parent_face[c])].push_back(Index(c));
    a.children.push_back(std::move(children));
    a.vertex_child.push_back(std::move(vc));
    a.edge_child.push_back(std::move(ec));
  }
  a.refined.emplace_back(size_t(h.levels.back().face_count()), 0);
  // Each vertex's descendant at level L: the finest level's own vertices, then back up.
  a.finest.resize(size_t(levels) + 1);
  const Index fine_count = h.levels.back().vertex_count;
  for (Index v = 0; v < fine_count; ++v) a.finest.back().push_back(v);
  for (int l = levels; l-- > 0;) {
    for (Index c : a.vertex_child[size_t(l)]) a.finest[size_t(l)].push_back(a.finest[size_t(l) + 1][size_t(c)]);
  }
  for (Index f = 0; f < base.face_count(); ++f)
    if (!base.is_hole(f)) a.emit(0, f, f);
  // Positions of the level-L vertices used, numbered in order of first use.
  std::vector<double> fine(positions.begin(), positions.end());
  for (int l = 0; l < levels; ++l) fine = h.stencils[size_t(l)].apply(fine, 3);
  if (limit) {
    LimitOptions lo;
    lo.features = features;
    lo.first_step = levels;
    fine = limit_positions(scheme, h.levels.back(), fine, lo).positions;
  }
  std::vector<Index> number(size_t(fine_count), kNone);
  AdaptiveMesh& out = a.out;
  for (Index& v : out.face_vertices) {
    if (number[size_t(v)] == kNone) {
      number[size_t(v)] = Index(out.positions.size() / 3);
      out.positions.insert(out.positions.end(), fine.begin() + 3 * size_t(v), fine.begin() + 3 * size_t(v) + 3);
    }
    v = number[size_t(v)];
  }
  out.uniform_faces = h.levels.back().face_count();
  return std::move(a.out);
}

}  // namespace subdiv
