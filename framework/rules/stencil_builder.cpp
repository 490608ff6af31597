#include "framework/rules/stencil_builder.h"

#include <atomic>
#include <cmath>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "framework/rules/feature_curve.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

constexpr double kSumTolerance = 1e-9;
constexpr Index kChunk = 1024;

struct StepInputs {
  const Level& parent;
  const WeightTables& tables;
  const FeatureContexts& features;
  const RowBlock* blocks[kElementCount] = {nullptr, nullptr, nullptr};
};

const RowBlock& new_points(const StepInputs& in, NewPoint kind, const CompiledTerm& term) {
  const Element e = kind == NewPoint::Face ? Element::Face : kind == NewPoint::Edge ? Element::Edge
                                                                                     : Element::Vertex;
  const RowBlock* block = in.blocks[int(e)];
  if (!block)
    throw Error(fmt::format("{}: uses new {} points, which this step does not make", term.where,
                            element_name(e)));
  return *block;
}

// Adds a point of a role: a parent vertex, or (with "new") the new point of an element.
void add_point(RowBuilder& row, const StepInputs& in, const CompiledTerm& term, Index element, double w) {
  if (term.new_point == NewPoint::None) row.add(element, w);
  else row.add_row(new_points(in, term.new_point, term), element, w);
}

void add_curve_term(RowBuilder& row, const StepInputs& in, const CompiledTerm& term, Index a,
                    Index edge_back, Index edge_forward, int forward_origin, Index b, double scale) {
  // Offsets <= 0 walk from a (back), offsets >= forward_origin walk from b (forward).
  for (size_t t = 0; t < term.curve_weights.size(); ++t) {
    const int offset = term.curve_start + int(t);
    const double w = scale * term.curve_weights[t];
    if (offset <= 0) add_curve_point(row, in.parent, in.features, a, edge_back, -offset, w);
    else add_curve_point(row, in.parent, in.features, b, edge_forward, offset - forward_origin, w);
  }
}

void apply_vertex_rule(RowBuilder& row, const StepInputs& in, Index v, const CompiledRule& rule,
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
      case Role::Edges:
        for (int j = 0; j < n; ++j) add_point(row, in, t, ring[j], scale * t.weight(n, 0, j));
        break;
      case Role::Curve:
        add_curve_term(row, in, t, v, ring[crease[0]], ring[crease[1]], 0, v, scale);
        break;
      default: throw Error(fmt::format("{}: role '{}' is not a vertex role", t.where, role_name(t.role)));
    }
  }
}

Index opposite_vertex(const Level& L, Index f, Index a, Index b, const CompiledTerm& t) {
  if (L.face_size(f) != 3)
    throw Error(fmt::format("{}: role 'opposite' needs triangles, but face {} has {} vertices",
                            t.where, f, L.face_size(f)));
  for (Index u : L.face(f))
    if (u != a && u != b) return u;
  return kNone;
}

void apply_edge_rule(RowBuilder& row, const StepInputs& in, Index e, const CompiledRule& rule, double scale) {
  const Level& L = in.parent;
  const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
  const Index face_of_edge[2] = {L.edge_faces[2 * e], L.edge_faces[2 * e + 1]};
  const int face_count = face_of_edge[1] == kNone ? 1 : 2;
  for (const CompiledTerm& t : rule.terms) {
    switch (t.role) {
      case Role::Ends:
        row.add(a, scale * t.weight(2, 0, 0));
        row.add(b, scale * t.weight(2, 0, 1));
        break;
      case Role::Faces:
        for (int j = 0; j < face_count; ++j)
          add_point(row, in, t, face_of_edge[j], scale * t.weight(2, L.face_size(face_of_edge[j]), j));
        break;
      case Role::Opposite:
        for (int j = 0; j < face_count; ++j)
          row.add(opposite_vertex(L, face_of_edge[j], a, b, t), scale * t.weight(2, 3, j));
        break;
      case Role::Curve: {
        const auto& fa = in.features.vertices[a];
        const auto& fb = in.features.vertices[b];
        const Index back = fa.parent == Context::Crease ? L.ring_edges(a)[fa.parent_crease[0]] == e
                                                              ? L.ring_edges(a)[fa.parent_crease[1]]
                                                              : L.ring_edges(a)[fa.parent_crease[0]]
                                                        : kNone;
        const Index forward = fb.parent == Context::Crease ? L.ring_edges(b)[fb.parent_crease[0]] == e
                                                                 ? L.ring_edges(b)[fb.parent_crease[1]]
                                                                 : L.ring_edges(b)[fb.parent_crease[0]]
                                                           : kNone;
        // Walking back from a starts along `back`; offsets from b count from 1.
        for (size_t i = 0; i < t.curve_weights.size(); ++i) {
          const int offset = t.curve_start + int(i);
          const double w = scale * t.curve_weights[i];
          if (offset <= 0) {
            if (offset == 0) row.add(a, w);
            else if (back != kNone) add_curve_point(row, L, in.features, a, back, -offset, w);
            else row.add(a, w * (1 - offset)), row.add(b, w * offset);  // extrapolate past a
          } else {
            if (offset == 1) row.add(b, w);
            else if (forward != kNone) add_curve_point(row, L, in.features, b, forward, offset - 1, w);
            else row.add(b, w * offset), row.add(a, -w * (offset - 1));  // extrapolate past b
          }
        }
        break;
      }
      default: throw Error(fmt::format("{}: role '{}' is not an edge role", t.where, role_name(t.role)));
    }
  }
}

