#include "framework/limit/dual_crease_strip.h"

#include "framework/features/dual_features.h"
#include "framework/limit/dual_crease_chart.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

Index corner_edge(const Level& L, Index f, int corner) { return L.face_edges[size_t(L.face_offsets[f] + corner)]; }

// An edge across the strip: smooth (its E-face joins the two creases), or a sharp edge
// between two corners of the mesh (the end of the strip; it stays a straight segment).
bool strip_rung(const Level& L, Index e) {
  if (!dual_sharp_edge(L, e)) return L.edge_sharp(e) == 0;
  const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
  return edge_infinitely_sharp(L, e) && dual_collapses(L, a) && dual_collapses(L, b);
}

// Three basis functions of a quadratic piece in its parameter x, with their first and second
// derivatives, on three vertices.
struct Piece {
  std::array<Index, 3> vertex;
  std::array<double, 3> w, dw, ddw;
};

// Chaikin's curve (Chaikin 1974: the uniform quadratic B-spline, control points at integer
// Greville abscissae; Lane & Riesenfeld 1980), clamped at a corner of the mesh (knots
// 0, 0, 0, 1, 2, ...: the corner at 0, its neighbour at 1/2; de Boor 1972), or between two
// corners with one vertex between them the quadratic Bezier curve (knots 0, 0, 0, 1, 1, 1).
Piece uniform(Index prev, Index x, Index y, double t) {  // t in [0, 1/2] from x towards y
  return {{prev, x, y},
          {0.5 * (0.5 - t) * (0.5 - t), 0.75 - t * t, 0.5 * (0.5 + t) * (0.5 + t)},
          {-(0.5 - t), -2 * t, 0.5 + t},
          {1, -2, 1}};
}
Piece clamped(Index corner, Index next, Index after, double t) {  // t in [0, 1] from the corner
  return {{corner, next, after},
          {(1 - t) * (1 - t), 2 * t - 1.5 * t * t, 0.5 * t * t},
          {-2 * (1 - t), 2 - 3 * t, t},
          {2, -3, 1}};
}
Piece bezier(Index corner, Index middle, Index other, double t) {  // t in [0, 1] from `corner`
  return {{corner, middle, other}, {(1 - t) * (1 - t), 2 * t * (1 - t), t * t}, {-2 * (1 - t), 2 - 4 * t, 2 * t},
          {2, -4, 2}};
}

// The piece at u along (p, q), and dt/du.
std::optional<std::pair<Piece, double>> piece_at(const Level& L, Index p, Index q, double u) {
  const bool cp = dual_collapses(L, p), cq = dual_collapses(L, q);
  if (cp && cq) {  // a crease polygon of one edge between two corners: the segment
    Piece s{{p, q, q}, {1 - u, u, 0}, {-1, 1, 0}, {0, 0, 0}};
    return std::pair{s, 1.0};
  }
  if (cp || cq) {  // the edge is half a knot interval, [0, 1/2] from the corner
    const Index k = cp ? p : q, x = cp ? q : p;
    const double t = cp ? u / 2 : (1 - u) / 2, dt = cp ? 0.5 : -0.5;
    const Index next = other_crease_neighbour(L, x, k);
    if (next == kNone) return std::nullopt;
    return std::pair{dual_collapses(L, next) ? bezier(k, x, next, t) : clamped(k, x, next, t), dt};
  }
  // The half of the edge at x = p (u <= 1/2) or x = q: a uniform piece unless x's other
  // neighbour is a corner, where the clamped spline's first interval reaches to the middle.
  const bool near_p = u <= 0.5;
  const Index x = near_p ? p : q, y = near_p ? q : p;
  const double t = near_p ? u : 1 - u, dt = near_p ? 1.0 : -1.0;
  const Index prev = other_crease_neighbour(L, x, y);
  if (prev == kNone) return std::nullopt;
  return std::pair{dual_collapses(L, prev) ? clamped(prev, x, y, 0.5 + t) : uniform(prev, x, y, t), dt};
}

}  // namespace

std::optional<CreaseStrip> crease_strip(const Level& L, Index f) {
  if (L.face_size(f) != 4) return std::nullopt;
  for (int k = 0; k < 2; ++k) {
    const Index low = corner_edge(L, f, k), high = corner_edge(L, f, k + 2);
    const Index r0 = corner_edge(L, f, k + 1), r1 = corner_edge(L, f, (k + 3) % 4);
    if (!dual_sharp_edge(L, low) || !dual_sharp_edge(L, high)) continue;
    if (edge_infinitely_sharp(L, low) && edge_infinitely_sharp(L, high)) {
      if (strip_rung(L, r0) && strip_rung(L, r1)) return CreaseStrip{k, true};
      continue;
    }
    bool corner = false;
    for (Index x : L.face(f)) corner = corner || dual_collapses(L, x);
    if (!corner && !dual_sharp_edge(L, r0) && L.edge_sharp(r0) == 0 && !dual_sharp_edge(L, r1) && L.edge_sharp(r1) == 0)
      return CreaseStrip{k, false};
  }
  return std::nullopt;
}

