#include "framework/interpolation/dual_limits.h"

#include <cmath>
#include <fmt/format.h>
#include <cstdint>
#include <map>

#include "framework/features/dual_features.h"
#include "framework/features/sharpness.h"
#include "framework/interpolation/limit_rows.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

RefineOptions with_levels(RefineOptions o, int levels, int step_offset) {
  o.levels = levels;
  o.first_step += step_offset;
  return o;
}

// The mean of the stencil rows of a face's vertices, merged by source.
std::map<Index, double> mean_row(const StencilTable& s, std::span<const Index> face) {
  std::map<Index, double> row;
  for (Index c : face)
    for (Index i = s.offsets[c]; i < s.offsets[c + 1]; ++i) row[s.indices[i]] += s.weights[i] / double(face.size());
  return row;
}

// Whether every feature at v keeps its rule at every level: its sharp edges (for the dual
// split) and its vertex tag are boundaries, non-manifold edges or infinitely sharp. A
// semi-sharp crease or corner rounds off after a few levels, so its limit is the smooth
// scheme's, not the crease curve's.
bool features_stay(const Level& L, Index v) {
  if (L.vertex_sharp(v) > 0.f && L.vertex_sharp(v) < kInfinitelySharp) return false;
  for (Index e : L.ring_edges(v))
    if (dual_sharp_edge(L, e) && !L.edge_on_boundary(e) && !L.non_manifold_edge(e) && L.edge_sharp(e) < kInfinitelySharp)
      return false;
  return true;
}

Index previous_corner(const Level& L, Index f, Index c) { return c == L.face_offsets[f] ? L.face_offsets[f + 1] - 1 : c - 1; }

// The sharp edge (for the dual split) whose curve point child vertex `child` is, at the
// parent vertex it was made at, or kNone: a corner point beside one sharp face edge lies on
// it; a corner with both face edges sharp gives two points, the second (corner_side 1) on
// the arriving edge (refine/dual_crease_topology.h).
Index crease_edge_of(const Level& L, const ChildOrigins& o, Index child) {
  if (o.kind[child] != OriginKind::Corner) return kNone;
  const Index f = o.parent[child];
  const Index c = L.face_offsets[f] + o.local[child];
  const Index out = L.face_edges[c], in = L.face_edges[previous_corner(L, f, c)];
  const bool second = !o.corner_side.empty() && o.corner_side[child] == 1;
  if (!second && dual_sharp_edge(L, out)) return out;
  if (dual_sharp_edge(L, in)) return in;
  return kNone;
}

}  // namespace

DualCreasePoints dual_crease_points(const Level& parent, const ChildOrigins& origins) {
  DualCreasePoints out;
  out.first.assign(size_t(parent.vertex_count), kNone);
  out.second.assign(size_t(parent.vertex_count), kNone);
  out.first_edge.assign(size_t(parent.vertex_count), kNone);
  for (Index c = 0; c < Index(origins.kind.size()); ++c) {
    const Index e = crease_edge_of(parent, origins, c);
    if (e == kNone) continue;
    const Index v = parent.face(origins.parent[c])[origins.local[c]];
    if (out.first[v] == kNone) out.first[v] = c, out.first_edge[v] = e;
    else if (out.first_edge[v] != e && out.first[v] != c) out.second[v] = c;
  }
  return out;
}

std::vector<Index> vertex_faces_after_step(const Hierarchy& h) {
  const Level& parent = h.levels[0];
  const Level& child = h.levels[1];
  const ChildOrigins& o = h.origins[0];
  // The parent vertices a child vertex belongs to (at most two).
  auto owners = [&](Index c, Index out[2]) -> int {
    switch (o.kind[c]) {
      case OriginKind::Vertex: out[0] = o.parent[c]; return 1;
      case OriginKind::Edge: out[0] = parent.edge_vertices[2 * o.parent[c]], out[1] = parent.edge_vertices[2 * o.parent[c] + 1]; return 2;
      case OriginKind::Corner: out[0] = parent.face(o.parent[c])[o.local[c]]; return 1;
      case OriginKind::Face: return 0;
    }
    return 0;
  };
  std::vector<Index> vface(size_t(parent.vertex_count), kNone);
  for (Index f = 0; f < child.face_count(); ++f) {
    if (o.parent_face[f] != kNone) continue;
    const auto corners = child.face(f);
    Index common[2];
    int count = owners(corners[0], common);
    for (size_t i = 1; i < corners.size() && count > 0; ++i) {
      Index mine[2];
      const int m = owners(corners[i], mine);
      int kept = 0;
      for (int a = 0; a < count; ++a)
        for (int b = 0; b < m; ++b)
          if (common[a] == mine[b]) common[kept++] = common[a];
      count = kept;
    }
    if (count == 1) vface[common[0]] = f;
  }
  return vface;
}

