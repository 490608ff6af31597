#include "framework/rules/step_rows.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "framework/features/dual_features.h"
#include "framework/rules/feature_curve.h"
#include "framework/rules/row_plans.h"
#include "framework/util/error.h"
#include "framework/util/input_file.h"
#include "framework/util/json_path_line.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

const CompiledRule& needed_rule(const WeightTables& tables, Element e, Context c, const std::string& source) {
  const CompiledRule& rule = tables.rule(e, c);
  if (!rule.defined)
    throw Error(fmt::format(
        "{}: the mesh needs a rule for new {} points in the {} context, and the scheme has none; "
        "add rules.{}.{}{}",
        source, element_name(e), subdiv::quoted(context_name(c)), element_name(e), context_name(c),
        c == Context::Crease ? " or name a boundary curve scheme with \"curve\"" : ""));
  return rule;
}

const CompiledRule& curve_rule(const StepContext& s, int r, Element e, const WeightTables& tables) {
  if (r >= int(tables.curve_rules.size()))
    throw Error(fmt::format("{}: the mesh has boundaries or creases, and the scheme has neither a crease rule for "
                            "new {} points nor a curve scheme (\"curve\") to give one",
                            s.source, element_name(e)));
  return tables.curve_rules[r];
}

const CompiledRule& curve_rule(const StepContext& s, int r, Element e) { return curve_rule(s, r, e, s.tables); }

// Code rules (plugins) cover smooth contexts, or every context with handles_features.
bool code_covers(const StepContext& s, bool has_function, Context c) {
  return s.code && has_function && (s.code->handles_features || c == Context::Smooth || c == Context::Dart);
}

// A stated `crease` corner rule is written for the sharp edge leaving the corner (the face's
// next vertex, j = 1, lies on it). Where the sharp edge arrives (the previous vertex on it),
// it is applied mirrored, j counted clockwise, so the two points of a corner between two
// sharp edges are the rule on each edge, not one point twice (docs/features.md).
void apply_stated_crease_rule(RowBuilder& row, const RuleInputs& in, Index f, int corner, const CompiledRule& rule,
                              bool arriving, double scale) {
  if (!arriving) return apply_corner_rule(row, in, f, corner, rule, scale);
  const auto verts = in.parent.face(f);
  const int k = int(verts.size());
  for (const CompiledTerm& t : rule.terms) {
    if (t.role == Role::Self) row.add(verts[corner], scale * t.weight(k, k, 0));
    else if (t.role == Role::Vertices)
      for (int j = 0; j < k; ++j) row.add(verts[(corner - j + k) % k], scale * t.weight(k, k, j));
    else
      throw Error(fmt::format("{}: a corner 'crease' rule is applied mirrored where the sharp edge arrives at the "
                              "corner, and role {} cannot be mirrored; use 'self' and 'vertices', or leave the "
                              "rule out so the scheme's \"curve\" gives it",
                              t.where, subdiv::quoted(role_name(t.role))));
  }
}

// A dual split's point on a sharp segment a -> b near its end `near` (a: rule 0; b: rule 1),
// where the far end collapses into a corner (features/dual_features.h): there the segment's
// two cuts merge into their mean, (a + b) / 2 for Chaikin. Chaikin's cuts are knot insertion
// for the uniform quadratic B-spline; with the knots clamped (triple) at a corner, inserting
// the midpoints gives the corner, the end segment's midpoint, then Chaikin's cuts (Boehm
// 1980, "Inserting new knots into B-spline curves"), and the child knots are clamped and
// uniform again, so the rule repeats: the crease is the open quadratic B-spline that
// interpolates the corner, tangent to its first edge (docs/features.md, "Corners").
void apply_dual_segment_rule(RowBuilder& row, const StepContext& s, const RuleInputs& in, Index e, Index a, Index b,
                             bool near_a, double w) {
  const Index far = near_a ? b : a;
  if (dual_collapses(s.parent, far) && !dual_collapses(s.parent, near_a ? a : b)) {
    apply_segment_curve_rule(row, in, e, a, b, curve_rule(s, 0, Element::Corner), 0.5 * w);
    return apply_segment_curve_rule(row, in, e, a, b, curve_rule(s, 1, Element::Corner), 0.5 * w);
  }
  apply_segment_curve_rule(row, in, e, a, b, curve_rule(s, near_a ? 0 : 1, Element::Corner), w);
}

