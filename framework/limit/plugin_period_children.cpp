#include "framework/limit/plugin_period_children.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <fmt/format.h>

#include "framework/util/error.h"

namespace subdiv {
namespace {

constexpr Uv kQuad[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
constexpr Uv kTriangle[3] = {{0, 0}, {1, 0}, {0, 1}};

using Placed = std::unordered_map<Index, Uv>;  // vertex -> its place in the face's frame

const Uv* placed_at(const Placed& at, Index v) {
  const auto found = at.find(v);
  return found == at.end() ? nullptr : &found->second;
}

// The children of edge e at (i + 1)/(c + 1) from its first vertex, when both ends are placed.
void place_edge_children(const Level& parent, const ChildrenOf& children, Index e, const Placed& at, Placed& out) {
  const Uv* a = placed_at(at, parent.edge_vertices[size_t(2 * e)]);
  const Uv* b = placed_at(at, parent.edge_vertices[size_t(2 * e + 1)]);
  if (!a || !b) return;
  const auto on_edge = children.edge(e);
  for (size_t i = 0; i < on_edge.size(); ++i) {
    if (on_edge[i] == kNone) continue;
    const double t = double(i + 1) / double(on_edge.size() + 1);
    out[on_edge[i]] = {(*a)[0] + t * ((*b)[0] - (*a)[0]), (*a)[1] + t * ((*b)[1] - (*a)[1])};
  }
}

// The first step's children around face f: its corners' vertex children, its own face point
// at its centroid, the face points of its neighbours across its edges unfolded, its edges'
// points.
Placed first_step(const Level& L, const ChildrenOf& children, Index f, bool triangles) {
  const auto fv = L.face(f);
  const auto fe = L.face_edge_list(f);
  const int n = int(fv.size());
  const Uv* frame = triangles ? kTriangle : kQuad;
  Placed corners, out;
  Uv centre{0, 0};
  for (int k = 0; k < n; ++k) {
    corners[fv[size_t(k)]] = frame[k];
    centre[0] += frame[k][0] / n, centre[1] += frame[k][1] / n;
    if (const Index c = children.vertex(fv[size_t(k)]); c != kNone) out[c] = frame[k];
  }
  if (const Index c = children.face(f); c != kNone) out[c] = centre;
  for (int k = 0; k < n; ++k) {
    const Index e = fe[size_t(k)];
    const Index g = L.edge_faces[size_t(2 * e)] == f ? L.edge_faces[size_t(2 * e + 1)] : L.edge_faces[size_t(2 * e)];
    const Uv A = frame[k], B = frame[(k + 1) % n];
    if (g != kNone && g != f && children.face(g) != kNone) {
      if (triangles) {  // the neighbour's far corner A + B - C
        const Uv C = frame[(k + 2) % 3];
        out[children.face(g)] = {(2 * A[0] + 2 * B[0] - C[0]) / 3, (2 * A[1] + 2 * B[1] - C[1]) / 3};
      } else {  // the neighbour reflected: far corners 2A - D and 2B - C
        const Uv C = frame[(k + 2) % 4], D = frame[(k + 3) % 4];
        out[children.face(g)] = {(3 * A[0] + 3 * B[0] - C[0] - D[0]) / 4, (3 * A[1] + 3 * B[1] - C[1] - D[1]) / 4};
      }
    }
    place_edge_children(L, children, e, corners, out);
  }
  return out;
}

// A later step's children, from where their parents are: vertex children at their parent,
// face points at the centroid of faces whose corners are all placed, edges' points along
// edges whose ends are.
Placed next_step(const Level& parent, const ChildrenOf& children, const Placed& at) {
  Placed out;
  std::vector<Index> faces, edges;
  for (const auto& [v, uv] : at) {
    if (const Index c = children.vertex(v); c != kNone) out[c] = uv;
    for (Index g : parent.ring_faces(v)) faces.push_back(g);
    for (Index e : parent.ring_edges(v)) edges.push_back(e);
  }
  for (auto* list : {&faces, &edges}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  for (Index g : faces) {
    const auto gv = parent.face(g);
    Uv centre{0, 0};
    bool all = children.face(g) != kNone;
    for (Index w : gv) {
      const Uv* x = placed_at(at, w);
      if (!x) all = false;
      else centre[0] += (*x)[0] / double(gv.size()), centre[1] += (*x)[1] / double(gv.size());
    }
    if (all) out[children.face(g)] = centre;
  }
  for (Index e : edges) place_edge_children(parent, children, e, at, out);
  return out;
}

bool inside_face(const Uv& x, bool triangles) {
  constexpr double eps = 1e-9;
  if (x[0] < -eps || x[1] < -eps) return false;
  return triangles ? x[0] + x[1] <= 1 + eps : x[0] <= 1 + eps && x[1] <= 1 + eps;
}

// The faces of `last` whose corners are all placed inside the frame, in the order of their
// numbers: m^2 affine copies of the face, or an error saying why not.
std::vector<ChildFace> nested_children(const Level& last, const Placed& at, bool triangles, int m) {
  std::vector<Index> faces;
  for (const auto& [v, uv] : at)
    for (Index g : last.ring_faces(v)) faces.push_back(g);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  std::vector<ChildFace> out;
  for (Index g : faces) {
    ChildFace c;
    c.face = g;
    bool in = true;
    for (Index v : last.face(g)) {
      const Uv* x = placed_at(at, v);
      in = in && x && inside_face(*x, triangles);
      if (in) c.corners.push_back(*x);
    }
    if (!in) continue;
    if (int(c.corners.size()) != (triangles ? 3 : 4)) throw Error("the split's faces inside a face are not of its shape");
    if (!triangles) {  // a parallelogram: corner 2 = corner 1 + corner 3 - corner 0
      const Uv &a = c.corners[0], &b = c.corners[1], &d = c.corners[2], &e = c.corners[3];
      if (std::fabs(b[0] + e[0] - a[0] - d[0]) + std::fabs(b[1] + e[1] - a[1] - d[1]) > 1e-9)
        throw Error("the split's faces inside a face are not parallelograms of its frame");
    }
    out.push_back(std::move(c));
  }
  if (int(out.size()) != m * m)
    throw Error(fmt::format("the split makes {} faces inside a face after its period, not the {} of a {}-adic split",
                            out.size(), m * m, m));
  return out;
}

}  // namespace

ChildrenOf::ChildrenOf(const Level& parent, const ChildOrigins& origins)
    : vertex_child_(size_t(parent.vertex_count), kNone),
      face_child_(size_t(parent.face_count()), kNone),
      edge_offset_(size_t(parent.edge_count()) + 1, 0) {
  const size_t n = origins.kind.size();
  for (size_t c = 0; c < n; ++c) {
    const Index p = origins.parent[c];
    switch (origins.kind[c]) {
      case OriginKind::Vertex: vertex_child_[size_t(p)] = Index(c); break;
      case OriginKind::Face: face_child_[size_t(p)] = Index(c); break;
      case OriginKind::Edge: ++edge_offset_[size_t(p) + 1]; break;
      default: break;
    }
  }
  for (size_t e = 1; e < edge_offset_.size(); ++e) edge_offset_[e] += edge_offset_[e - 1];
  edge_children_.assign(size_t(edge_offset_.back()), kNone);
  for (size_t c = 0; c < n; ++c)
    if (origins.kind[c] == OriginKind::Edge) {
      const Index e = origins.parent[c];
      const Index slot = edge_offset_[size_t(e)] + Index(origins.local[c]);
      if (slot >= edge_offset_[size_t(e) + 1]) throw Error("the split numbers an edge's points beyond their count");
      edge_children_[size_t(slot)] = Index(c);
    }
}

std::vector<ChildFace> period_children(const Hierarchy& h, size_t first, int period, Index f, bool triangles,
                                       int factor, std::span<const ChildrenOf> children_of) {
  Placed at = first_step(h.levels[first], children_of[0], f, triangles);
  for (int s = 1; s < period; ++s) at = next_step(h.levels[first + size_t(s)], children_of[size_t(s)], at);
  return nested_children(h.levels[first + size_t(period)], at, triangles, factor);
}

}  // namespace subdiv