void apply_face_rule(RowBuilder& row, const StepInputs& in, Index f, const CompiledRule& rule) {
  const Level& L = in.parent;
  const auto verts = L.face(f);
  const auto edges = L.face_edge_list(f);
  const int k = int(verts.size());
  for (const CompiledTerm& t : rule.terms) {
    switch (t.role) {
      case Role::Vertices:
        for (int j = 0; j < k; ++j) add_point(row, in, t, verts[j], t.weight(k, k, j));
        break;
      case Role::Edges:
        for (int j = 0; j < k; ++j) add_point(row, in, t, edges[j], t.weight(k, k, j));
        break;
      default: throw Error(fmt::format("{}: role '{}' is not a face role", t.where, role_name(t.role)));
    }
  }
}

const CompiledRule& needed_rule(const WeightTables& tables, Element e, Context c, const std::string& source) {
  const CompiledRule& rule = tables.rule(e, c);
  if (!rule.defined)
    throw Error(fmt::format(
        "{}: the mesh needs a {} rule for the '{}' context, and the scheme has none; add "
        "rules.{}.{} or name a boundary curve scheme with \"curve\"",
        source, element_name(e), context_name(c), element_name(e), context_name(c)));
  return rule;
}

void fill_row(RowBuilder& row, const StepInputs& in, Element element, Index id, const std::string& source) {
  const WeightTables& T = in.tables;
  if (element == Element::Face) {
    apply_face_rule(row, in, id, needed_rule(T, Element::Face, Context::Smooth, source));
  } else if (element == Element::Edge) {
    const float cw = in.features.edges[id].crease_weight;
    // cw may exceed 1 (OpenSubdiv's unclamped Chaikin transition, see classify_edge).
    if (cw != 1.f) apply_edge_rule(row, in, id, needed_rule(T, Element::Edge, Context::Smooth, source), 1.0 - cw);
    if (cw > 0.f) apply_edge_rule(row, in, id, needed_rule(T, Element::Edge, Context::Crease, source), cw);
  } else {
    const VertexContext& vc = in.features.vertices[id];
    const double pw = vc.child == vc.parent ? 1.0 : vc.parent_weight;
    if (pw > 0.0)
      apply_vertex_rule(row, in, id, needed_rule(T, Element::Vertex, vc.parent, source), vc.parent_crease, pw);
    if (pw < 1.0)
      apply_vertex_rule(row, in, id, needed_rule(T, Element::Vertex, vc.child, source), vc.child_crease, 1.0 - pw);
  }
}

Index element_count(const Level& L, Element e) {
  return e == Element::Face ? L.face_count() : e == Element::Edge ? L.edge_count() : L.vertex_count;
}