// The crease-end rule for a crease vertex this far from its corners: the one for its crease's
// length and distance, else the one for its distance, else none (the `crease` rule).
const CompiledRule* crease_end_rule(const CreaseEndTable<CompiledRule>& ends, const CornerDistance& d) {
  if (d.distance <= 0) return nullptr;
  const size_t at = size_t(d.distance);
  if (const auto it = ends.by_length.find(d.length); d.length > 0 && it != ends.by_length.end())
    if (at < it->second.size() && it->second[at].defined) return &it->second[at];
  if (at < ends.by_distance.size() && ends.by_distance[at].defined) return &ends.by_distance[at];
  return nullptr;
}

void fill_vertex_row(RowBuilder& row, const StepContext& s, const RuleInputs& in, Index v) {
  const VertexContext& vc = s.features.vertices[v];
  const WeightTables& tables = s.vertex_tables(v);
  auto apply = [&](Context c, const std::array<std::uint16_t, 2>& crease, double w) {
    if (code_covers(s, s.code && s.code->vertex, c)) {
      RowWriter writer(row, w);
      return s.code->vertex({s.parent, s.features, s.level}, v, c, writer);
    }
    if (c == Context::Crease && !tables.crease_ends.empty()) {
      // A rule stated for this distance from the nearest corner, oriented towards it.
      const auto ring = s.parent.ring_edges(v);
      const CornerDistance d = distance_to_corner(s.parent, s.features, v, {ring[crease[0]], ring[crease[1]]},
                                                  tables.crease_ends.search_reach());
      if (const CompiledRule* rule = crease_end_rule(tables.crease_ends, d)) {
        const std::array<std::uint16_t, 2> toward = d.side == 0 ? crease : std::array<std::uint16_t, 2>{crease[1], crease[0]};
        return apply_vertex_rule(row, in, v, *rule, toward, w);
      }
    }
    if (c == Context::Crease && !tables.rule(Element::Vertex, c).defined) {
      if (!s.features_refined) return row.add(v, w);  // feature curves wait for the next step
      return apply_vertex_rule(row, in, v, curve_rule(s, 0, Element::Vertex, tables), crease, w);
    }
    apply_vertex_rule(row, in, v, needed_rule(tables, Element::Vertex, c, s.source), crease, w);
  };
  const double pw = vc.child == vc.parent ? 1.0 : vc.parent_weight;
  if (pw > 0.0) apply(vc.parent, vc.parent_crease, pw);
  if (pw < 1.0) apply(vc.child, vc.child_crease, 1.0 - pw);
}

void fill_edge_row(RowBuilder& row, const StepContext& s, const RuleInputs& in, Index e, int local) {
  float cw = s.features.edges[e].crease_weight;
  const bool code = s.code && s.code->edge;
  if (code && s.code->handles_features) {
    RowWriter writer(row, 1.0);
    return s.code->edge({s.parent, s.features, s.level}, e, local, cw > 0.f ? Context::Crease : Context::Smooth, writer);
  }
  // Splits that make edge points only on features (sqrt3 trisection) have no smooth edge
  // rule: there a semi-sharp feature edge is refined as a crease while it is one.
  if (!code && cw > 0.f && !s.tables.rule(Element::Edge, Context::Smooth).defined) cw = 1.f;
  // cw may exceed 1 (OpenSubdiv's unclamped Chaikin transition, see classify_edge).
  if (cw != 1.f && code) {
    RowWriter writer(row, 1.0 - cw);
    s.code->edge({s.parent, s.features, s.level}, e, local, Context::Smooth, writer);
  } else if (cw != 1.f) {
    apply_edge_rule(row, in, e, needed_rule(s.tables, Element::Edge, Context::Smooth, s.source), 1.0 - cw);
  }
  if (cw <= 0.f) return;
  const CompiledRule& stated = s.tables.rule(Element::Edge, Context::Crease);
  if (stated.defined && local == 0) return apply_edge_rule(row, in, e, stated, cw);
  // The local-th new point along a crease edge is the curve scheme's rule local + 1.
  const Index a = s.parent.edge_vertices[2 * e], b = s.parent.edge_vertices[2 * e + 1];
  apply_segment_curve_rule(row, in, e, a, b, curve_rule(s, local + 1, Element::Edge), cw);
}

