#include "framework/rules/element_rules.h"

#include <cstdlib>
#include <fmt/format.h>

#include "framework/rules/end_sectors.h"
#include "framework/rules/feature_curve.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

Element element_of(NewPoint kind) {
  return kind == NewPoint::Face ? Element::Face : kind == NewPoint::Edge ? Element::Edge : Element::Vertex;
}

// Adds a point of a role: a parent vertex, or (with "new") the new point of an element.
void add_point(RowBuilder& row, const RuleInputs& in, const CompiledTerm& term, Index element, double w) {
  if (term.new_point == NewPoint::None) return row.add(element, w);
  const Element kind = element_of(term.new_point);
  const ChildGroup* group = in.groups ? &(*in.groups)[int(kind)] : nullptr;
  const bool as_source = in.new_point_base >= 0;
  if (!group || group->empty() || (!as_source && !in.blocks[int(kind)]))
    throw Error(fmt::format("{}: uses new {} points, which this step does not make", term.where, element_name(kind)));
  const Index r = group->row_of(element);
  if (r == kNone)
    throw Error(fmt::format("{}: {} {} has no new point in this step", term.where, element_name(kind), element));
  if (as_source) return row.add(in.new_point_base + group->child(r), w);
  row.add_row(*in.blocks[int(kind)], r, w);
}

[[noreturn]] void wrong_role(const CompiledTerm& t, Element e) {
  throw Error(fmt::format("{}: role {} is not a {} role", t.where, subdiv::quoted(role_name(t.role)), element_name(e)));
}

// The vertex of triangle f that is not a or b.
Index third_vertex(const Level& L, Index f, Index a, Index b, const CompiledTerm& t) {
  if (L.face_size(f) != 3)
    throw Error(fmt::format("{}: role {} needs triangles, but face {} has {} vertices", t.where,
                            subdiv::quoted(role_name(t.role)), f, L.face_size(f)));
  for (Index u : L.face(f))
    if (u != a && u != b) return u;
  return kNone;
}

// Adds the vertex across edge (p, q) from r, in the triangle beyond; where there is none
// (a boundary), the reflection p + q - r keeps linear precision.
void add_across(RowBuilder& row, const Level& L, Index p, Index q, Index r, double w, const CompiledTerm& t) {
  const Index e = find_edge(L, p, q);
  const Index f0 = L.edge_faces[2 * e], f1 = L.edge_faces[2 * e + 1];
  if (f1 == kNone) {
    row.add(p, w), row.add(q, w), row.add(r, -w);
    return;
  }
  const Index f = third_vertex(L, f0, p, q, t) == r ? f1 : f0;
  row.add(third_vertex(L, f, p, q, t), w);
}

// The ring of `end`, counted CCW from edge e (j = 0 is the edge's other end).
void add_end_ring(RowBuilder& row, const Level& L, Index e, Index end, const CompiledTerm& t, int n0, int n1, int k0,
                  int k1, const SectorVariables& sv, double scale) {
  const auto ring = L.ring_edges(end);
  const int n = int(ring.size());
  int start = 0;
  while (start < n && ring[start] != e) ++start;
  for (int j = 0; j < n; ++j)
    row.add(L.other_end(ring[(start + j) % n], end), scale * t.edge_weight(0, j, n0, n1, k0, k1, sv));
}

// The points p_0 .. p_m of end's sector that holds the edge (end_sectors.h); none where the
// end is not a feature vertex.
void add_end_sector(RowBuilder& row, const Level& L, Index end, const EndSector& sector, const CompiledTerm& t, int n0,
                    int n1, int k0, int k1, const SectorVariables& sv, double scale) {
  const auto ring = L.ring_edges(end);
  const int n = int(ring.size());
  for (int j = 0; sector.faces > 0 && j <= sector.faces; ++j)
    row.add(L.other_end(ring[(sector.first + j) % n], end), scale * t.edge_weight(0, j, n0, n1, k0, k1, sv));
}