DualCentroidLimit::DualCentroidLimit(std::shared_ptr<const Scheme> scheme, RefineOptions options)
    : scheme_(std::move(scheme)), options_(options) {}

std::string DualCentroidLimit::name() const { return fmt::format("V-face centroids of {} (Doo & Sabin 1978)", scheme_->name); }

StencilTable DualCentroidLimit::stencils_at(const Level& level, int step) const {
  RefineOptions one = options_;
  one.first_step = step;
  const Hierarchy h = refine(*scheme_, level, with_levels(one, 1, 0));
  const std::vector<Index> vface = vertex_faces_after_step(h);
  const DualCreasePoints crease = dual_crease_points(level, h.origins[0]);
  const StencilTable& s = h.stencils[0];
  // Per vertex: whether one step makes a point at it whose row is the vertex alone.
  std::vector<std::uint8_t> stays(size_t(level.vertex_count), 0);
  const ChildOrigins& o = h.origins[0];
  for (Index c = 0; c < Index(o.kind.size()); ++c) {
    if (o.kind[c] != OriginKind::Corner || s.offsets[c + 1] - s.offsets[c] != 1) continue;
    const Index v = level.face(o.parent[c])[o.local[c]];
    if (s.indices[s.offsets[c]] == v && s.weights[s.offsets[c]] == 1.0) stays[size_t(v)] = 1;
  }
  const std::string who = name();
  return detail::build_limit_rows(level.vertex_count, level.vertex_count, [&](Index v, detail::LimitRow& row) -> std::string {
    if (level.non_manifold_vertex(v))
      return fmt::format("{}: vertex {} is non-manifold, where the dual split makes no face", who, v);
    const bool feature = dual_collapses(level, v) || dual_sharp_edge_count(level, v) > 0;
    if (feature && !features_stay(level, v))
      return fmt::format("{}: vertex {} has a semi-sharp crease or corner (sharpness below 10), which rounds off "
                         "after a few levels; its limit is not computed for dual schemes: refine the mesh until the "
                         "sharpness has decayed, or make it infinitely sharp",
                         who, v);
    // A corner's face corners collapse into one point that stays at the vertex at every level
    // (docs/features.md, "Creases in dual schemes"): the limit passes through it — where the
    // split does collapse them into a point that stays (mid-edge's makes no point at a vertex).
    if (dual_collapses(level, v)) {
      if (!stays[size_t(v)])
        return fmt::format("{}: vertex {} is a corner, where one step of {} makes no point that stays at the vertex, "
                           "so its limit point is not known", who, v, scheme_->name);
      return row.add(v, 1.0), std::string();
    }
    const int sharp = dual_sharp_edge_count(level, v);
    if (sharp == 1)
      return fmt::format("{}: vertex {} ends a crease (one edge of sharpness >= 1, a dart), where no exact limit "
                         "mask is known for a dual scheme; interpolate the mesh with the crease ending at a corner "
                         "(tag the vertex) or with a primal scheme", who, v);
    // On a crease or boundary (two sharp edges) v's points are the crease curve's two points at
    // v; the child edge between them lies on the crease, and the crease rule keeps every crease
    // edge's midpoint (dual_centroid_mismatch checks it), so the nested edges shrink to their
    // common midpoint: v's point on the crease curve (for Chaikin the quadratic B-spline's
    // (p + 6 v + q) / 8).
    if (sharp == 2) {
      if (crease.first[v] == kNone || crease.second[v] == kNone)
        return fmt::format("{}: vertex {} lies on a crease or boundary, where one step of {} makes no two face-corner "
                           "points on its sharp edges there, so its crease curve's point is not known",
                           who, v, scheme_->name);
      for (Index c : {crease.first[v], crease.second[v]})
        for (Index i = s.offsets[c]; i < s.offsets[c + 1]; ++i) row.add(s.indices[i], 0.5 * s.weights[i]);
      return {};
    }
    if (vface[v] == kNone) return fmt::format("{}: vertex {} gets no V-face from one step of {}", who, v, scheme_->name);
    for (const auto& [source, w] : mean_row(s, h.levels[1].face(vface[v]))) row.add(source, w);
    return {};
  });
}

