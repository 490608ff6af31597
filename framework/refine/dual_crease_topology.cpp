#include "framework/refine/dual_crease_topology.h"

#include <algorithm>

#include "framework/features/dual_features.h"
#include "framework/features/sharpness.h"

namespace subdiv {
namespace {

Index next_corner(const Level& L, Index f, Index c) { return c + 1 == L.face_offsets[f + 1] ? L.face_offsets[f] : c + 1; }
Index prev_corner(const Level& L, Index f, Index c) { return c == L.face_offsets[f] ? L.face_offsets[f + 1] - 1 : c - 1; }

// The corner of f whose outgoing edge is e.
Index corner_leaving(const Level& L, Index f, Index e) {
  for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c)
    if (L.face_edges[c] == e) return c;
  return kNone;
}

class PointMap {
public:
  explicit PointMap(const Level& L) : L_(L) {
    sharp_.resize(size_t(L.edge_count()));
    for (Index e = 0; e < L.edge_count(); ++e) sharp_[e] = dual_sharp_edge(L, e);
    collapse_.resize(size_t(L.vertex_count));
    for (Index v = 0; v < L.vertex_count; ++v) collapse_[v] = dual_collapses(L, v);
    corner_point_.assign(size_t(L.corner_count()), kNone);
    edge_point_.assign(2 * size_t(L.edge_count()), kNone);
    vertex_point_.assign(size_t(L.vertex_count), kNone);
    face_of_.resize(size_t(L.corner_count()));
    for (Index f = 0; f < L.face_count(); ++f)
      std::fill(face_of_.begin() + L.face_offsets[f], face_of_.begin() + L.face_offsets[f + 1], f);
  }

  bool sharp(Index e) const { return sharp_[e]; }
  bool collapses(Index v) const { return collapse_[v]; }
  // Whether corner c gives two points (both its face edges sharp, its vertex no corner).
  bool split(Index c) const {
    const Index f = face_of_[c];
    return !collapse_[L_.face_vertices[c]] && sharp_[L_.face_edges[c]] && sharp_[L_.face_edges[prev_corner(L_, f, c)]];
  }
  // The child point of corner c on the side of its arriving edge (`in`) or its leaving edge.
  Index point(Index c, bool in) {
    const Index f = face_of_[c], v = L_.face_vertices[c];
    const Index out_e = L_.face_edges[c], in_e = L_.face_edges[prev_corner(L_, f, c)];
    Index* slot;
    if (collapse_[v]) slot = &vertex_point_[v];
    else if (sharp_[out_e] && !(in && sharp_[in_e])) slot = &edge_point_[2 * out_e + (L_.edge_vertices[2 * out_e] == v ? 0 : 1)];
    else if (sharp_[in_e]) slot = &edge_point_[2 * in_e + (L_.edge_vertices[2 * in_e] == v ? 0 : 1)];
    else slot = &corner_point_[c];
    if (*slot == kNone) {
      *slot = Index(origins.kind.size());
      origins.kind.push_back(OriginKind::Corner);
      origins.parent.push_back(f);
      origins.local.push_back(LocalIndex(c - L_.face_offsets[f]));
      origins.corner_side.push_back(std::uint8_t(in && split(c) ? 1 : 0));
    }
    return *slot;
  }
  Index edge_point(Index e, Index v) const { return edge_point_[2 * e + (L_.edge_vertices[2 * e] == v ? 0 : 1)]; }
  Index vertex_point(Index v) const { return vertex_point_[v]; }