// A registered role (plugins): its points around the element, point j weighted by the term's
// formula at (n, k, j, n0, n1).
template <typename WeightOf>
bool add_registered_role(RowBuilder& row, const RuleInputs& in, const CompiledTerm& t, Index element, int corner,
                         double scale, WeightOf weight_of) {
  const RoleInfo* info = registered_role(t.role);
  if (!info) return false;
  thread_local std::vector<Index> points;
  points.clear();
  info->points(in.parent, element, corner, points);
  if (int(points.size()) > t.max_j + 1)
    throw Error(fmt::format("{}: role {} ({}) gave {} points, more than its max_points ({})", t.where, subdiv::quoted(info->name),
                            info->origin, points.size(), t.max_j + 1));
  for (int j = 0; j < int(points.size()); ++j) {
    if (points[j] < 0 || points[j] >= in.parent.vertex_count)
      throw Error(fmt::format("{}: role {} ({}) gave vertex {}, not a vertex of the level", t.where, subdiv::quoted(info->name),
                              info->origin, points[j]));
    add_point(row, in, t, points[j], scale * weight_of(j));
  }
  return true;
}

}  // namespace

void apply_segment_curve_rule(RowBuilder& row, const RuleInputs& in, Index e, Index a, Index b,
                              const CompiledRule& rule, double scale) {
  const Level& L = in.parent;
  // The curve edge beyond `end`, away from e, or kNone where the curve ends there.
  auto beyond = [&](Index end) -> Index {
    const VertexContext& vc = in.features.vertices[end];
    if (vc.parent != Context::Crease) return kNone;
    const auto ring = L.ring_edges(end);
    const Index x = ring[vc.parent_crease[0]], y = ring[vc.parent_crease[1]];
    return x == e ? y : x;
  };
  for (const CompiledTerm& t : rule.terms) {
    for (size_t i = 0; i < t.curve_weights.size(); ++i) {
      const int offset = t.curve_start + int(i);
      const double w = scale * t.curve_weights[i];
      if (offset == 0) row.add(a, w);
      else if (offset == 1) row.add(b, w);
      else if (offset < 0) {
        const Index back = beyond(a);
        if (back != kNone) add_curve_point(row, L, in.features, a, back, -offset, w);
        else row.add(a, w * (1 - offset)), row.add(b, w * offset);  // extrapolate past a
      } else {
        const Index forward = beyond(b);
        if (forward != kNone) add_curve_point(row, L, in.features, b, forward, offset - 1, w);
        else row.add(b, w * offset), row.add(a, -w * (offset - 1));  // extrapolate past b
      }
    }
  }
}