// A point of the dual split of a level with features (refine/dual_crease_topology.h, docs/
// features.md "Creases in dual schemes"). A corner's vertex that collapses stays (the
// `corner` rule); a point on a sharp edge is the curve scheme's point on that edge near the
// vertex, rule 0 on the segment leaving the vertex, rule 1 on the one arriving (Chaikin 1974:
// 3/4 v + 1/4 w), or the stated `crease` rule; `side` 1 is a split corner's point on its
// arriving edge. A corner beside semi-sharp edges (0 < s < 1, smooth topology) blends:
// (1 - w_out - w_in) smooth + w_out (rule 0 out) + w_in (rule 1 in), the crease weights
// normalised when they sum past 1; a vertex of sharpness 0 < s < 1 blends s of the corner
// rule in (DeRose, Kass & Truong 1998's fractional sharpness, as the primal rules blend).
template <class Smooth>
void fill_feature_corner_row(RowBuilder& row, const StepContext& s, const RuleInputs& in, Index f, int corner, int side,
                             Smooth smooth) {
  const Level& L = s.parent;
  const int k = L.face_size(f);
  const Index v = L.face(f)[corner];
  const Index out = L.face_edge_list(f)[corner], in_edge = L.face_edge_list(f)[(corner + k - 1) % k];
  const Index next = L.face(f)[(corner + 1) % k], prev = L.face(f)[(corner + k - 1) % k];
  const CompiledRule& corner_rule = needed_rule(s.tables, Element::Corner, Context::Corner, s.source);
  if (dual_collapses(L, v)) return apply_corner_rule(row, in, f, corner, corner_rule, 1.0);
  const float sv = L.vertex_sharp(v);
  double scale = 1.0;
  if (sv > 0.f) apply_corner_rule(row, in, f, corner, corner_rule, sv), scale = 1.0 - sv;
  const CompiledRule& stated = s.tables.rule(Element::Corner, Context::Crease);
  auto leaving = [&](double w) {
    if (stated.defined) return apply_stated_crease_rule(row, in, f, corner, stated, false, w);
    apply_dual_segment_rule(row, s, in, out, v, next, true, w);
  };
  auto arriving = [&](double w) {
    if (stated.defined) return apply_stated_crease_rule(row, in, f, corner, stated, true, w);
    apply_dual_segment_rule(row, s, in, in_edge, prev, v, false, w);
  };
  const bool sharp_out = dual_sharp_edge(L, out), sharp_in = dual_sharp_edge(L, in_edge);
  if (sharp_in && (!sharp_out || side == 1)) return arriving(scale);
  if (sharp_out) return leaving(scale);
  double w_out = std::max(0.f, s.features.edges[out].crease_weight);
  double w_in = std::max(0.f, s.features.edges[in_edge].crease_weight);
  if (w_out + w_in > 1.0) {
    const double sum = w_out + w_in;
    w_out /= sum, w_in /= sum;
  }
  if (w_out + w_in < 1.0) smooth(scale * (1.0 - w_out - w_in));
  if (w_out > 0.0) leaving(scale * w_out);
  if (w_in > 0.0) arriving(scale * w_in);
}

