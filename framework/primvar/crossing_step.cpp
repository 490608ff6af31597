#include "framework/primvar/crossing_step.h"

#include <algorithm>
#include <fmt/format.h>
#include <unordered_map>

#include "framework/util/error.h"

namespace subdiv {
namespace {

// Where the new points of a step lie among the parent's elements.
struct Places {
  const Level& parent;
  const ChildOrigins& origins;
  std::vector<int> points_per_edge;  // new points on each parent edge (sqrt3 trisection: 2)

  Places(const Level& p, const ChildOrigins& o) : parent(p), origins(o), points_per_edge(size_t(p.edge_count()), 0) {
    for (size_t x = 0; x < o.kind.size(); ++x)
      if (o.kind[x] == OriginKind::Edge)
        points_per_edge[o.parent[x]] = std::max(points_per_edge[o.parent[x]], int(o.local[x]) + 1);
  }

  // The position of edge e within face f's edge list, or -1.
  int edge_slot(Index f, Index e) const {
    const auto edges = parent.face_edge_list(f);
    const auto it = std::find(edges.begin(), edges.end(), e);
    return it == edges.end() ? -1 : int(it - edges.begin());
  }
  int vertex_slot(Index f, Index v) const {
    const auto vs = parent.face(f);
    const auto it = std::find(vs.begin(), vs.end(), v);
    return it == vs.end() ? -1 : int(it - vs.begin());
  }

  // The parent faces new point x lies in (on the boundary of, for vertices and edges).
  std::span<const Index> faces_holding(Index x) const {
    const Index p = origins.parent[x];
    switch (origins.kind[x]) {
      case OriginKind::Vertex: return parent.ring_faces(p);
      case OriginKind::Edge: return parent.faces_of_edge(p);
      default: return {&origins.parent[x], 1};
    }
  }
  bool holds(Index f, Index x) const {
    const Index p = origins.parent[x];
    switch (origins.kind[x]) {
      case OriginKind::Vertex: return vertex_slot(f, p) >= 0;
      case OriginKind::Edge: return edge_slot(f, p) >= 0;
      default: return f == p;
    }
  }

  // The parent edge that new points a and b both lie on, or kNone.
  Index common_edge(Index a, Index b) const {
    const OriginKind ka = origins.kind[a], kb = origins.kind[b];
    const Index pa = origins.parent[a], pb = origins.parent[b];
    if (ka == OriginKind::Edge && kb == OriginKind::Edge) return pa == pb ? pa : kNone;
    if (ka == OriginKind::Vertex && kb == OriginKind::Vertex) return find_edge(parent, pa, pb);
    if (ka == OriginKind::Edge && kb == OriginKind::Vertex) return common_edge(b, a);
    if (ka == OriginKind::Vertex && kb == OriginKind::Edge)
      return parent.edge_vertices[2 * pb] == pa || parent.edge_vertices[2 * pb + 1] == pa ? pb : kNone;
    return kNone;
  }
  // Where new point x lies along parent edge e, 0 at its first vertex and 1 at its second.
  double place_along(Index x, Index e) const {
    if (origins.kind[x] == OriginKind::Vertex) return origins.parent[x] == parent.edge_vertices[2 * e] ? 0.0 : 1.0;
    return (origins.local[x] + 1.0) / (points_per_edge[e] + 1.0);
  }
  bool runs_forward(Index f, Index e) const {
    const int slot = edge_slot(f, e);
    return slot >= 0 && parent.face(f)[slot] == parent.edge_vertices[2 * e];
  }