void apply_vertex_rule(RowBuilder& row, const RuleInputs& in, Index v, const CompiledRule& rule,
                       const std::array<std::uint16_t, 2>& crease, double scale) {
  const Level& L = in.parent;
  const auto ring = L.ring_edges(v);
  const auto faces = L.ring_faces(v);
  const int n = int(ring.size());
  for (const CompiledTerm& t : rule.terms) {
    switch (t.role) {
      case Role::Self: row.add(v, scale * t.weight(n, 0, 0)); break;
      case Role::Ring:
        for (int j = 0; j < n; ++j) row.add(L.other_end(ring[j], v), scale * t.weight(n, 0, j));
        break;
      case Role::Faces:
        for (int j = 0; j < int(faces.size()); ++j)
          add_point(row, in, t, faces[j], scale * t.weight(n, L.face_size(faces[j]), j));
        break;
      case Role::FaceCentroids:
        for (int j = 0; j < int(faces.size()); ++j) {
          const int k = L.face_size(faces[j]);
          const double w = scale * t.weight(n, k, j) / k;
          for (Index u : L.face(faces[j])) row.add(u, w);
        }
        break;
      case Role::Edges:
        for (int j = 0; j < n; ++j) add_point(row, in, t, ring[j], scale * t.weight(n, 0, j));
        break;
      case Role::Diagonals:
        for (int j = 0; j < int(faces.size()); ++j) {
          const Index f = faces[j];
          if (L.face_size(f) != 4)
            throw Error(fmt::format("{}: role 'diagonals' needs quads, but face {} has {} vertices", t.where, f,
                                    L.face_size(f)));
          const int c = L.vertex_face_corner[L.vertex_face_offsets[v] + j];
          row.add(L.face(f)[(c + 2) % 4], scale * t.weight(n, 4, j));
        }
        break;
      case Role::CreaseNeighbours:
        for (int j = 0; j < 2; ++j) row.add(L.other_end(ring[crease[j]], v), scale * t.weight(n, 0, j));
        break;
      case Role::CreasePoint:
        // Negative steps walk out along the first crease edge (towards the nearest corner,
        // where the rule was chosen by its distance), positive ones along the second.
        if (t.step == 0) row.add(v, scale * t.weight(n, 0, 0));
        else add_curve_point(row, L, in.features, v, ring[crease[t.step < 0 ? 0 : 1]], std::abs(t.step), scale * t.weight(n, 0, 0));
        break;
      case Role::Curve:
        // Offsets <= 0 walk out along the first crease edge, > 0 along the second.
        for (size_t i = 0; i < t.curve_weights.size(); ++i) {
          const int offset = t.curve_start + int(i);
          const double w = scale * t.curve_weights[i];
          if (offset <= 0) add_curve_point(row, L, in.features, v, ring[crease[0]], -offset, w);
          else add_curve_point(row, L, in.features, v, ring[crease[1]], offset, w);
        }
        break;
      default:
        if (!add_registered_role(row, in, t, v, 0, scale, [&](int j) { return t.weight(n, 0, j); }))
          wrong_role(t, Element::Vertex);
    }
  }
}

namespace {

// How much of an end's sector stencil an edge takes: all of it while the end stays a feature
// vertex one level down; where its features decay to smooth this level (a semi-sharp crease
// ending), the vertex rules' fractional weight (DeRose, Kass & Truong 1998; OpenSubdiv's
// Sdc::Crease::ComputeFractionalWeightAtVertex), so that the surface moves continuously as the
// sharpness goes to 0 rather than jumping from the sector stencil to the smooth one.
double sector_share(const FeatureContexts& F, Index v) {
  const VertexContext& vc = F.vertices[v];
  const bool sectors_end = vc.child == Context::Smooth || vc.child == Context::Dart;
  return sectors_end && vc.child != vc.parent ? double(vc.parent_weight) : 1.0;
}

// The rule's terms for edge e = (a, b) with the given ends' sectors (none: faces = 0).
void add_edge_terms(RowBuilder& row, const RuleInputs& in, Index e, const CompiledRule& rule,
                    const EndSector& sector_a, const EndSector& sector_b, double scale) {
  const Level& L = in.parent;
  const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
  const Index faces[2] = {L.edge_faces[2 * e], L.edge_faces[2 * e + 1]};
  const int face_count = faces[1] == kNone ? 1 : 2;
  const int n0 = L.valence(a), n1 = L.valence(b);
  // Sizes of the edge's two faces (0: none), for formulas that weigh by both (k0, k1).
  const int k0 = L.face_size(faces[0]), k1 = face_count == 2 ? L.face_size(faces[1]) : 0;
  const SectorVariables sv = sector_variables(sector_a, sector_b);
  for (const CompiledTerm& t : rule.terms) {
    switch (t.role) {
      case Role::Ends:
        row.add(a, scale * t.edge_weight(0, 0, n0, n1, k0, k1, sv));
        row.add(b, scale * t.edge_weight(0, 1, n0, n1, k0, k1, sv));
        break;
      case Role::Faces:
        for (int j = 0; j < face_count; ++j)
          add_point(row, in, t, faces[j], scale * t.edge_weight(L.face_size(faces[j]), j, n0, n1, k0, k1, sv));
        break;
      case Role::Opposite:
      case Role::Wings:
        for (int j = 0; j < face_count; ++j)
          row.add(third_vertex(L, faces[j], a, b, t), scale * t.edge_weight(3, j, n0, n1, k0, k1, sv));
        break;
      case Role::FarWings:
        // Triangle j runs (p, q, c); its far wings lie across (q, c) and (c, p).
        for (int j = 0; j < face_count; ++j) {
          const Index p = j == 0 ? a : b, q = j == 0 ? b : a;
          const Index c = third_vertex(L, faces[j], a, b, t);
          add_across(row, L, q, c, p, scale * t.edge_weight(3, 2 * j, n0, n1, k0, k1, sv), t);
          add_across(row, L, c, p, q, scale * t.edge_weight(3, 2 * j + 1, n0, n1, k0, k1, sv), t);
        }
        break;
      case Role::EndRing0: add_end_ring(row, L, e, a, t, n0, n1, k0, k1, sv, scale); break;
      case Role::EndRing1: add_end_ring(row, L, e, b, t, n0, n1, k0, k1, sv, scale); break;
      case Role::EndSector0: add_end_sector(row, L, a, sector_a, t, n0, n1, k0, k1, sv, scale); break;
      case Role::EndSector1: add_end_sector(row, L, b, sector_b, t, n0, n1, k0, k1, sv, scale); break;
      case Role::Curve: {
        CompiledRule single;
        single.terms.push_back(t);
        apply_segment_curve_rule(row, in, e, a, b, single, scale);
        break;
      }
      default:
        if (!add_registered_role(row, in, t, e, 0, scale, [&](int j) { return t.edge_weight(0, j, n0, n1, k0, k1, sv); }))
          wrong_role(t, Element::Edge);
    }
  }
}

}  // namespace