// A face corner beside a sharp face edge follows the (dual) curve scheme along that edge:
// rule 0 for the point near the segment's start, rule 1 near its end (Nasri 1987: the
// boundary follows Chaikin; our crease extension for dual schemes, docs/scheme-format.md).
void fill_corner_row(RowBuilder& row, const StepContext& s, const RuleInputs& in, Index f, int corner, int side) {
  const Level& L = s.parent;
  const int k = L.face_size(f);
  const Index v = L.face(f)[corner];
  const Index out = L.face_edge_list(f)[corner], in_edge = L.face_edge_list(f)[(corner + k - 1) % k];
  const float w_out = s.features.edges[out].crease_weight, w_in = s.features.edges[in_edge].crease_weight;
  const bool corner_vertex = s.features.vertex_sharpness[v] > 0.f || (w_out > 0.f && w_in > 0.f);
  const bool code = s.code && s.code->corner;
  if (code && s.code->handles_features) {
    const Context c = corner_vertex ? Context::Corner : std::max(w_out, w_in) > 0.f ? Context::Crease : Context::Smooth;
    RowWriter writer(row, 1.0);
    return s.code->corner({s.parent, s.features, s.level}, f, corner, c, writer);
  }
  // The smooth part of the row: the code rule or the scheme's smooth corner rule.
  auto smooth = [&](double scale) {
    if (!code) return apply_corner_rule(row, in, f, corner, needed_rule(s.tables, Element::Corner, Context::Smooth, s.source), scale);
    RowWriter writer(row, scale);
    s.code->corner({s.parent, s.features, s.level}, f, corner, Context::Smooth, writer);
  };
  if (side >= 0) return fill_feature_corner_row(row, s, in, f, corner, side, smooth);
  if (corner_vertex) {
    const double w = s.features.vertex_sharpness[v] > 0.f ? 1.0 : std::min(w_out, w_in);
    apply_corner_rule(row, in, f, corner, needed_rule(s.tables, Element::Corner, Context::Corner, s.source), w);
    if (w < 1.0) smooth(1.0 - w);
    return;
  }
  const double w = std::max(w_out, w_in);
  if (w < 1.0) smooth(1.0 - w);
  if (w <= 0.0) return;
  const CompiledRule& stated = s.tables.rule(Element::Corner, Context::Crease);
  if (stated.defined) return apply_stated_crease_rule(row, in, f, corner, stated, w_out <= 0.f, w);
  const Index next = L.face(f)[(corner + 1) % k], prev = L.face(f)[(corner + k - 1) % k];
  if (w_out > 0.f) apply_dual_segment_rule(row, s, in, out, v, next, true, w);
  else apply_dual_segment_rule(row, s, in, in_edge, prev, v, false, w);
}

Index element_count(const Level& L, Element e) {
  switch (e) {
    case Element::Vertex: return L.vertex_count;
    case Element::Edge: return L.edge_count();
    case Element::Face: return L.face_count();
    case Element::Corner: return L.corner_count();
  }
  return 0;
}

bool references(const WeightTables& T, Element from, NewPoint to) {
  for (const auto& rule : T.rules[int(from)])
    for (const auto& term : rule.terms)
      if (term.new_point == to) return true;
  return false;
}

}  // namespace

void fill_row(RowBuilder& row, const StepContext& s, const RuleInputs& in, Index child) {
  const Index p = s.origins.parent[child];
  switch (s.origins.kind[child]) {
    case OriginKind::Vertex: return fill_vertex_row(row, s, in, p);
    case OriginKind::Edge: return fill_edge_row(row, s, in, p, s.origins.local[child]);
    case OriginKind::Face:
      if (s.code && s.code->face) {
        RowWriter writer(row, 1.0);
        return s.code->face({s.parent, s.features, s.level}, p, writer);
      }
      return apply_face_rule(row, in, p, needed_rule(s.tables, Element::Face, Context::Smooth, s.source));
    case OriginKind::Corner:
      return fill_corner_row(row, s, in, p, s.origins.local[child],
                             s.origins.corner_side.empty() ? -1 : int(s.origins.corner_side[child]));
  }
}