  ChildOrigins origins;

private:
  const Level& L_;
  std::vector<std::uint8_t> sharp_, collapse_;
  std::vector<Index> corner_point_, edge_point_, vertex_point_, face_of_;
};

// Appends a face with consecutive repeats (cyclically) dropped, if 3 or more corners remain.
bool add_face(std::vector<Index>& offsets, std::vector<Index>& verts, std::vector<Index> face) {
  std::vector<Index> kept;
  for (size_t i = 0; i < face.size(); ++i)
    if (face[i] != face[(i + 1) % face.size()]) kept.push_back(face[i]);
  if (kept.size() < 3) return false;
  verts.insert(verts.end(), kept.begin(), kept.end());
  offsets.push_back(Index(verts.size()));
  return true;
}

// The corner of ring face j of v.
Index ring_corner(const Level& L, Index v, Index j) {
  const Index i = L.vertex_face_offsets[v] + j;
  return L.face_offsets[L.vertex_faces[i]] + L.vertex_face_corner[i];
}

// Sector faces of v: ring face j leaves v along ring edge j and arrives along ring edge j + 1
// (dual_topology.cpp); a sector runs from a sharp ring edge to the next one.
// A non-manifold vertex has no CCW ring to cut into sectors: it gets no face (a gap, as in
// the plain split), while the rest of the level keeps its creases.
void add_sector_faces(const Level& L, PointMap& pm, Index v, std::vector<Index>& offsets, std::vector<Index>& verts,
                      Index* skipped) {
  const Index n = L.incident_face_count(v);
  if (n == 0 || pm.collapses(v)) return;
  if (L.non_manifold_vertex(v)) {
    ++*skipped;
    return;
  }
  const auto ring = L.ring_edges(v);
  const bool boundary = L.on_boundary(v);
  std::vector<Index> cuts;  // ring edges that start a sector
  for (Index j = 0; j < n; ++j)
    if (pm.sharp(ring[j])) cuts.push_back(j);
  if (cuts.empty()) {  // a smooth interior vertex: its V-face
    std::vector<Index> face;
    for (Index j = 0; j < n; ++j) face.push_back(pm.point(ring_corner(L, v, j), false));
    add_face(offsets, verts, face);
    return;
  }
  for (size_t s = 0; s < cuts.size(); ++s) {
    const Index first = cuts[s];
    const Index last = s + 1 < cuts.size() ? cuts[s + 1] : (boundary ? n : cuts[0] + n);  // exclusive
    std::vector<Index> face;
    for (Index j = first; j < last; ++j) {
      const Index c = ring_corner(L, v, j % n);
      if (j == first) face.push_back(pm.point(c, false));
      if (j + 1 == last) face.push_back(pm.point(c, true));
      if (j != first && j + 1 != last) face.push_back(pm.point(c, false));
    }
    add_face(offsets, verts, face);
  }
}

// Sharpness of the child edges along and across the crease, and of collapsed tagged vertices.
// A child edge along sharp edge e = (v, w) lies in e's middle: it takes the mean of e's child
// sharpness at both ends; the edge across a crease vertex v, the mean of its two sharp edges'
// child sharpness at v (features/sharpness.h: uniform decay, or Chaikin's, which also reads
// the other semi-sharp edges at v). The uniform values go to the child, Chaikin's aside.
void tag_child(const Level& L, PointMap& pm, DualFeatureSplit& out) {
  Level& C = out.child;
  if (!L.edge_sharpness.empty()) {
    C.edge_sharpness.assign(size_t(C.edge_count()), 0.f);
    std::vector<float> averaged(C.edge_sharpness.size(), 0.f);
    auto at = [&](Index e, Index v, CreaseMethod m) { return child_edge_sharpness(L, e, v, m); };
    auto tag = [&](Index a, Index b, float uniform, float by_chaikin) {
      const Index e = a == kNone || b == kNone ? kNone : find_edge(C, a, b);
      if (e != kNone && !C.edge_on_boundary(e)) C.edge_sharpness[e] = uniform, averaged[e] = by_chaikin;
    };
    for (Index e = 0; e < L.edge_count(); ++e) {
      if (L.edge_on_boundary(e) || !pm.sharp(e)) continue;
      const Index f = L.edge_faces[2 * e], c = corner_leaving(L, f, e);
      const Index v = L.edge_vertices[2 * e], w = L.edge_vertices[2 * e + 1];
      auto mean = [&](CreaseMethod m) { return 0.5f * (at(e, v, m) + at(e, w, m)); };
      tag(pm.point(c, false), pm.point(next_corner(L, f, c), true), mean(CreaseMethod::Uniform), mean(CreaseMethod::Chaikin));
    }
    for (Index v = 0; v < L.vertex_count; ++v) {
      if (pm.collapses(v) || L.on_boundary(v) || L.non_manifold_vertex(v)) continue;
      Index sharp[2], count = 0;
      for (Index e : L.ring_edges(v))
        if (pm.sharp(e) && count < 2) sharp[count++] = e;
      if (count != 2) continue;
      auto mean = [&](CreaseMethod m) { return 0.5f * (at(sharp[0], v, m) + at(sharp[1], v, m)); };
      tag(pm.edge_point(sharp[0], v), pm.edge_point(sharp[1], v), mean(CreaseMethod::Uniform), mean(CreaseMethod::Chaikin));
    }
    if (averaged != C.edge_sharpness) out.averaged_edge_sharpness = std::move(averaged);
  }
  if (!L.vertex_sharpness.empty()) {
    C.vertex_sharpness.assign(size_t(C.vertex_count), 0.f);
    for (Index v = 0; v < L.vertex_count; ++v)
      if (pm.collapses(v) && pm.vertex_point(v) != kNone)
        C.vertex_sharpness[pm.vertex_point(v)] = decremented_sharpness(L.vertex_sharpness[v]);
  }
}

}  // namespace

DualFeatureSplit dual_feature_split(const Level& L, bool full, Index* skipped_vertices) {
  Index skipped = 0;
  PointMap pm(L);
  std::vector<Index> offsets{0}, verts;
  // F-faces.
  for (Index f = 0; f < L.face_count(); ++f) {
    std::vector<Index> face;
    for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c) {
      if (pm.split(c)) face.push_back(pm.point(c, true));
      face.push_back(pm.point(c, false));
    }
    if (!add_face(offsets, verts, face)) {  // cannot happen for faces of 3+ distinct vertices
      verts.insert(verts.end(), face.begin(), face.end());
      offsets.push_back(Index(verts.size()));
    }
  }
  const Index f_faces = L.face_count();
  // E-faces of smooth interior edges: f0 runs a -> b, f1 runs b -> a.
  for (Index e = 0; e < L.edge_count(); ++e) {
    if (pm.sharp(e)) continue;
    const Index f0 = L.edge_faces[2 * e], f1 = L.edge_faces[2 * e + 1];
    const Index f0a = corner_leaving(L, f0, e), f1b = corner_leaving(L, f1, e);
    add_face(offsets, verts,
             {pm.point(next_corner(L, f1, f1b), true), pm.point(f1b, false), pm.point(next_corner(L, f0, f0a), true),
              pm.point(f0a, false)});
  }
  for (Index v = 0; v < L.vertex_count; ++v) add_sector_faces(L, pm, v, offsets, verts, &skipped);
  if (skipped_vertices) *skipped_vertices = skipped;

  DualFeatureSplit out;
  const Index points = Index(pm.origins.kind.size());
  if (full) {
    out.child = build_level(points, offsets, verts);
    tag_child(L, pm, out);
  } else {
    out.child.vertex_count = points;
    out.child.face_offsets.assign(offsets.begin(), offsets.end());
    out.child.face_vertices.assign(verts.begin(), verts.end());
  }
  out.origins = std::move(pm.origins);
  out.origins.parent_face.assign(size_t(out.child.face_count()), kNone);
  for (Index f = 0; f < f_faces; ++f) out.origins.parent_face[f] = f;
  return out;
}

}  // namespace subdiv
