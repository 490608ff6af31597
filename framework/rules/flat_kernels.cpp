#include "framework/rules/flat_kernels.h"

#include <algorithm>
#include <initializer_list>

#include "framework/rules/kernel_contexts.h"
#include "framework/rules/point_accumulator.h"
#include "framework/rules/weight_tables.h"
#include "framework/util/parallel_ranges.h"

namespace subdiv {
namespace {

using Points = FlatKernels::Points;
using TermShape = FlatKernels::TermShape;

// Whether every term gathers one of `allowed` with a weight that reads at most the
// element's own n (or k), and (unless `along_role`) is the same for every point of the role.
bool fits(const std::vector<TermShape>& terms, std::initializer_list<Points> allowed, bool along_role = false) {
  if (terms.empty()) return false;
  for (const TermShape& t : terms) {
    if ((t.varies && !along_role) || t.reads_shape) return false;
    if (std::find(allowed.begin(), allowed.end(), t.points) == allowed.end()) return false;
  }
  return true;
}

bool uses(const std::vector<TermShape>& terms, Points points) {
  return std::any_of(terms.begin(), terms.end(), [&](const TermShape& t) { return t.points == points; });
}

// The merged weight of the terms gathering `points`, at (n, k): the element_rules.cpp
// arguments of a vertex of valence n (n, 0), an edge (2, 0: its terms read no k here) and
// a face of size k (k, k).
double weight_of(const std::vector<TermShape>& terms, Points points, int n, int k) {
  double w = 0.0;
  for (const TermShape& t : terms)
    if (t.points == points) w += t.weights->weight(n, k, 0);
  return w;
}

// The corner of triangle f that is not a or b (face_vertices of a triangle: 3 in a row).
Index third_corner(const Level& L, Index f, Index a, Index b) {
  const Index* c = L.face_vertices.data() + L.face_offsets[f];
  return c[0] != a && c[0] != b ? c[0] : c[1] != a && c[1] != b ? c[1] : c[2];
}

}  // namespace

FlatKernels::FlatKernels(const StepContext& step, const std::vector<ChildGroup>& groups,
                         const std::vector<TermShape> (&terms)[kElementCount])
    : step_(step), untagged_(without_sharpness_tags(step.parent)), plain_(untagged_ && step.parent.manifold()) {
  const Level& L = step.parent;
  const Index element_count[kElementCount] = {L.vertex_count, L.edge_count(), L.face_count(), L.corner_count()};
  for (int k = 0; k < kElementCount; ++k) {
    const ChildGroup& g = groups[k];
    first_child_[k] = g.first_of_run() != kNone && g.size() == element_count[k] ? g.first_of_run() : kNone;
  }
  const bool face_points = first_child_[int(Element::Face)] != kNone;
  const bool edge_points = first_child_[int(Element::Edge)] != kNone;
  auto new_points_available = [&](const std::vector<TermShape>& t) {
    return (!uses(t, Points::FacePoints) || face_points) && (!uses(t, Points::EdgePoints) || edge_points);
  };
  if (step.stream_output)
    if (const std::vector<Element> order = build_order(step, groups); !order.empty()) stream_[int(order.back())] = true;
  const WeightTables& tables = step.tables;

  // Vertices: weights per valence n, up to the tables' largest n.
  const auto& vt = terms[int(Element::Vertex)];
  if (first_child_[int(Element::Vertex)] != kNone &&
      fits(vt, {Points::Self, Points::Ring, Points::FacePoints, Points::EdgePoints}) && new_points_available(vt)) {
    PerSize& p = vertex_;
    // A rule without a ring term (the butterflies keep their vertices) gathers no ring.
    p.uses_ring = uses(vt, Points::Ring);
    p.uses_face_points = uses(vt, Points::FacePoints), p.uses_edge_points = uses(vt, Points::EdgePoints);
    for (int n = 0; n <= tables.max_n; ++n) {
      p.self.push_back(weight_of(vt, Points::Self, n, 0));
      p.ring.push_back(weight_of(vt, Points::Ring, n, 0));
      p.face_points.push_back(weight_of(vt, Points::FacePoints, n, 0));
      p.edge_points.push_back(weight_of(vt, Points::EdgePoints, n, 0));
      p.sum_ok.push_back(row_sum_ok(p.self[n] + n * (p.ring[n] + p.face_points[n] + p.edge_points[n])));
    }
    covers_[int(Element::Vertex)] = true;
  }
  // Edges: constant weights.
  const auto& et = terms[int(Element::Edge)];
  if (first_child_[int(Element::Edge)] != kNone && fits(et, {Points::Ends, Points::FacePoints, Points::Opposite}) &&
      new_points_available(et)) {
    EdgeWeights& w = edge_;
    w.uses_face_points = uses(et, Points::FacePoints), w.uses_opposite = uses(et, Points::Opposite);
    w.ends = weight_of(et, Points::Ends, 2, 0), w.face_points = weight_of(et, Points::FacePoints, 2, 0);
    w.opposite = weight_of(et, Points::Opposite, 2, 0);
    w.sum_ok = row_sum_ok(2 * (w.ends + w.face_points + w.opposite));
    covers_[int(Element::Edge)] = true;
  }
  // Faces: weights per face size k (the rule reads k as n and k).
  const auto& ft = terms[int(Element::Face)];
  if (first_child_[int(Element::Face)] != kNone && fits(ft, {Points::Corners, Points::EdgePoints}) &&
      new_points_available(ft)) {
    PerSize& p = face_;
    p.uses_edge_points = uses(ft, Points::EdgePoints);
    const int max_k = tables.max_k;
    for (int k = 0; k <= max_k; ++k) {
      p.corners.push_back(weight_of(ft, Points::Corners, k, k));
      p.edge_points.push_back(weight_of(ft, Points::EdgePoints, k, k));
      p.sum_ok.push_back(row_sum_ok(k * (p.corners[k] + p.edge_points[k])));
    }
    covers_[int(Element::Face)] = true;
  }
  // Face corners: weights per face size k and place j, read at (k, k, j) as
  // element_rules.cpp's apply_corner_rule does.
  const auto& ct = terms[int(Element::Corner)];
  if (first_child_[int(Element::Corner)] != kNone && fits(ct, {Points::Self, Points::Corners}, true)) {
    CornerWeights& p = corner_;
    const int max_k = tables.max_k;
    for (int k = 0; k <= max_k; ++k) {
      p.row_start.push_back(Index(p.around.size()));
      double self = 0.0, sum = 0.0;
      for (const TermShape& t : ct)
        if (t.points == Points::Self) self += t.weights->weight(k, k, 0);
      p.self.push_back(self), sum += self;
      for (int j = 0; j < k; ++j) {
        double w = 0.0;
        for (const TermShape& t : ct)
          if (t.points == Points::Corners) w += t.weights->weight(k, k, j);
        p.around.push_back(w), sum += w;
      }
      p.sum_ok.push_back(row_sum_ok(sum));
    }
    covers_[int(Element::Corner)] = true;
  }
}

bool FlatKernels::covers(Element kind) const { return covers_[int(kind)]; }

Index FlatKernels::run(Element kind, Index begin, Index end, const StepSources& in, double* dst,
                       std::vector<Index>& left, FirstBadRow& bad) const {
  const bool three = in.channels == 3;
  // One loop per channel count (3, or any) and way of walking (Walk).
  const Walk walk = resolved_ ? Walk::Resolved : plain_ ? Walk::Plain : Walk::Checked;
  switch (kind) {
    case Element::Vertex:
      if (walk == Walk::Resolved) return three ? run_vertices<3, Walk::Resolved>(begin, end, in, dst, left, bad) : run_vertices<0, Walk::Resolved>(begin, end, in, dst, left, bad);
      if (walk == Walk::Plain) return three ? run_vertices<3, Walk::Plain>(begin, end, in, dst, left, bad) : run_vertices<0, Walk::Plain>(begin, end, in, dst, left, bad);
      return three ? run_vertices<3, Walk::Checked>(begin, end, in, dst, left, bad) : run_vertices<0, Walk::Checked>(begin, end, in, dst, left, bad);
    case Element::Edge:
      if (walk == Walk::Resolved) return three ? run_edges<3, Walk::Resolved>(begin, end, in, dst, left, bad) : run_edges<0, Walk::Resolved>(begin, end, in, dst, left, bad);
      if (walk == Walk::Plain) return three ? run_edges<3, Walk::Plain>(begin, end, in, dst, left, bad) : run_edges<0, Walk::Plain>(begin, end, in, dst, left, bad);
      return three ? run_edges<3, Walk::Checked>(begin, end, in, dst, left, bad) : run_edges<0, Walk::Checked>(begin, end, in, dst, left, bad);
    case Element::Face:
      return three ? run_faces<3>(begin, end, in, dst, left, bad) : run_faces<0>(begin, end, in, dst, left, bad);
    case Element::Corner:
      return three ? run_corners<3>(begin, end, in, dst, left, bad) : run_corners<0>(begin, end, in, dst, left, bad);
  }
  return 0;
}

bool FlatKernels::takes_vertex(Index v, Index n) const {
  const Level& L = step_.parent;
  return !L.vertex_on_boundary[v] && (L.manifold() || !L.non_manifold_vertex(v)) && n < Index(vertex_.self.size()) &&
         smooth_vertex(step_.features, untagged_, v, n) && L.incident_face_count(v) == n;
}

// Edges between two faces, and between two triangles when the rule reads the opposite
// vertices.
bool FlatKernels::takes_edge(Index e) const {
  const Level& L = step_.parent;
  const Index f0 = L.edge_faces[2 * e], f1 = L.edge_faces[2 * e + 1];
  return f1 != kNone && (L.manifold() || !L.non_manifold_edge(e)) && smooth_edge(step_.features, untagged_, e) &&
         (!edge_.uses_opposite || (L.face_size(f0) == 3 && L.face_size(f1) == 3));
}

void FlatKernels::resolve_neighbourhoods() {
  const Level& L = step_.parent;
  auto r = std::make_unique<Resolved>();
  if (covers_[int(Element::Vertex)]) {
    r->vertex_taken.resize(size_t(L.vertex_count));
    if (vertex_.uses_ring) r->ring_ends.resize(L.vertex_edges.size());
    parallel_ranges(L.vertex_count, Index(4096), [&](Index begin, Index end) {
      for (Index v = begin; v < end; ++v) {
        const Index ring_begin = L.vertex_ring_offsets[v], n = L.vertex_ring_offsets[v + 1] - ring_begin;
        r->vertex_taken[v] = takes_vertex(v, n);
        if (r->vertex_taken[v] && vertex_.uses_ring)
          for (Index j = ring_begin; j < ring_begin + n; ++j) r->ring_ends[j] = L.other_end(L.vertex_edges[j], v);
      }
    });
  }
  if (covers_[int(Element::Edge)]) {
    const int stride = r->edge_stride = edge_.uses_opposite ? 4 : 2;
    r->edge_gathers.resize(size_t(L.edge_count()) * stride);
    parallel_ranges(L.edge_count(), Index(4096), [&](Index begin, Index end) {
      for (Index e = begin; e < end; ++e) {
        Index* gathers = r->edge_gathers.data() + size_t(e) * stride;
        if (!takes_edge(e)) {
          gathers[0] = kNone;
          continue;
        }
        const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
        gathers[0] = a, gathers[1] = b;
        if (stride == 4)
          gathers[2] = third_corner(L, L.edge_faces[2 * e], a, b),
          gathers[3] = third_corner(L, L.edge_faces[2 * e + 1], a, b);
      }
    });
  }
  resolved_ = std::move(r);
}

// Row r is vertex r; the smooth interior ones.
template <int C, FlatKernels::Walk W>
Index FlatKernels::run_vertices(Index begin, Index end, const StepSources& in, double* dst, std::vector<Index>& left,
                                FirstBadRow& bad) const {
  const Level& L = step_.parent;
  const PerSize& w = vertex_;
  const Index first = first_child_[int(Element::Vertex)];
  const double* face_points = w.uses_face_points ? in.child(first_child_[int(Element::Face)]) : nullptr;
  const double* edge_points = w.uses_edge_points ? in.child(first_child_[int(Element::Edge)]) : nullptr;
  const int channels = in.channels;
  const bool stream = stream_[int(Element::Vertex)];
  Index done = 0;
  for (Index v = begin; v < end; ++v) {
    const Index ring_begin = L.vertex_ring_offsets[v], n = L.vertex_ring_offsets[v + 1] - ring_begin;
    // Plain: takes_vertex's conditions on a manifold level without tags (smooth_vertex: n > 0).
    const bool taken = W == Walk::Resolved ? resolved_->vertex_taken[v] != 0
                       : W == Walk::Plain  ? !L.vertex_on_boundary[v] && n > 0 && n < Index(w.self.size()) &&
                                                L.vertex_face_offsets[v + 1] - L.vertex_face_offsets[v] == n
                                           : takes_vertex(v, n);
    if (!taken) {
      left.push_back(v);
      continue;
    }
    const Index* ring = L.vertex_edges.data() + ring_begin;
    PointAccumulator<C> acc(dst + size_t(first + v) * channels, channels);
    acc.add(in.vertex(v), w.self[n]);
    if (w.uses_ring) {
      const double w_ring = w.ring[n];
      if constexpr (W == Walk::Resolved) {
        const Index* far_ends = resolved_->ring_ends.data() + ring_begin;
        for (Index j = 0; j < n; ++j) acc.add(in.vertex(far_ends[j]), w_ring);
      } else {
        for (Index j = 0; j < n; ++j) acc.add(in.vertex(L.other_end(ring[j], v)), w_ring);
      }
    }
    if (face_points) {
      const Index* faces = L.vertex_faces.data() + L.vertex_face_offsets[v];
      const double w_face = w.face_points[n];
      for (Index j = 0; j < n; ++j) acc.add(face_points + size_t(faces[j]) * channels, w_face);
    }
    if (edge_points) {
      const double w_edge = w.edge_points[n];
      for (Index j = 0; j < n; ++j) acc.add(edge_points + size_t(ring[j]) * channels, w_edge);
    }
    if (stream) acc.stream(); else acc.store();
    ++done;
    if (!w.sum_ok[n]) bad.mark(v);
  }
  if (stream) streaming_fence();
  return done;
}

// Row r is edge r; the interior smooth ones (takes_edge).
template <int C, FlatKernels::Walk W>
Index FlatKernels::run_edges(Index begin, Index end, const StepSources& in, double* dst, std::vector<Index>& left,
                             FirstBadRow& bad) const {
  const Level& L = step_.parent;
  const EdgeWeights& w = edge_;
  const Index first = first_child_[int(Element::Edge)];
  const double* face_points = w.uses_face_points ? in.child(first_child_[int(Element::Face)]) : nullptr;
  const int channels = in.channels;
  const bool stream = stream_[int(Element::Edge)];
  Index done = 0;
  for (Index e = begin; e < end; ++e) {
    constexpr bool IsResolved = W == Walk::Resolved;
    const Index* gathers = IsResolved ? resolved_->edge_gathers.data() + size_t(e) * resolved_->edge_stride : nullptr;
    // Plain: takes_edge's conditions on a manifold level without tags (smooth_edge: true).
    const bool taken = IsResolved            ? gathers[0] != kNone
                       : W == Walk::Plain    ? L.edge_faces[2 * e + 1] != kNone &&
                                                (!w.uses_opposite || (L.face_size(L.edge_faces[2 * e]) == 3 &&
                                                                      L.face_size(L.edge_faces[2 * e + 1]) == 3))
                                             : takes_edge(e);
    if (!taken) {
      left.push_back(e);
      continue;
    }
    const Index a = IsResolved ? gathers[0] : L.edge_vertices[2 * e];
    const Index b = IsResolved ? gathers[1] : L.edge_vertices[2 * e + 1];
    const Index* faces = L.edge_faces.data() + 2 * size_t(e);  // read only for face points or a walk
    PointAccumulator<C> acc(dst + size_t(first + e) * channels, channels);
    acc.add(in.vertex(a), w.ends), acc.add(in.vertex(b), w.ends);
    if (face_points)
      acc.add(face_points + size_t(faces[0]) * channels, w.face_points),
          acc.add(face_points + size_t(faces[1]) * channels, w.face_points);
    if (w.uses_opposite) {
      const Index c = IsResolved ? gathers[2] : third_corner(L, faces[0], a, b);
      const Index d = IsResolved ? gathers[3] : third_corner(L, faces[1], a, b);
      acc.add(in.vertex(c), w.opposite), acc.add(in.vertex(d), w.opposite);
    }
    if (stream) acc.stream(); else acc.store();
    ++done;
    if (!w.sum_ok) bad.mark(e);
  }
  if (stream) streaming_fence();
  return done;
}

// Row r is the corner made child first + r; its face and place come from the origins. The
// smooth kernels' corner_point conditions: neither edge of the corner sharp, its vertex not.
template <int C>
Index FlatKernels::run_corners(Index begin, Index end, const StepSources& in, double* dst, std::vector<Index>& left,
                               FirstBadRow& bad) const {
  const Level& L = step_.parent;
  const CornerWeights& w = corner_;
  const int max_k = int(w.self.size()) - 1;
  const Index first = first_child_[int(Element::Corner)];
  const ChildOrigins& origins = step_.origins;
  const FeatureContexts& F = step_.features;
  const int channels = in.channels;
  const bool stream = stream_[int(Element::Corner)];
  Index done = 0;
  for (Index r = begin; r < end; ++r) {
    const Index child = first + r, f = origins.parent[child];
    const int i = origins.local[child];
    const Index corner_begin = L.face_offsets[f], k = L.face_offsets[f + 1] - corner_begin;
    const Index out_edge = L.face_edges[corner_begin + i], in_edge = L.face_edges[corner_begin + (i + k - 1) % k];
    if (sharp_corner(L, F, untagged_, L.face_vertices[corner_begin + i], out_edge, in_edge) || k > max_k ||
        dual_feature_corner(L, origins, L.face_vertices[corner_begin + i])) {
      left.push_back(r);
      continue;
    }
    const Index* corners = L.face_vertices.data() + corner_begin;
    const double* around = w.around.data() + w.row_start[k];
    PointAccumulator<C> acc(dst + size_t(child) * channels, channels);
    acc.add(in.vertex(corners[i]), w.self[k]);
    // Corner j places on from i, without a modulo per point.
    for (Index j = 0; j < k - i; ++j) acc.add(in.vertex(corners[i + j]), around[j]);
    for (Index j = k - i; j < k; ++j) acc.add(in.vertex(corners[i + j - k]), around[j]);
    if (stream) acc.stream(); else acc.store();
    ++done;
    if (!w.sum_ok[k]) bad.mark(r);
  }
  if (stream) streaming_fence();
  return done;
}

// Row r is face r; every face whose size the tables reach.
template <int C>
Index FlatKernels::run_faces(Index begin, Index end, const StepSources& in, double* dst, std::vector<Index>& left,
                             FirstBadRow& bad) const {
  const Level& L = step_.parent;
  const PerSize& w = face_;
  const int max_k = int(w.corners.size()) - 1;
  const Index first = first_child_[int(Element::Face)];
  const double* edge_points = w.uses_edge_points ? in.child(first_child_[int(Element::Edge)]) : nullptr;
  const int channels = in.channels;
  const bool stream = stream_[int(Element::Face)];
  Index done = 0;
  for (Index f = begin; f < end; ++f) {
    const Index corner_begin = L.face_offsets[f], k = L.face_offsets[f + 1] - corner_begin;
    if (k > max_k) {
      left.push_back(f);
      continue;
    }
    PointAccumulator<C> acc(dst + size_t(first + f) * channels, channels);
    const Index* corners = L.face_vertices.data() + corner_begin;
    const double w_corner = w.corners[k];
    for (Index j = 0; j < k; ++j) acc.add(in.vertex(corners[j]), w_corner);
    if (edge_points) {
      const Index* edges = L.face_edges.data() + corner_begin;
      const double w_edge = w.edge_points[k];
      for (Index j = 0; j < k; ++j) acc.add(edge_points + size_t(edges[j]) * channels, w_edge);
    }
    if (stream) acc.stream(); else acc.store();
    ++done;
    if (!w.sum_ok[k]) bad.mark(f);
  }
  if (stream) streaming_fence();
  return done;
}

}  // namespace subdiv