StripStep strip_child(const Level& child, const ChildOrigins& o, Index f, CreaseStrip strip, double u, double v) {
  Index F = kNone;
  for (Index g = 0; g < child.face_count() && F == kNone; ++g)
    if (o.parent_face[size_t(g)] == f) F = g;
  if (F == kNone || child.face_size(F) != 4) throw Error("internal: a face between two creases has no quad F-face");
  // The F-face keeps f's corner order. Its corners 0 and 3 (k = 0) or 0 and 1 (k = 1) start
  // the two creases' edges; the point's child is the F-face, or the E-face across the F-face's
  // edge at along = 0 or 1, with along' measured from that edge's end on the crease at across 0.
  const bool along_u = strip.k == 0;
  const double along = along_u ? u : v, across = along_u ? v : u;
  const auto Fc = child.face(F);
  Index a = Fc[0], b = Fc[along_u ? 3 : 1];
  double scale = 2, offset = -0.5;
  if (along > 0.75) a = Fc[along_u ? 1 : 3], b = Fc[2], offset = -1.5;
  if (along < 0.25) scale = -2, offset = 0.5;
  StripStep s;
  s.face = F;
  if (along < 0.25 || along > 0.75) {
    const Index e = find_edge(child, a, b);
    if (e == kNone || child.edge_faces[size_t(2 * e + 1)] == kNone)
      throw Error("internal: a face between two creases has no E-face across its smooth edge");
    s.face = child.edge_faces[size_t(2 * e)] == F ? child.edge_faces[size_t(2 * e + 1)] : child.edge_faces[size_t(2 * e)];
    if (child.face_size(s.face) != 4) throw Error("internal: the E-face between two creases is not a quad");
  }
  const auto g = child.face(s.face);
  int ia = 0, ib = 0;
  for (int k = 0; k < 4; ++k) {
    if (g[size_t(k)] == a) ia = k;
    if (g[size_t(k)] == b) ib = k;
  }
  const int id = (ia + 1) % 4 == ib ? (ia + 3) % 4 : (ia + 1) % 4;
  constexpr double kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const double ed[2] = {kCorner[id][0] - kCorner[ia][0], kCorner[id][1] - kCorner[ia][1]};
  const double eb[2] = {kCorner[ib][0] - kCorner[ia][0], kCorner[ib][1] - kCorner[ia][1]};
  const double a2 = scale * along + offset;
  const double dA[2] = {along_u ? 1.0 : 0.0, along_u ? 0.0 : 1.0}, dX[2] = {dA[1], dA[0]};
  for (size_t r = 0; r < 2; ++r) {
    s.uv[r] = kCorner[ia][r] + a2 * ed[r] + across * eb[r];
    for (size_t c = 0; c < 2; ++c) s.jacobian[r][c] = scale * ed[r] * dA[c] + eb[r] * dX[c];
  }
  return s;
}

std::optional<std::vector<CurveWeight>> crease_edge_limit(const Level& L, Index p, Index q, double u) {
  const auto piece = piece_at(L, p, q, u);
  if (!piece) return std::nullopt;
  const auto& [s, dt] = *piece;
  std::vector<CurveWeight> out;
  for (size_t i = 0; i < 3; ++i) out.push_back({s.vertex[i], s.w[i], s.dw[i] * dt, s.ddw[i] * dt * dt});
  return out;
}

std::optional<StripRows> crease_strip_limit(const Level& L, Index f, CreaseStrip strip, double u, double v) {
  // k = 0: edge 0 (corner 0 to 1) at v = 0 and edge 2 (corner 3 to 2) at v = 1, along u;
  // k = 1: edge 3 (corner 0 to 3) at u = 0 and edge 1 (corner 1 to 2) at u = 1, along v.
  const auto g = L.face(f);
  const bool along_u = strip.k == 0;
  const double along = along_u ? u : v, across = along_u ? v : u;
  const auto low = crease_edge_limit(L, g[0], g[along_u ? 1 : 3], along);
  const auto high = crease_edge_limit(L, g[along_u ? 3 : 1], g[2], along);
  if (!low || !high) return std::nullopt;
  StripRows rows;
  for (auto& r : rows) r.assign(size_t(L.vertex_count), 0.0);
  // Rows: 0 position, 1 d/du, 2 d/dv, 3 d2/du2, 4 d2/dudv, 5 d2/dv2 (zero: linear across).
  const size_t d_along = along_u ? 1 : 2, d_across = along_u ? 2 : 1;
  const size_t dd_along = along_u ? 3 : 5;
  for (const auto& [curve, side] : {std::pair{&*low, 1 - across}, std::pair{&*high, across}}) {
    const double sign = curve == &*low ? -1.0 : 1.0;  // d(side)/d(across)
    for (const CurveWeight& c : *curve) {
      const size_t x = size_t(c.vertex);
      rows[0][x] += side * c.w;
      rows[d_along][x] += side * c.dw;
      rows[d_across][x] += sign * c.w;
      rows[dd_along][x] += side * c.ddw;
      rows[4][x] += sign * c.dw;
    }
  }
  return rows;
}

}  // namespace subdiv