namespace {

// The parent element a child hangs off in its kind's group: a corner is numbered over all
// face corners.
Index group_element(const StepContext& s, Index c) {
  const Index p = s.origins.parent[c];
  return s.origins.kind[c] == OriginKind::Corner ? s.parent.face_offsets[p] + s.origins.local[c] : p;
}

// Per kind: whether its children are one run (ChildGroup::run), where it starts, and how
// many children it has.
struct KindRuns {
  bool run[kElementCount] = {true, true, true, true};
  Index first[kElementCount] = {kNone, kNone, kNone, kNone};
  Index count[kElementCount] = {};
};

KindRuns find_runs(const StepContext& s) {
  KindRuns k;
  for (Index c = 0; c < Index(s.origins.kind.size()); ++c) {
    const int kind = int(s.origins.kind[c]);
    if (k.first[kind] == kNone) k.first[kind] = c;
    if (c != k.first[kind] + k.count[kind] || group_element(s, c) != k.count[kind]) k.run[kind] = false;
    ++k.count[kind];
  }
  for (int e = 0; e < kElementCount; ++e)
    if (k.count[e] != element_count(s.parent, Element(e))) k.run[e] = false;
  return k;
}

}  // namespace

// The runs the split declared (child_origins.h): no scan.
KindRuns declared_runs(const ChildRuns& declared) {
  KindRuns k;
  for (int e = 0; e < kElementCount; ++e) k.first[e] = declared.first[e], k.count[e] = declared.count[e];
  return k;
}

std::vector<ChildGroup> group_children(const StepContext& s) {
  const KindRuns runs = s.origins.runs ? declared_runs(*s.origins.runs) : find_runs(s);
  std::vector<ChildGroup> groups;
  for (int e = 0; e < kElementCount; ++e)
    groups.push_back(runs.count[e] == 0 ? ChildGroup()
                     : runs.run[e]      ? ChildGroup::run(runs.first[e], runs.count[e])
                                        : ChildGroup(element_count(s.parent, Element(e)), runs.count[e]));
  if (std::all_of(std::begin(runs.run), std::end(runs.run), [](bool run) { return run; })) return groups;
  for (Index c = 0; c < Index(s.origins.kind.size()); ++c) {
    const int kind = int(s.origins.kind[c]);
    if (!runs.run[kind]) groups[kind].add(group_element(s, c), c);
  }
  return groups;
}

std::vector<Element> build_order(const StepContext& s, const std::vector<ChildGroup>& groups) {
  const NewPoint as_new[kElementCount] = {NewPoint::Vertex, NewPoint::Edge, NewPoint::Face, NewPoint::None};
  std::vector<Element> order;
  bool placed[kElementCount] = {};
  for (int round = 0; round < kElementCount; ++round)
    for (int e = 0; e < kElementCount; ++e) {
      if (placed[e] || groups[e].empty()) continue;
      bool ready = true;
      for (int d = 0; d < kElementCount; ++d)
        if (d != e && !placed[d] && !groups[d].empty() && references(s.tables, Element(e), as_new[d]))
          ready = false;
      if (as_new[e] != NewPoint::None && references(s.tables, Element(e), as_new[e]))
        throw Error(fmt::format("{}: the {} rules use new {} points, which they define", s.source,
                                element_name(Element(e)), element_name(Element(e))));
      if (ready) placed[e] = true, order.push_back(Element(e));
    }
  for (int e = 0; e < kElementCount; ++e)
    if (!groups[e].empty() && !placed[e])
      throw Error(fmt::format("{}: the rules refer to each other's new points in a cycle", s.source));
  return order;
}