// Rows of one element kind, built in parallel chunks and joined in order, so the result
// does not depend on the thread count. Checks every row is finite and sums to one.
RowBlock build_block(const StepInputs& in, Element element, const std::string& source) {
  const Index count = element_count(in.parent, element);
  const Index chunks = (count + kChunk - 1) / kChunk;
  std::vector<RowBlock> parts(chunks);
  std::atomic<Index> first_bad{count};
  tbb::parallel_for(Index(0), chunks, [&](Index c) {
    RowBuilder row;
    RowBlock& part = parts[c];
    for (Index id = c * kChunk; id < std::min(count, (c + 1) * kChunk); ++id) {
      row.clear();
      fill_row(row, in, element, id, source);
      double sum = 0.0;
      for (size_t i = 0; i < row.indices().size(); ++i) {
        sum += row.weights()[i];
        part.indices.push_back(row.indices()[i]);
        part.weights.push_back(row.weights()[i]);
      }
      part.offsets.push_back(Index(part.indices.size()));
      if (!std::isfinite(sum) || std::abs(sum - 1.0) > kSumTolerance) {
        Index seen = first_bad.load();
        while (id < seen && !first_bad.compare_exchange_weak(seen, id)) {}
      }
    }
  });
  RowBlock block;
  size_t total = 0;
  for (const auto& p : parts) total += p.indices.size();
  block.offsets.reserve(count + 1);
  block.indices.reserve(total);
  block.weights.reserve(total);
  for (const auto& p : parts) {
    const Index base = block.offsets.back();
    for (size_t r = 1; r < p.offsets.size(); ++r) block.offsets.push_back(base + p.offsets[r]);
    block.indices.insert(block.indices.end(), p.indices.begin(), p.indices.end());
    block.weights.insert(block.weights.end(), p.weights.begin(), p.weights.end());
  }
  if (first_bad < count) {
    const Index id = first_bad;
    double sum = 0.0;
    for (Index i = block.offsets[id]; i < block.offsets[id + 1]; ++i) sum += block.weights[i];
    throw Error(fmt::format(
        "{}: the new point of {} {} has weights summing to {} instead of 1 (valence {}); every "
        "rule must be affine: check the weight formulas of the {} rules",
        source, element_name(element), id, sum,
        element == Element::Vertex ? in.parent.valence(id) : element == Element::Face ? in.parent.face_size(id) : 2,
        element_name(element)));
  }
  return block;
}

bool references(const WeightTables& T, Element from, NewPoint to) {
  for (const auto& rule : T.rules[int(from)])
    for (const auto& term : rule.terms)
      if (term.new_point == to) return true;
  return false;
}

// Element kinds in an order where referenced new points come first.
std::vector<Element> build_order(const WeightTables& T, const ChildLayout& layout, const std::string& source) {
  const NewPoint as_new[kElementCount] = {NewPoint::Face, NewPoint::Edge, NewPoint::Vertex};
  std::vector<Element> order;
  bool placed[kElementCount] = {false, false, false};
  for (int round = 0; round < kElementCount; ++round) {
    for (int e = 0; e < kElementCount; ++e) {
      if (placed[e] || layout.first[e] == kNone) continue;
      bool ready = true;
      for (int d = 0; d < kElementCount; ++d)
        if (d != e && !placed[d] && references(T, Element(e), as_new[d])) ready = false;
      if (references(T, Element(e), as_new[e]))
        throw Error(fmt::format("{}: the {} rules use new {} points, which they define", source,
                                element_name(Element(e)), element_name(Element(e))));
      if (ready) placed[e] = true, order.push_back(Element(e));
    }
  }
  for (int e = 0; e < kElementCount; ++e)
    if (layout.first[e] != kNone && !placed[e])
      throw Error(fmt::format("{}: the face, edge and vertex rules refer to each other's new points in a cycle", source));
  return order;
}

}  // namespace

ChildLayout primal_layout(const Level& parent, SplitKind split) {
  ChildLayout layout;
  layout.first[int(Element::Vertex)] = 0;
  layout.first[int(Element::Edge)] = parent.vertex_count;
  if (split == SplitKind::Quad) layout.first[int(Element::Face)] = parent.vertex_count + parent.edge_count();
  return layout;
}

StencilTable build_step_stencils(const Level& parent, const ChildLayout& layout,
                                 const WeightTables& tables, const FeatureContexts& features,
                                 const std::string& source) {
  StepInputs in{parent, tables, features};
  RowBlock blocks[kElementCount];
  for (Element e : build_order(tables, layout, source)) {
    blocks[int(e)] = build_block(in, e, source);
    in.blocks[int(e)] = &blocks[int(e)];
  }
  // Join the blocks in child numbering order.
  std::vector<Element> by_position;
  for (int e = 0; e < kElementCount; ++e)
    if (layout.first[e] != kNone) by_position.push_back(Element(e));
  std::sort(by_position.begin(), by_position.end(),
            [&](Element a, Element b) { return layout.first[int(a)] < layout.first[int(b)]; });
  StencilTable table;
  table.source_count = parent.vertex_count;
  for (Element e : by_position) {
    const RowBlock& b = blocks[int(e)];
    const Index base = table.offsets.back();
    for (size_t r = 1; r < b.offsets.size(); ++r) table.offsets.push_back(base + b.offsets[r]);
    table.indices.insert(table.indices.end(), b.indices.begin(), b.indices.end());
    table.weights.insert(table.weights.end(), b.weights.begin(), b.weights.end());
  }
  return table;
}

}  // namespace subdiv
