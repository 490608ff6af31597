#include "framework/rules/row_plans.h"

#include <algorithm>

#include "framework/rules/step_rows.h"

namespace subdiv {
namespace {

// Enumerations longer than this (valences in the twenties and up) take the generic path:
// the distinctness check is quadratic, and such vertices are rare.
constexpr size_t kMaxAround = 64;

// Roles whose points lie inside the element's enumeration (row_plans.h).
bool vertex_role_inside(Role r) {
  return r == Role::Self || r == Role::Ring || r == Role::Faces || r == Role::Edges || r == Role::FaceCentroids ||
         r == Role::Diagonals;
}
bool edge_role_inside(Role r) { return r == Role::Ends || r == Role::Opposite || r == Role::Wings || r == Role::Faces; }
bool face_role_inside(Role r) { return r == Role::Vertices; }
// Roles a light enumeration holds (RowPlanStore): no face corners.
bool vertex_role_light(Role r) { return r == Role::Self || r == Role::Ring || r == Role::Faces || r == Role::Edges; }
bool edge_role_light(Role r) { return r == Role::Ends || r == Role::Faces; }

template <class Inside>
bool rule_inside(const CompiledRule& rule, Inside inside, const bool new_point_ok[4]) {
  if (!rule.defined) return false;
  for (const CompiledTerm& t : rule.terms) {
    if (!inside(t.role) || !new_point_ok[int(t.new_point)]) return false;
    // A face's corner variables (formula.h) are not part of a plan's key.
    if (t.stride_ci || t.stride_cb || t.stride_ex || t.stride_fe) return false;
    // Nor are an edge's sector variables (end_sectors.h).
    if (t.reads_sectors()) return false;
  }
  return true;
}

}  // namespace

RowPlanStore::RowPlanStore(const Level& parent_level, const ChildOrigins& child_origins, const WeightTables& tables,
                           const FeatureContexts& feature_contexts, bool code_rules,
                           const std::vector<ChildGroup>* new_point_sources)
    : parent(parent_level), origins(child_origins), features(feature_contexts), sources(new_point_sources) {
  if (code_rules) return;
  const CompiledRule& face = tables.rule(Element::Face, Context::Smooth);
  const CompiledRule& edge = tables.rule(Element::Edge, Context::Smooth);
  const CompiledRule& vertex = tables.rule(Element::Vertex, Context::Smooth);
  // Indexed by NewPoint: None, Face, Edge, Vertex. A face row reads its own face only; an
  // edge row its two faces, inside a vertex's ring; a vertex row reaches past any edge's.
  const bool plain[4] = {true, false, false, false};
  enabled[int(Element::Face)] = rule_inside(face, face_role_inside, plain);
  if (sources) {
    // New face points are sources in the edge's and vertex's enumerations, new edge points
    // in the vertex's.
    const bool faces[4] = {true, true, false, false}, faces_edges[4] = {true, true, true, false};
    enabled[int(Element::Edge)] = rule_inside(edge, edge_role_inside, faces);
    enabled[int(Element::Vertex)] = rule_inside(vertex, vertex_role_inside, faces_edges);
    light[int(Element::Edge)] = rule_inside(edge, edge_role_light, faces);
    light[int(Element::Vertex)] = rule_inside(vertex, vertex_role_light, faces_edges);
    for (int k = 0; k < kElementCount; ++k) {
      for (const CompiledTerm& t : tables.rule(Element(k), Context::Smooth).terms) {
        reads_face_points[k] |= t.new_point == NewPoint::Face;
        reads_edge_points[k] |= t.new_point == NewPoint::Edge;
      }
    }
    return;
  }
  const bool faces[4] = {true, enabled[int(Element::Face)], false, false};
  enabled[int(Element::Edge)] = rule_inside(edge, edge_role_inside, faces);
  const bool faces_edges[4] = {true, enabled[int(Element::Face)], enabled[int(Element::Edge)], false};
  enabled[int(Element::Vertex)] = rule_inside(vertex, vertex_role_inside, faces_edges);
}

const RowPlan* RowPlanStore::find(const std::vector<std::int32_t>& key) const {
  std::lock_guard lock(mutex_);
  const auto it = plans_.find(key);
  return it == plans_.end() ? nullptr : it->second.get();
}

const RowPlan* RowPlanStore::add(const std::vector<std::int32_t>& key, RowPlan plan) {
  std::lock_guard lock(mutex_);
  auto& slot = plans_[key];
  if (!slot) slot = std::make_unique<RowPlan>(std::move(plan));  // else another thread learnt it first
  return slot.get();
}

// key_: the element kind and everything its row depends on (valences, face sizes in ring
// order, the point's index along an edge, and where each face starts when the faces'
// corners are listed, since a new face point lists its face from corner 0); around_: its
// neighbourhood, canonically.
bool RowPlanner::describe(Index child) {
  const Level& L = store_.parent;
  const FeatureContexts& F = store_.features;
  const OriginKind kind = store_.origins.kind[child];
  const Index p = store_.origins.parent[child];
  if (!store_.enabled[int(kind)]) return false;
  key_.clear(), around_.clear();
  key_.push_back(std::int32_t(kind));
  switch (kind) {
    case OriginKind::Vertex: {
      const VertexContext& vc = F.vertices[p];
      if (L.on_boundary(p) || vc.parent != Context::Smooth || vc.child != Context::Smooth) return false;
      for (Index e : L.ring_edges(p))
        if (F.edges[e].crease_weight != 0.f) return false;
      describe_vertex(p);
      break;
    }
    case OriginKind::Edge:
      if (L.edge_on_boundary(p) || F.edges[p].crease_weight != 0.f) return false;
      describe_edge(p, store_.origins.local[child]);
      break;
    case OriginKind::Face: {
      const auto face = L.face(p);
      key_.push_back(int(face.size()));
      around_.assign(face.begin(), face.end());
      break;
    }
    case OriginKind::Corner:
      return false;
  }
  if (store_.sources && std::find(around_.begin(), around_.end(), kNone) != around_.end())
    return false;  // a new point the element does not have
  return around_.size() <= kMaxAround;
}

// v; then its ring (light) or, in each ring face, the corners after v except the last (the
// next edge neighbour, listed by the face that has it right after v); then, as sources,
// the new points of the ring faces and edges.
void RowPlanner::describe_vertex(Index v) {
  const Level& L = store_.parent;
  const bool light = store_.sources && store_.light[int(Element::Vertex)];
  around_.push_back(v);
  key_.push_back(L.valence(v));
  const Index first = L.vertex_face_offsets[v];
  for (Index i = first; i < L.vertex_face_offsets[v + 1]; ++i) {
    const auto face = L.face(L.vertex_faces[i]);
    const int k = int(face.size()), c = L.vertex_face_corner[i];
    key_.push_back(k);
    if (light) continue;
    key_.push_back(c);
    for (int d = c + 1; d < c + k - 1; ++d) around_.push_back(face[d < k ? d : d - k]);
  }
  if (light)
    for (Index e : L.ring_edges(v)) around_.push_back(L.other_end(e, v));
  if (!store_.sources) return;
  if (store_.reads_face_points[int(Element::Vertex)])
    for (Index f : L.ring_faces(v)) around_.push_back(store_.new_point(Element::Face, f));
  if (store_.reads_edge_points[int(Element::Vertex)])
    for (Index e : L.ring_edges(v)) around_.push_back(store_.new_point(Element::Edge, e));
}

// Its ends; then (unless light) in each face the corners off the edge; then, as sources,
// the new points of its faces.
void RowPlanner::describe_edge(Index e, int local) {
  const Level& L = store_.parent;
  const bool light = store_.sources && store_.light[int(Element::Edge)];
  const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
  around_.push_back(a), around_.push_back(b);
  key_.push_back(local);
  key_.push_back(L.valence(a)), key_.push_back(L.valence(b));
  for (int side = 0; side < 2; ++side) {
    const Index f = L.edge_faces[2 * e + side];
    const auto face = L.face(f);
    const int k = int(face.size());
    key_.push_back(k);
    if (light) continue;
    const auto edges = L.face_edge_list(f);
    const int c = int(std::find(edges.begin(), edges.end(), e) - edges.begin());
    key_.push_back(c);
    for (int d = c + 2; d < c + k; ++d) around_.push_back(face[d < k ? d : d - k]);
  }
  if (!store_.sources || !store_.reads_face_points[int(Element::Edge)]) return;
  for (int side = 0; side < 2; ++side) around_.push_back(store_.new_point(Element::Face, L.edge_faces[2 * e + side]));
}

bool RowPlanner::distinct() const {
  for (size_t i = 1; i < around_.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (around_[i] == around_[j]) return false;
  return true;
}

const RowPlan* RowPlanner::find(Index child, Outcome& outcome) {
  outcome = Outcome::Generic;
  if (!describe(child)) return nullptr;
  const RowPlan* plan = nullptr;
  if (last_plan_ && key_ == last_key_) {
    plan = last_plan_;
  } else if (const auto known = local_.find(key_); known != local_.end()) {
    plan = known->second;
  } else {
    plan = store_.find(key_);
    if (plan) local_.emplace(key_, plan);
  }
  if (plan) last_key_ = key_, last_plan_ = plan;
  // Learning needs distinct points (positions are found by value). Replaying onto repeated
  // points is the same sum; only stored tables, which must equal the interpreter's merged
  // rows entry for entry, need them distinct too.
  if ((!plan || !store_.sources) && !distinct()) return nullptr;
  if (!plan) outcome = Outcome::Learn;
  if (!plan || !plan->usable) return nullptr;
  outcome = Outcome::Appended;
  return plan;
}

RowPlanner::Outcome RowPlanner::try_append(Index child, RowBlock& out) {
  Outcome outcome;
  const RowPlan* plan = find(child, outcome);
  if (!plan) return outcome;
  for (std::uint16_t position : plan->positions) out.indices.push_back(around_[position]);
  out.weights.insert(out.weights.end(), plan->weights.begin(), plan->weights.end());
  return Outcome::Appended;
}

void RowPlanner::learn(const RowBuilder& row, RowPlanStore& store) {
  RowPlan plan;
  plan.usable = true;
  for (Index source : row.indices()) {
    const auto at = std::find(around_.begin(), around_.end(), source);
    if (at == around_.end()) {
      plan.usable = false;
      break;
    }
    plan.positions.push_back(std::uint16_t(at - around_.begin()));
  }
  if (plan.usable) {
    plan.weights = row.weights();
    plan.sum_ok = row_sum_ok(weight_sum(plan.weights));
  }
  else plan.positions.clear();
  local_.emplace(key_, store.add(key_, std::move(plan)));
}

}  // namespace subdiv