namespace {

// The contexts whose rules a new point of element p may have used.
std::vector<Context> contexts_of(const StepContext& s, Element e, Index p) {
  switch (e) {
    case Element::Vertex: {
      const VertexContext& vc = s.features.vertices[p];
      if (vc.child == vc.parent) return {vc.parent};
      return {vc.parent, vc.child};
    }
    case Element::Edge:
      if (s.features.edges[p].crease_weight > 0.f) return {Context::Smooth, Context::Crease};
      return {Context::Smooth};
    case Element::Face: return {Context::Smooth};
    case Element::Corner: return {Context::Smooth, Context::Crease, Context::Corner};
  }
  return {};
}

// "FILE: rules.vertex" as "FILE:LINE: rules.vertex" when the file is readable JSON text.
std::string with_line(const std::string& where, const std::string& file) {
  if (file.empty() || where.rfind(file + ": ", 0) != 0) return where;
  try {
    const std::string text = read_input_file(file, "scheme", 4'000'000);
    const std::string placed = with_json_line(where + ": ", file, text);
    return placed.substr(0, placed.size() - 2);
  } catch (const std::exception&) {
    return where;
  }
}

// The rules (with their places in the scheme file, as `subdiv validate` names them) that
// made a new point of element p.
std::string rule_places(const StepContext& s, Element e, Index p) {
  const WeightTables& tables = e == Element::Vertex ? s.vertex_tables(p) : s.tables;
  std::string list;
  for (Context c : contexts_of(s, e, p)) {
    const CompiledRule& rule = tables.rule(e, c);
    std::string place;
    if (rule.defined && rule.where.rfind(s.source + ": ", 0) == 0)
      place = fmt::format("{} ({})", with_line(rule.where, s.source), context_name(c));
    else if (c == Context::Crease && !tables.curve_rules.empty())
      place = fmt::format("the curve scheme's rules ({})", tables.curve_rules.front().where);
    if (!place.empty() && list.find(place) == std::string::npos) list += (list.empty() ? "" : ", ") + place;
  }
  return list.empty() ? fmt::format("the {} rules", element_name(e)) : list;
}

}  // namespace

double weight_sum(std::span<const double> weights) {
  double sum = 0.0;
  for (double w : weights) sum += w;
  return sum;
}

void FirstBadRow::report_if_any(const StepContext& s, const RuleInputs& in, const ChildGroup& group) const {
  const Index r = first_.load();
  if (r == count_) return;
  s.need_features();
  const Index child = group.child(r);
  RowBuilder row;
  fill_row(row, s, in, child);
  const double sum = weight_sum(row.weights());
  const Index p = s.origins.parent[child];
  const Element e = Element(int(s.origins.kind[child]));
  const int size = e == Element::Vertex ? s.parent.valence(p) : e == Element::Edge ? 2 : s.parent.face_size(p);
  throw Error(fmt::format(
      "{}: the new point of {} {} has weights summing to {} instead of 1 ({} {}); every rule must "
      "be affine and finite: check the weight formulas of {}",
      s.source, element_name(e), p,
      std::isnan(sum) ? std::string("NaN (a formula left its domain there)") : fmt::format("{}", sum),
      e == Element::Vertex ? "valence" : "size", size, rule_places(s, e, p)));
}

ChunkedRows build_rows(const StepContext& s, const RuleInputs& in, const ChildGroup& group, RowPlanStore& plans) {
  const Index count = group.size();
  ChunkedRows rows;
  rows.chunk_rows = kRowChunk;
  rows.chunks.resize((count + kRowChunk - 1) / kRowChunk);
  FirstBadRow first_bad(count);
  tbb::parallel_for(Index(0), Index(rows.chunks.size()), [&](Index c) {
    RowBuilder row;
    RowPlanner planner(plans);
    RowBlock& part = rows.chunks[c];
    const Index begin = c * kRowChunk, end = std::min(count, (c + 1) * kRowChunk);
    part.offsets.reserve(size_t(end - begin) + 1);
    part.indices.reserve(size_t(end - begin) * 12);
    part.weights.reserve(size_t(end - begin) * 12);
    for (Index r = begin; r < end; ++r) {
      const Index child = group.child(r);
      const auto outcome = s.use_row_plans ? planner.try_append(child, part) : RowPlanner::Outcome::Generic;
      if (outcome != RowPlanner::Outcome::Appended) {
        row.clear();
        fill_row(row, s, in, child);
        if (outcome == RowPlanner::Outcome::Learn) planner.learn(row, plans);
        part.indices.insert(part.indices.end(), row.indices().begin(), row.indices().end());
        part.weights.insert(part.weights.end(), row.weights().begin(), row.weights().end());
      }
      const Index from = part.offsets.back();
      part.offsets.push_back(Index(part.indices.size()));
      if (!row_sum_ok(weight_sum({part.weights.data() + from, size_t(part.offsets.back() - from)}))) first_bad.mark(r);
    }
  });
  first_bad.report_if_any(s, in, group);
  return rows;
}

}  // namespace subdiv