namespace {

// Every crease vertex's child crease edge (between its two crease points) keeps its midpoint
// one step further down: the crease points the next step makes on that edge, at its two
// ends, have the same mean.
std::string crease_midpoint_mismatch(const Scheme& scheme, const Level& level, const Hierarchy& h) {
  const DualCreasePoints at0 = dual_crease_points(level, h.origins[0]);
  const DualCreasePoints at1 = dual_crease_points(h.levels[1], h.origins[1]);
  const Level& l1 = h.levels[1];
  const StencilTable& s = h.stencils[1];
  for (Index v = 0; v < level.vertex_count; ++v) {
    if (level.non_manifold_vertex(v) || dual_collapses(level, v) || dual_sharp_edge_count(level, v) != 2 ||
        !features_stay(level, v))
      continue;
    const Index a = at0.first[v], b = at0.second[v];
    if (a == kNone || b == kNone) continue;  // DualCentroidLimit names the vertex
    const Index e = find_edge(l1, a, b);
    std::map<Index, double> got;
    for (Index end : {a, b}) {
      // The next step's point on e at `end`.
      Index point = kNone;
      for (Index c : {at1.first[end], at1.second[end]})
        if (c != kNone && crease_edge_of(l1, h.origins[1], c) == e) point = c;
      if (e == kNone || point == kNone)
        return fmt::format("one step of {} makes no crease edge between the two crease points of vertex {}",
                           subdiv::quoted(scheme.name), v);
      for (Index i = s.offsets[point]; i < s.offsets[point + 1]; ++i) got[s.indices[i]] += 0.5 * s.weights[i];
    }
    got[a] += 0.0, got[b] += 0.0;  // both must be there, with 1/2 each
    for (const auto& [source, w] : got) {
      const double want = source == a || source == b ? 0.5 : 0.0;
      if (std::abs(w - want) > 1e-12)
        return fmt::format("the crease rule of {} does not keep the midpoint of a crease edge (at vertex {}, weight {:.15g} "
                           "on a point where the midpoint has {:.15g}), so the crease curve's point of a vertex is not "
                           "known from its two crease points",
                           subdiv::quoted(scheme.name), v, w, want);
    }
  }
  return {};
}

}  // namespace

std::string dual_centroid_mismatch(const Scheme& scheme, const Level& level, const RefineOptions& options) {
  const Hierarchy h = refine(scheme, level, with_levels(options, 2, 0));
  const std::vector<Index> vface = vertex_faces_after_step(h);
  const Level& l1 = h.levels[1];
  const Level& l2 = h.levels[2];
  // The child face of each level-1 face.
  std::vector<Index> child_face(size_t(l1.face_count()), kNone);
  for (Index f = 0; f < l2.face_count(); ++f)
    if (h.origins[1].parent_face[f] != kNone) child_face[h.origins[1].parent_face[f]] = f;
  if (std::string why = crease_midpoint_mismatch(scheme, level, h); !why.empty()) return why;
  for (Index v = 0; v < level.vertex_count; ++v) {
    // Boundary, corner and crease vertices have no whole V-face (DualCentroidLimit says what
    // their limit is, or why it has none).
    if (level.non_manifold_vertex(v) || level.on_boundary(v) || dual_collapses(level, v) ||
        dual_sharp_edge_count(level, v) > 0)
      continue;
    const Index g = vface[v];
    if (g == kNone) return fmt::format("one step of {} makes no V-face around vertex {}", subdiv::quoted(scheme.name), v);
    if (child_face[g] == kNone)
      return fmt::format("one step of {} makes no child face inside the V-face of vertex {}", subdiv::quoted(scheme.name), v);
    const auto got = mean_row(h.stencils[1], l2.face(child_face[g]));
    const auto corners = l1.face(g);
    std::map<Index, double> want;
    for (Index c : corners) want[c] += 1.0 / double(corners.size());
    const std::map<Index, double>* both[] = {&got, &want};
    for (const std::map<Index, double>* m : both)
      for (const auto& [source, w] : *m) {
        const double a = got.count(source) ? got.at(source) : 0.0, b = want.count(source) ? want.at(source) : 0.0;
        if (std::abs(a - b) > 1e-12)
          return fmt::format("{} does not keep the centroid of the V-face of vertex {} (the face's child has "
                             "weight {:.15g} on its corner {}, the centroid {:.15g}), so V-face centroids are not "
                             "limit points", subdiv::quoted(scheme.name), v, a, source, b);
      }
  }
  return {};
}

}  // namespace subdiv