void apply_edge_rule(RowBuilder& row, const RuleInputs& in, Index e, const CompiledRule& rule, double scale) {
  EndSector sector_a, sector_b;
  if (reads_sectors(rule)) {
    const Level& L = in.parent;
    sector_a = end_sector(L, in.features, e, L.edge_vertices[2 * e]);
    sector_b = end_sector(L, in.features, e, L.edge_vertices[2 * e + 1]);
  }
  const double share_a = sector_a.faces ? sector_share(in.features, in.parent.edge_vertices[2 * e]) : 1.0;
  const double share_b = sector_b.faces ? sector_share(in.features, in.parent.edge_vertices[2 * e + 1]) : 1.0;
  // Each end's sector in with its share and out with the rest, bilinearly over the two ends.
  for (const bool with_a : {true, false})
    for (const bool with_b : {true, false}) {
      const double w = (with_a ? share_a : 1.0 - share_a) * (with_b ? share_b : 1.0 - share_b);
      if (w > 0.0)
        add_edge_terms(row, in, e, rule, with_a ? sector_a : EndSector{}, with_b ? sector_b : EndSector{}, scale * w);
    }
}

namespace {

// What the corner roles of a face rule see (formula.h: ci, cb, ex, fe).
struct FaceCorners {
  int k = 0;
  int first = 0;         // the corner counted as ci = 0
  int feature_edges = 0; // fe: face edges on a boundary or sharp
  int extraordinary = 0; // ex: corners inside the surface whose valence is not the regular one
};

// The valence of a regular interior vertex among faces of size k (6 for triangles, 4 for
// quads); 0 where no regular tiling has such faces.
int regular_valence(int k) { return (k == 3 || k == 4) ? 2 * k / (k - 2) : 0; }

// cb: a corner whose vertex lies on a boundary or crease (its context is crease or corner).
bool on_feature(const RuleInputs& in, Index v) {
  const Context c = in.features.vertices[v].parent;
  return c == Context::Crease || c == Context::Corner;
}

FaceCorners face_corners(const RuleInputs& in, Index f) {
  const Level& L = in.parent;
  const auto verts = L.face(f);
  const auto edges = L.face_edge_list(f);
  FaceCorners fc;
  fc.k = int(verts.size());
  int feature_edge = -1, smooth_edge = -1;
  for (int i = 0; i < fc.k; ++i) {
    const bool sharp = in.features.edge_sharpness[edges[i]] > 0.f;
    fc.feature_edges += sharp;
    (sharp ? feature_edge : smooth_edge) = i;
  }
  // A triangle with one feature edge is counted from the corner across it, one with two
  // from the corner between them (across the smooth edge); edge i joins corners i, i + 1.
  if (fc.k == 3 && fc.feature_edges == 1) fc.first = (feature_edge + 2) % 3;
  if (fc.k == 3 && fc.feature_edges == 2) fc.first = (smooth_edge + 2) % 3;
  const int regular = regular_valence(fc.k);
  for (Index v : verts) fc.extraordinary += !on_feature(in, v) && L.valence(v) != regular;
  return fc;
}

// The ring of the vertex at `corner` of face f, CCW from the face's previous vertex
// (j = 0) to its next one (j = n - 1); a boundary vertex's ring wraps across its gap.
void add_corner_ring(RowBuilder& row, const RuleInputs& in, Index f, int corner, const FaceCorners& fc,
                     const CompiledTerm& t) {
  const Level& L = in.parent;
  const Index v = L.face(f)[corner];
  const Index arriving = L.face_edge_list(f)[(corner + fc.k - 1) % fc.k];  // previous vertex -> v
  const auto ring = L.ring_edges(v);
  const int n = int(ring.size());
  int start = 0;
  while (start < n && ring[start] != arriving) ++start;
  const int ci = (corner - fc.first + fc.k) % fc.k, cb = on_feature(in, v);
  for (int j = 0; j < n; ++j)
    add_point(row, in, t, L.other_end(ring[(start + j) % n], v),
              t.corner_weight(n, fc.k, j, ci, cb, fc.extraordinary, fc.feature_edges));
}

}  // namespace

