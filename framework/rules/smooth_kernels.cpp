#include "framework/rules/smooth_kernels.h"

#include <algorithm>

#include "framework/rules/flat_kernels.h"
#include "framework/rules/kernel_contexts.h"
#include "framework/rules/point_accumulator.h"

namespace subdiv {
namespace {

using Gather = SmoothKernels::Gather;

// The gather of a term of `element`'s smooth rule, or false when the kernels have none.
// The roles and their point order are element_rules.cpp's, which the kernels mirror.
bool gather_of(Element element, const CompiledTerm& t, Gather& gather) {
  const bool plain = t.new_point == NewPoint::None;
  switch (element) {
    case Element::Vertex:
      if (t.role == Role::Self && plain) return gather = Gather::Self, true;
      if (t.role == Role::Ring && plain) return gather = Gather::Ring, true;
      if (t.role == Role::Faces && t.new_point == NewPoint::Face) return gather = Gather::FacePoints, true;
      if (t.role == Role::Edges && t.new_point == NewPoint::Edge) return gather = Gather::EdgePoints, true;
      return false;
    case Element::Edge:
      if (t.role == Role::Ends && plain) return gather = Gather::Ends, true;
      if (t.role == Role::Faces && t.new_point == NewPoint::Face) return gather = Gather::FacePoints, true;
      if ((t.role == Role::Opposite || t.role == Role::Wings) && plain) return gather = Gather::Opposite, true;
      if (t.role == Role::FarWings && plain) return gather = Gather::FarWings, true;
      if (t.role == Role::EndRing0 && plain) return gather = Gather::EndRing0, true;
      if (t.role == Role::EndRing1 && plain) return gather = Gather::EndRing1, true;
      if ((t.role == Role::EndSector0 || t.role == Role::EndSector1) && plain) return gather = Gather::EndSector, true;
      return false;
    case Element::Face:
      if (t.role == Role::Vertices && plain) return gather = Gather::Corners, true;
      if (t.role == Role::Edges && t.new_point == NewPoint::Edge) return gather = Gather::EdgePoints, true;
      return false;
    case Element::Corner:
      if (t.role == Role::Self && plain) return gather = Gather::Self, true;
      if (t.role == Role::Vertices && plain) return gather = Gather::Corners, true;
      return false;
  }
  return false;
}

// Whether C++ rules (plugins) take the smooth rule of `element`.
bool code_rule_for(const CodeRules* code, Element element) {
  if (!code) return false;
  switch (element) {
    case Element::Vertex: return bool(code->vertex);
    case Element::Edge: return bool(code->edge);
    case Element::Face: return bool(code->face);
    case Element::Corner: return bool(code->corner);
  }
  return true;
}

std::vector<SmoothKernels::Term> compile_kernel(const StepContext& s, Element element) {
  if (code_rule_for(s.code, element) || (element == Element::Vertex && s.per_vertex)) return {};
  const CompiledRule& rule = s.tables.rule(element, Context::Smooth);
  if (!rule.defined) return {};
  std::vector<SmoothKernels::Term> terms;
  for (const CompiledTerm& t : rule.terms) {
    Gather gather;
    if (!gather_of(element, t, gather)) return {};
    // The kernels take no edge with an end on a boundary or crease (edge_point), where the
    // sector roles are empty and a term of sector weights only is 0.
    if (gather == Gather::EndSector || (t.reads_sectors() && t.zero_without_sectors)) continue;
    // Weights that read a face's corner variables (formula.h) need the generic interpreter.
    if (t.stride_ci || t.stride_cb || t.stride_ex || t.stride_fe) return {};
    // Face points are weighed by their face's size k (element_rules.cpp), so k varies too.
    const bool varies = t.stride_j != 0 || (gather == Gather::FacePoints && t.stride_k != 0);
    using Reads = SmoothKernels::Term::Reads;
    const bool others = t.stride_j || t.stride_n0 || t.stride_n1 || t.stride_k0 || t.stride_k1;
    const auto reads = others || (t.stride_n && t.stride_k) ? Reads::More
                       : t.stride_n                         ? Reads::N
                       : t.stride_k                         ? Reads::K
                                                            : Reads::Nothing;
    terms.push_back({gather, &t, varies, reads, {}, 0});
  }
  return terms;
}

// The vertex of triangle f that is not a or b, or kNone if f is not a triangle.
Index third_corner(const Level& L, Index f, Index a, Index b) {
  if (L.face_size(f) != 3) return kNone;
  for (Index u : L.face(f))
    if (u != a && u != b) return u;
  return kNone;
}

// The place of edge e in triangle f's edges (edge i runs from corner i to corner i + 1, so
// corner i + 2 is opposite it), or -1 when f is not a triangle holding e.
int place_in_triangle(const Level& L, Index f, Index e) {
  const Index o = L.face_offsets[f];
  if (L.face_offsets[f + 1] - o != 3) return -1;
  const Index* edges = L.face_edges.data() + o;
  return edges[0] == e ? 0 : edges[1] == e ? 1 : edges[2] == e ? 2 : -1;
}

// Across edge e of triangle f: the corner opposite e in the triangle on e's other side, or
// kNone where there is none to read plainly (a boundary, a non-manifold edge, a face that
// is not a triangle: the interpreter's cases). element_rules.cpp, add_across.
Index across(const Level& L, Index f, Index e) {
  if (L.edge_on_boundary(e) || L.non_manifold_edge(e)) return kNone;
  const Index g = L.edge_faces[2 * e] == f ? L.edge_faces[2 * e + 1] : L.edge_faces[2 * e];
  const int i = place_in_triangle(L, g, e);
  return i < 0 ? kNone : L.face_vertices[L.face_offsets[g] + (i + 2) % 3];
}

// A term as the flat kernels see it: the points it gathers, and whether its weight reads
// more than the element's own size (a vertex's n; a face's or a corner's k, which it reads
// as n and k; an edge's n, always 2). Faces of a vertex are weighed at their own k (`varies`).
FlatKernels::TermShape flat_shape(Element element, const SmoothKernels::Term& t) {
  using Points = FlatKernels::Points;
  using Reads = SmoothKernels::Term::Reads;
  Points points = Points::Other;
  switch (t.gather) {
    case Gather::Self: points = Points::Self; break;
    case Gather::Ring: points = Points::Ring; break;
    case Gather::FacePoints: points = Points::FacePoints; break;
    case Gather::EdgePoints: points = Points::EdgePoints; break;
    case Gather::Ends: points = Points::Ends; break;
    case Gather::Opposite: points = Points::Opposite; break;
    case Gather::Corners: points = Points::Corners; break;
    default: break;
  }
  // A corner's weights are read at (k, k, j): they may read n, k and j.
  const CompiledTerm& w = *t.weights;
  const bool reads_neighbours = w.stride_n0 || w.stride_n1 || w.stride_k0 || w.stride_k1;
  const bool reads_shape = element == Element::Corner ? reads_neighbours
                                                      : t.reads == Reads::More || (element != Element::Face && t.reads == Reads::K);
  return {points, t.weights, t.varies, reads_shape};
}

// Term::zero_by_ends for an edge's far-wing and end-ring terms whose weights read no face
// size: every tabulated j at each (n0, n1), at the k the kernel passes (3 for far wings, 0
// for end rings; unread here).
void tabulate_zero_weights(SmoothKernels::Term& t, int max_n) {
  const bool gathers_many = t.gather == Gather::FarWings || t.gather == Gather::EndRing0 || t.gather == Gather::EndRing1;
  const CompiledTerm& w = *t.weights;
  if (!gathers_many || w.stride_k || w.stride_k0 || w.stride_k1 || max_n > 64) return;
  t.max_n = max_n;
  t.zero_by_ends.assign(size_t(max_n + 1) * size_t(max_n + 1), 1);
  for (int n0 = 0; n0 <= max_n; ++n0)
    for (int n1 = 0; n1 <= max_n; ++n1)
      for (int j = 0; j <= (w.stride_j ? w.max_j : 0); ++j)
        if (w.weight(2, 0, j, n0, n1) != 0.0) t.zero_by_ends[size_t(n0) * size_t(max_n + 1) + size_t(n1)] = 0;
}

}  // namespace

SmoothKernels::SmoothKernels(const StepContext& step, const std::vector<ChildGroup>& groups)
    : step_(step),
      groups_(groups),
      untagged_(without_sharpness_tags(step.parent)) {
  std::vector<FlatKernels::TermShape> shapes[kElementCount];
  edge_reads_sectors_ = reads_sectors(step.tables.rule(Element::Edge, Context::Smooth));
  // Without sharpness tags, only a boundary or non-manifold vertex can have a sector: a closed
  // manifold level (one scan here) needs no check per edge.
  const Level& L = step.parent;
  if (edge_reads_sectors_ && untagged_ && L.vertex_non_manifold.empty() &&
      std::none_of(L.vertex_on_boundary.begin(), L.vertex_on_boundary.end(), [](std::uint8_t b) { return b != 0; }))
    edge_reads_sectors_ = false;
  for (int k = 0; k < kElementCount; ++k) {
    kernels_[k] = compile_kernel(step, Element(k));
    for (const Term& t : kernels_[k]) {
      if (k == int(Element::Edge) && (t.reads == Term::Reads::More || t.reads == Term::Reads::K ||
                                      (t.gather != Gather::Ends && t.gather != Gather::FacePoints)))
        edge_reads_shape_ = true;
      shapes[k].push_back(flat_shape(Element(k), t));
    }
  }
  for (Term& t : kernels_[int(Element::Edge)]) tabulate_zero_weights(t, step.tables.max_n);
  flat_ = std::make_unique<FlatKernels>(step, groups, shapes);
}

SmoothKernels::~SmoothKernels() = default;

void SmoothKernels::resolve_neighbourhoods() { flat_->resolve_neighbourhoods(); }

template <class Accumulator, class Weight>
bool SmoothKernels::add_new_points(Accumulator& acc, double& sum, Element kind, std::span<const Index> elements,
                                   const StepSources& in, Weight weight) const {
  for (int j = 0; j < int(elements.size()); ++j) {
    const Index c = new_point(kind, elements[j]);
    if (c == kNone) return false;
    const double w = weight(j);
    acc.add(in.child(c), w), sum += w;
  }
  return true;
}

Index SmoothKernels::run(Element kind, const ChildGroup& group, Index begin, Index end, const StepSources& in,
                        double* dst, std::vector<Index>& left, FirstBadRow& bad, Index& flat) const {
  flat = 0;
  // The flat kernels cover a kind only when its children are one run over its elements.
  if (flat_->covers(kind)) return flat = flat_->run(kind, begin, end, in, dst, left, bad);
  if (in.channels == 3) return run_rows<3>(kind, group, begin, end, in, dst, left, bad);
  return run_rows<0>(kind, group, begin, end, in, dst, left, bad);
}

// The loop over rows, one per kind, so each element's kernel is inlined into it.
template <int C>
Index SmoothKernels::run_rows(Element kind, const ChildGroup& group, Index begin, Index end, const StepSources& in,
                              double* dst, std::vector<Index>& left, FirstBadRow& bad) const {
  const ChildOrigins& origins = step_.origins;
  // In a primal split, row r of a kind is the new point of element r (a corner's element
  // is its face, with the corner in `local`).
  const bool in_order = kind != Element::Corner && group.first_of_run() != kNone;
  Index done = 0;
  auto each_row = [&](auto point) {
    for (Index r = begin; r < end; ++r) {
      const Index child = group.child(r);
      const Index element = in_order ? r : origins.parent[child];
      double sum;
      if (!point(element, child, dst + size_t(child) * in.channels, sum)) {
        left.push_back(r);
        continue;
      }
      ++done;
      if (!row_sum_ok(sum)) bad.mark(r);
    }
  };
  switch (kind) {
    case Element::Vertex:
      each_row([&](Index v, Index, double* out, double& sum) { return vertex_point<C>(v, in, out, sum); });
      break;
    case Element::Edge:
      each_row([&](Index e, Index, double* out, double& sum) { return edge_point<C>(e, in, out, sum); });
      break;
    case Element::Face:
      each_row([&](Index f, Index, double* out, double& sum) { return face_point<C>(f, in, out, sum); });
      break;
    case Element::Corner:
      each_row([&](Index f, Index child, double* out, double& sum) {
        return corner_point<C>(f, origins.local[child], in, out, sum);
      });
      break;
  }
  return done;
}

// element_rules.cpp, apply_vertex_rule: weights at (n, 0, j), face points at (n, k_j, j).
template <int C>
[[gnu::always_inline]] inline  // into run_rows' loop
bool SmoothKernels::vertex_point(Index v, const StepSources& in, double* out, double& weight_sum) const {
  const Level& L = step_.parent;
  if (L.on_boundary(v) || L.non_manifold_vertex(v)) return false;
  const auto ring = L.ring_edges(v);
  const auto faces = L.ring_faces(v);
  const int n = int(ring.size()), channels = in.channels;
  if (!smooth_vertex(step_.features, untagged_, v, n)) return false;
  PointAccumulator<C> acc(out, channels);
  double sum = 0.0;
  for (const Term& term : kernels_[int(Element::Vertex)]) {
    const double w0 = term.weight_at(n, 0, 0);
    switch (term.gather) {
      case Gather::Self:
        acc.add(in.vertex(v), w0), sum += w0;
        break;
      case Gather::Ring:
        for (int j = 0; j < n; ++j) {
          const double w = term.varies ? term.weight_at(n, 0, j) : w0;
          acc.add(in.vertex(L.other_end(ring[j], v)), w), sum += w;
        }
        break;
      case Gather::FacePoints:
        if (!add_new_points(acc, sum, Element::Face, faces, in, [&](int j) {
              return term.varies ? term.weight_at(n, L.face_size(faces[j]), j) : w0;
            }))
          return false;
        break;
      case Gather::EdgePoints:
        if (!add_new_points(acc, sum, Element::Edge, ring, in,
                            [&](int j) { return term.varies ? term.weight_at(n, 0, j) : w0; }))
          return false;
        break;
      default: return false;
    }
  }
  acc.store();
  weight_sum = sum;
  return true;
}

// element_rules.cpp, apply_edge_rule: weights at (2, k, j, n0, n1, k0, k1).
template <int C>
[[gnu::always_inline]] inline  // into run_rows' loop
bool SmoothKernels::edge_point(Index e, const StepSources& in, double* out, double& weight_sum) const {
  const Level& L = step_.parent;
  if (L.edge_on_boundary(e) || L.non_manifold_edge(e) || !smooth_edge(step_.features, untagged_, e))
    return false;
  const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
  if (edge_reads_sectors_ && (feature_vertex(L, step_.features, untagged_, a) || feature_vertex(L, step_.features, untagged_, b)))
    return false;
  const Index faces[2] = {L.edge_faces[2 * e], L.edge_faces[2 * e + 1]};
  // The ends' valences and the faces' sizes only for formulas that read them: four random
  // reads an edge otherwise.
  const bool shape = edge_reads_shape_;
  const int n0 = shape ? L.valence(a) : 0, n1 = shape ? L.valence(b) : 0;
  const int k0 = shape ? L.face_size(faces[0]) : 0, k1 = shape ? L.face_size(faces[1]) : 0;
  const int channels = in.channels;
  PointAccumulator<C> acc(out, channels);
  double sum = 0.0;
  for (const Term& term : kernels_[int(Element::Edge)]) {
    auto weight = [&](int k, int j) { return term.weight_at(2, k, j, n0, n1, k0, k1); };
    switch (term.gather) {
      case Gather::Ends: {
        const double wa = weight(0, 0), wb = term.varies ? weight(0, 1) : wa;
        acc.add(in.vertex(a), wa), acc.add(in.vertex(b), wb), sum += wa + wb;
        break;
      }
      case Gather::FacePoints:
        if (!add_new_points(acc, sum, Element::Face, faces, in,
                            [&](int j) { return weight(shape ? (j == 0 ? k0 : k1) : 0, j); }))
          return false;
        break;
      case Gather::Opposite:
        for (int j = 0; j < 2; ++j) {
          const Index u = third_corner(L, faces[j], a, b);
          if (u == kNone) return false;
          const double w = weight(3, j);
          acc.add(in.vertex(u), w), sum += w;
        }
        break;
      case Gather::FarWings:
        // Most edges of a scheme that switches stencils by its ends' valences give the other
        // stencil's points weight 0 (the modified butterfly: far wings only between two
        // regular ends, end rings only at an extraordinary one): their gathers are skipped.
        if (const auto zero = term.zero_at(n0, n1); zero == Term::Zero::Yes ||
            (zero == Term::Zero::Unknown && weight(3, 0) == 0.0 && weight(3, 1) == 0.0 && weight(3, 2) == 0.0 &&
             weight(3, 3) == 0.0))
          break;
        // Triangle j runs (p, q, c), e being its edge i from p to q; its far wings lie across
        // (q, c) and (c, p), its edges i + 1 and i + 2.
        for (int j = 0; j < 2; ++j) {
          const int place = place_in_triangle(L, faces[j], e);
          if (place < 0) return false;
          const Index* edges = L.face_edges.data() + L.face_offsets[faces[j]];
          const Index far[2] = {across(L, faces[j], edges[(place + 1) % 3]), across(L, faces[j], edges[(place + 2) % 3])};
          for (int i = 0; i < 2; ++i) {
            if (far[i] == kNone) return false;
            const double w = weight(3, 2 * j + i);
            acc.add(in.vertex(far[i]), w), sum += w;
          }
        }
        break;
      case Gather::EndRing0:
      case Gather::EndRing1: {
        // element_rules.cpp, add_end_ring: j = 0 is the edge's other end.
        const Index end = term.gather == Gather::EndRing0 ? a : b;
        const auto ring = L.ring_edges(end);
        const int n = int(ring.size());
        // As the far wings above.
        const auto zero = term.zero_at(n0, n1);
        if (zero == Term::Zero::Yes) break;
        bool any = zero == Term::Zero::No;
        for (int j = 0; j < n && !any; ++j) any = weight(0, j) != 0.0;
        if (!any) break;
        int start = 0;
        while (start < n && ring[start] != e) ++start;
        for (int j = 0; j < n; ++j) {
          const double w = weight(0, j);
          acc.add(in.vertex(L.other_end(ring[(start + j) % n], end)), w), sum += w;
        }
        break;
      }
      default: return false;
    }
  }
  acc.store();
  weight_sum = sum;
  return true;
}

// element_rules.cpp, apply_face_rule: weights at (k, k, j).
template <int C>
[[gnu::always_inline]] inline  // into run_rows' loop
bool SmoothKernels::face_point(Index f, const StepSources& in, double* out, double& weight_sum) const {
  const Level& L = step_.parent;
  const auto corners = L.face(f);
  const int k = int(corners.size()), channels = in.channels;
  PointAccumulator<C> acc(out, channels);
  double sum = 0.0;
  for (const Term& term : kernels_[int(Element::Face)]) {
    const double w0 = term.weight_at(k, k, 0);
    if (term.gather == Gather::Corners) {
      for (int j = 0; j < k; ++j) {
        const double w = term.varies ? term.weight_at(k, k, j) : w0;
        acc.add(in.vertex(corners[j]), w), sum += w;
      }
    } else if (!add_new_points(acc, sum, Element::Edge, L.face_edge_list(f), in,  // Gather::EdgePoints
                               [&](int j) { return term.varies ? term.weight_at(k, k, j) : w0; })) {
      return false;
    }
  }
  acc.store();
  weight_sum = sum;
  return true;
}

// step_rows.cpp, fill_corner_row away from features: the smooth corner rule alone;
// element_rules.cpp, apply_corner_rule: weights at (k, k, j), corners counted from `corner`.
template <int C>
[[gnu::always_inline]] inline  // into run_rows' loop
bool SmoothKernels::corner_point(Index f, int corner, const StepSources& in, double* out, double& weight_sum) const {
  const Level& L = step_.parent;
  const auto corners = L.face(f);
  const auto edges = L.face_edge_list(f);
  const int k = int(corners.size()), channels = in.channels;
  if (sharp_corner(L, step_.features, untagged_, corners[corner], edges[corner], edges[(corner + k - 1) % k]) ||
      dual_feature_corner(L, step_.origins, corners[corner]))
    return false;
  PointAccumulator<C> acc(out, channels);
  double sum = 0.0;
  for (const Term& term : kernels_[int(Element::Corner)]) {
    const double w0 = term.weight_at(k, k, 0);
    if (term.gather == Gather::Self) {
      acc.add(in.vertex(corners[corner]), w0), sum += w0;
      continue;
    }
    for (int j = 0; j < k; ++j) {  // Gather::Corners
      const double w = term.varies ? term.weight_at(k, k, j) : w0;
      acc.add(in.vertex(corners[(corner + j) % k]), w), sum += w;
    }
  }
  acc.store();
  weight_sum = sum;
  return true;
}

}  // namespace subdiv
