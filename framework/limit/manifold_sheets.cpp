#include "framework/limit/manifold_sheets.h"

#include <fmt/format.h>
#include <numeric>

#include "framework/features/base_tags.h"
#include "framework/features/sharpness.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// Union-find over the face corners: corners that a manifold edge joins are one sheet vertex.
struct CornerSets {
  std::vector<Index> parent;
  explicit CornerSets(Index corners) : parent(size_t(corners)) { std::iota(parent.begin(), parent.end(), 0); }
  Index find(Index c) {
    while (parent[size_t(c)] != c) c = parent[size_t(c)] = parent[size_t(parent[size_t(c)])];
    return c;
  }
  void join(Index a, Index b) { parent[size_t(find(a))] = find(b); }
};

// The corner of face f whose edge (to the next corner) is e.
Index corner_of_edge(const Level& L, Index f, Index e) {
  for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c)
    if (L.face_edges[c] == e) return c;
  throw Error("internal: a face does not hold its own edge");
}

Index next_corner(const Level& L, Index f, Index c) { return c + 1 == L.face_offsets[f + 1] ? L.face_offsets[f] : c + 1; }

// Joins, across every manifold edge, the two faces' corners at each of its ends: f0 runs
// the edge a -> b, f1 runs it b -> a (level.h's convention for edge_faces).
CornerSets fans(const Level& L) {
  CornerSets sets(L.corner_count());
  for (Index e = 0; e < L.edge_count(); ++e) {
    if (L.non_manifold_edge(e) || L.edge_on_boundary(e)) continue;
    const Index f0 = L.edge_faces[2 * e], f1 = L.edge_faces[2 * e + 1];
    const Index a0 = corner_of_edge(L, f0, e), b1 = corner_of_edge(L, f1, e);
    sets.join(a0, next_corner(L, f1, b1));
    sets.join(next_corner(L, f0, a0), b1);
  }
  return sets;
}

// The base level with the tags it takes before refinement (base_tags.h), in Far's order.
Level tagged_base(const Level& base, const FeatureOptions& features) {
  Level L = base;
  tag_base_level(L, features.boundary);
  return L;
}

// A vertex left smooth on a non-manifold crease takes the crease rule only while its two
// non-manifold edges are its only sharp ones; with more, it is a corner for every sheet.
// Semi-sharp edges there change the rule as they decay, which the cut sheets would each see
// differently; so would Chaikin's rule reading the sharpness of edges in other fans.
void check_cut_vertex(const Level& L, Index v, const FeatureOptions& features) {
  for (Index e : L.ring_edges(v)) {
    if (!is_semi_sharp(L.edge_sharp(e))) continue;
    if (L.vertex_sharp(v) < kInfinitelySharp || features.crease_method == CreaseMethod::Chaikin)
      throw Error(fmt::format("vertex {}: a semi-sharp edge ends at this non-manifold vertex, where the fans of faces "
                              "meet; its rule there changes as the sharpness decays, which limit evaluation of "
                              "the fans apart does not follow yet (make the edge sharp or smooth, or split the "
                              "mesh into manifold parts)", v));
  }
}

void set_corner_if_more_creases(Level& L, Index v) {
  int sharp = 0;
  for (Index e : L.ring_edges(v)) sharp += L.edge_sharp(e) >= kInfinitelySharp;
  if (sharp <= 2) return;
  if (L.vertex_sharpness.empty()) L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
  L.vertex_sharpness[size_t(v)] = kInfinitelySharp;
}

void copy_tags(const Level& from, ManifoldSheets& to) {
  Level& S = to.level;
  S.face_hole = from.face_hole;
  if (!from.edge_sharpness.empty()) {
    S.edge_sharpness.assign(size_t(S.edge_count()), 0.f);
    for (Index c = 0; c < S.corner_count(); ++c)
      S.edge_sharpness[size_t(S.face_edges[c])] = from.edge_sharpness[size_t(from.face_edges[c])];
  }
  if (!from.vertex_sharpness.empty()) {
    S.vertex_sharpness.resize(size_t(S.vertex_count));
    for (Index v = 0; v < S.vertex_count; ++v)
      S.vertex_sharpness[size_t(v)] = from.vertex_sharpness[size_t(to.origin[size_t(v)])];
  }
}

void check_sheets_manifold(const ManifoldSheets& sheets) {
  const Level& S = sheets.level;
  if (S.manifold()) return;
  Index v = 0;
  while (v < S.vertex_count && !S.non_manifold_vertex(v)) ++v;
  throw Error(fmt::format("the mesh is non-manifold at vertex {} in a way limit evaluation does not take (a face "
                          "that repeats the vertex, or an edge from it to itself): remove the repeated corner",
                          v < S.vertex_count ? sheets.origin[size_t(v)] : Index(0)));
}

}  // namespace

ManifoldSheets manifold_sheets(const Level& base, const FeatureOptions& features) {
  Level tagged = tagged_base(base, features);
  for (Index v = 0; v < tagged.vertex_count; ++v)
    if (tagged.non_manifold_vertex(v)) {
      set_corner_if_more_creases(tagged, v);
      check_cut_vertex(tagged, v, features);
    }
  CornerSets sets = fans(tagged);
  // Sheet vertices numbered by their first corner, so the order follows the faces'.
  std::vector<Index> sheet_of_root(size_t(tagged.corner_count()), kNone);
  std::vector<Index> sheet_vertices(size_t(tagged.corner_count()));
  ManifoldSheets out;
  for (Index c = 0; c < tagged.corner_count(); ++c) {
    Index& id = sheet_of_root[size_t(sets.find(c))];
    if (id == kNone) id = Index(out.origin.size()), out.origin.push_back(tagged.face_vertices[c]);
    sheet_vertices[size_t(c)] = id;
  }
  out.level = build_level(Index(out.origin.size()), tagged.face_offsets, sheet_vertices);
  check_sheets_manifold(out);
  copy_tags(tagged, out);
  return out;
}

}  // namespace subdiv