  // The parent face that holds both new points, on the left of a -> b (a new face's side of
  // its edge a -> b, faces being CCW) when they lie on a common parent edge; kNone if none.
  Index face_holding_both(Index a, Index b) const {
    Index first = kNone;
    bool several = false;
    for (Index f : faces_holding(a))
      if (holds(f, b)) {
        several = several || (first != kNone && f != first);
        if (first == kNone) first = f;
      }
    const Index e = several ? common_edge(a, b) : kNone;
    if (e == kNone) return first;
    const bool forward = place_along(b, e) > place_along(a, e);
    for (Index f : faces_holding(a))
      if (holds(f, b) && runs_forward(f, e) == forward) return f;
    return first;
  }
};

// Stage 1: the parent face each new face corner takes its value in (crossing_step.h).
std::vector<Index> corner_faces(const Places& places, const Level& child) {
  std::vector<Index> out(child.face_vertices.size(), kNone);
  for (Index cf = 0; cf < child.face_count(); ++cf) {
    const auto corners = child.face(cf);
    const int k = int(corners.size());
    const Index parent_face = size_t(cf) < places.origins.parent_face.size() ? places.origins.parent_face[cf] : kNone;
    for (int i = 0; i < k; ++i) {
      const Index x = corners[i], before = corners[(i + k - 1) % k], after = corners[(i + 1) % k];
      Index f = parent_face != kNone && places.holds(parent_face, x) ? parent_face : kNone;
      if (f == kNone) f = places.face_holding_both(before, x);
      if (f == kNone) f = places.face_holding_both(x, after);
      if (f == kNone && !places.faces_holding(x).empty()) f = places.faces_holding(x)[0];
      if (f == kNone)
        throw Error(fmt::format("face-varying data: new point {} of face {} lies in no old face, so it has no value "
                                "(the split's origins are inconsistent; report it with the mesh)", x, cf));
      out[size_t(child.face_offsets[cf] + i)] = f;
    }
  }
  return out;
}

// Stage 2: new point x, valued in parent face f, as a new point of the value mesh.
struct ValueOrigin {
  OriginKind kind;
  Index parent;
  LocalIndex local;
};

ValueOrigin value_origin(const Places& places, const Level& values, Index x, Index f) {
  const OriginKind kind = places.origins.kind[x];
  const Index p = places.origins.parent[x];
  const LocalIndex local = places.origins.local[x];
  if (kind == OriginKind::Vertex) return {kind, values.face(f)[places.vertex_slot(f, p)], 0};
  if (kind != OriginKind::Edge) return {kind, p, local};
  // The same place along the value edge, whose first vertex may be the other end.
  const int slot = places.edge_slot(f, p);
  const Index value_edge = values.face_edge_list(f)[slot];
  const Level& L = places.parent;
  const bool face_runs_forward = L.face(f)[slot] == L.edge_vertices[2 * p];
  const Index value_at_first = values.face(f)[face_runs_forward ? slot : (slot + 1) % L.face_size(f)];
  const bool same_way = values.edge_vertices[2 * value_edge] == value_at_first;
  return {kind, value_edge, same_way ? local : LocalIndex(places.points_per_edge[p] - 1 - local)};
}

}  // namespace

bool corners_in_parent_faces(const Level& parent, const ChildOrigins& origins, const Level& child) {
  const Places places(parent, origins);
  for (Index cf = 0; cf < child.face_count(); ++cf) {
    if (size_t(cf) >= origins.parent_face.size() || origins.parent_face[cf] == kNone) return false;
    for (Index x : child.face(cf))
      if (!places.holds(origins.parent_face[cf], x)) return false;
  }
  return true;
}

CrossingStep crossing_step(const SchemeRun& run, const Level& vertices, Level values, const ChildOrigins& origins,
                           const Level& child, bool features_refined, std::span<const double> parent_values,
                           int components, const RefineOptions& options) {
  const Places places(vertices, origins);
  const std::vector<Index> faces = corner_faces(places, child);
  CrossingStep out;
  ChildOrigins value_origins;
  std::unordered_map<std::uint64_t, Index> index_of;  // (kind, parent, local) -> new value
  for (size_t c = 0; c < faces.size(); ++c) {
    const Index x = child.face_vertices[c];
    const ValueOrigin o = value_origin(places, values, x, faces[c]);
    const std::uint64_t key = std::uint64_t(o.kind) << 56 | std::uint64_t(o.local) << 40 | std::uint32_t(o.parent);
    auto [it, added] = index_of.emplace(key, Index(out.vertex_of.size()));
    if (added) {
      value_origins.kind.push_back(o.kind), value_origins.parent.push_back(o.parent);
      value_origins.local.push_back(o.local);
      out.vertex_of.push_back(x);
      out.value_of_vertex_origin.push_back(o.kind == OriginKind::Vertex ? o.parent : kNone);
    }
    out.level.indices.push_back(it->second);
  }
  value_origins.parent_face = origins.parent_face;
  // Stage 3: the scheme's rows on the value mesh, for exactly these new values.
  Level value_child = build_level(Index(out.vertex_of.size()), child.face_offsets, out.level.indices);
  value_child.face_hole = child.face_hole;
  Hierarchy on_values;
  on_values.levels = {std::move(values), std::move(value_child)};
  on_values.origins = {std::move(value_origins)};
  on_values.features_refined = {features_refined};
  out.level.values = step_values(std::span(&run, 1), on_values, 0, parent_values, components, options);
  out.values = std::move(on_values.levels[1]);
  return out;
}

}  // namespace subdiv