void apply_face_rule(RowBuilder& row, const RuleInputs& in, Index f, const CompiledRule& rule) {
  const Level& L = in.parent;
  const auto verts = L.face(f);
  const auto edges = L.face_edge_list(f);
  const int k = int(verts.size());
  const FaceCorners fc = face_corners(in, f);
  const int ex = fc.extraordinary, fe = fc.feature_edges;
  for (const CompiledTerm& t : rule.terms) {
    switch (t.role) {
      case Role::Vertices:
        for (int j = 0; j < k; ++j) add_point(row, in, t, verts[j], t.corner_weight(k, k, j, 0, 0, ex, fe));
        break;
      case Role::Edges:
        for (int j = 0; j < k; ++j) add_point(row, in, t, edges[j], t.corner_weight(k, k, j, 0, 0, ex, fe));
        break;
      case Role::Corners:
        for (int c = 0; c < k; ++c) {
          const int ci = (c - fc.first + k) % k;
          add_point(row, in, t, verts[c],
                    t.corner_weight(L.valence(verts[c]), k, ci, ci, on_feature(in, verts[c]), ex, fe));
        }
        break;
      case Role::CornerRings:
        for (int c = 0; c < k; ++c) add_corner_ring(row, in, f, c, fc, t);
        break;
      default:
        if (!add_registered_role(row, in, t, f, 0, 1.0, [&](int j) { return t.corner_weight(k, k, j, 0, 0, ex, fe); }))
          wrong_role(t, Element::Face);
    }
  }
}

void apply_corner_rule(RowBuilder& row, const RuleInputs& in, Index f, int corner, const CompiledRule& rule, double scale) {
  const Level& L = in.parent;
  const auto verts = L.face(f);
  const int k = int(verts.size());
  for (const CompiledTerm& t : rule.terms) {
    switch (t.role) {
      case Role::Self: row.add(verts[corner], scale * t.weight(k, k, 0)); break;
      case Role::Vertices:
        for (int j = 0; j < k; ++j) row.add(verts[(corner + j) % k], scale * t.weight(k, k, j));
        break;
      default:
        if (!add_registered_role(row, in, t, f, corner, scale, [&](int j) { return t.weight(k, k, j); }))
          wrong_role(t, Element::Corner);
    }
  }
}

}  // namespace subdiv
