#include "framework/limit/face_domain.h"

#include <cmath>
#include <vector>

namespace subdiv {
namespace {

constexpr Uv kQuadCorners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
constexpr Uv kTriangleCorners[3] = {{0, 0}, {1, 0}, {0, 1}};
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

Uv mid(const Uv& a, const Uv& b) { return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])}; }

// Coordinates, in the parent point's frame, of the parent face's corners, edge middles and
// centre (NaN where an element is outside the frame: the other sub-faces of an n-gon).
struct ParentFrame {
  std::vector<Uv> corner, edge;
  Uv centre{kNan, kNan};
};

ParentFrame parent_frame(const Level& parent, const FacePoint& p, bool triangles) {
  const int n = parent.face_size(p.face);
  ParentFrame f;
  f.corner.assign(size_t(n), Uv{kNan, kNan});
  f.edge.assign(size_t(n), Uv{kNan, kNan});
  if (p.sub_face >= 0) {
    const size_t i = size_t(p.sub_face);
    f.corner[i] = {0, 0};
    f.edge[i] = {1, 0};
    f.edge[(i + size_t(n) - 1) % size_t(n)] = {0, 1};
    f.centre = {1, 1};
    return f;
  }
  const Uv* c = triangles ? kTriangleCorners : kQuadCorners;
  for (int k = 0; k < n; ++k) f.corner[size_t(k)] = c[k];
  for (int k = 0; k < n; ++k) f.edge[size_t(k)] = mid(c[k], c[(k + 1) % n]);
  f.centre = triangles ? Uv{1.0 / 3, 1.0 / 3} : Uv{0.5, 0.5};
  return f;
}

int position_in(std::span<const Index> list, Index x) {
  for (size_t k = 0; k < list.size(); ++k)
    if (list[k] == x) return int(k);
  return -1;
}

// Where child vertex c lies in the frame, or NaN.
Uv child_coordinates(const Level& parent, const ChildOrigins& o, const ParentFrame& frame, Index face, Index c) {
  const Index from = o.parent[size_t(c)];
  switch (o.kind[size_t(c)]) {
    case OriginKind::Vertex: {
      const int k = position_in(parent.face(face), from);
      return k < 0 ? Uv{kNan, kNan} : frame.corner[size_t(k)];
    }
    case OriginKind::Edge: {
      const int k = position_in(parent.face_edge_list(face), from);
      return k < 0 ? Uv{kNan, kNan} : frame.edge[size_t(k)];
    }
    case OriginKind::Face: return from == face ? frame.centre : Uv{kNan, kNan};
    case OriginKind::Corner: break;
  }
  return {kNan, kNan};
}

bool inside(const Uv& st, bool triangles, double eps) {
  if (triangles) return st[0] >= -eps && st[1] >= -eps && st[0] + st[1] <= 1 + eps;
  return st[0] >= -eps && st[1] >= -eps && st[0] <= 1 + eps && st[1] <= 1 + eps;
}

// The point in child g's coordinates: the affine frame of its corners 0, 1 and last.
std::optional<FacePoint> in_child(const std::vector<Uv>& corners, const FacePoint& p, Index g, double eps,
                                  bool triangles) {
  const Uv& c0 = corners.front();
  const double a = corners[1][0] - c0[0], c = corners[1][1] - c0[1];
  const double b = corners.back()[0] - c0[0], d = corners.back()[1] - c0[1];
  const double det = a * d - b * c;
  if (!(std::fabs(det) > 0)) return std::nullopt;
  const double x = p.st[0] - c0[0], y = p.st[1] - c0[1];
  const Jacobian inv{{{d / det, -b / det}, {-c / det, a / det}}};
  FacePoint q;
  q.face = g;
  q.st = {inv[0][0] * x + inv[0][1] * y, inv[1][0] * x + inv[1][1] * y};
  if (!inside(q.st, triangles, eps)) return std::nullopt;
  for (int r = 0; r < 2; ++r) {
    q.st[size_t(r)] = std::fmin(std::fmax(q.st[size_t(r)], 0.0), 1.0);
    for (int k = 0; k < 2; ++k)
      q.jacobian[size_t(r)][size_t(k)] = inv[size_t(r)][0] * p.jacobian[0][size_t(k)] + inv[size_t(r)][1] * p.jacobian[1][size_t(k)];
  }
  // On a triangle's long edge the rounding of the frame can leave u + v a few ulps above 1,
  // outside the domain the child's evaluator accepts: back onto the edge.
  if (const double sum = q.st[0] + q.st[1]; triangles && sum > 1) q.st = {q.st[0] / sum, q.st[1] / sum};
  return q;
}

}  // namespace

int sub_face_columns(int n) {
  int c = 1;
  while (c * c < n) ++c;
  return c;
}

std::optional<FacePoint> base_face_point(const Level& level, Index face, double u, double v, bool triangles,
                                         const char** why) {
  if (!std::isfinite(u) || !std::isfinite(v)) return *why = "u or v is not a finite number", std::nullopt;
  const int n = level.face_size(face);
  FacePoint p;
  p.face = face;
  if (triangles || n == 4) {
    if (triangles && n != 3) return *why = "the scheme refines triangles and the face is not one", std::nullopt;
    p.st = {u, v};
    if (!inside(p.st, n == 3, 0.0))
      return *why = n == 3 ? "(u, v) is outside the triangle u >= 0, v >= 0, u + v <= 1"
                           : "(u, v) is outside the unit square",
             std::nullopt;
    return p;
  }
  // Bfr::Parameterization::ConvertCoordToNormalizedSubFace: a tile's quarter beyond 3/4
  // belongs to the next tile.
  const int columns = sub_face_columns(n);
  if (u < 0 || v < 0 || u > columns || v > columns)  // before the casts: u = 1e10 does not fit an int
    return *why = "(u, v) is outside the face's sub-face tiles (Bfr's QUAD_SUBFACES layout)", std::nullopt;
  int col = int(std::floor(u)), row = int(std::floor(v));
  double fu = u - col, fv = v - row;
  if (fu > 0.75) ++col, fu -= 1;
  if (fv > 0.75) ++row, fv -= 1;
  const int sub = row * columns + col;
  if (u < 0 || v < 0 || col >= columns || sub >= n || fu > 0.5 || fv > 0.5 || fu < 0 || fv < 0)
    return *why = "(u, v) is outside the face's sub-face tiles (Bfr's QUAD_SUBFACES layout)", std::nullopt;
  p.sub_face = sub;
  p.st = {2 * fu, 2 * fv};
  p.jacobian = {{{2, 0}, {0, 2}}};
  return p;
}

int corner_at(const FacePoint& p, int face_size, bool triangles) {
  if (p.sub_face >= 0) return p.st[0] == 0 && p.st[1] == 0 ? p.sub_face : -1;
  const Uv* c = triangles ? kTriangleCorners : kQuadCorners;
  for (int k = 0; k < face_size && k < (triangles ? 3 : 4); ++k)
    if (p.st[0] == c[k][0] && p.st[1] == c[k][1]) return k;
  return -1;
}

std::vector<ChildFace> child_faces(const Level& parent, const Level& child, const ChildOrigins& origins,
                                   const FacePoint& p, bool triangles) {
  std::vector<Index> candidates;
  for (Index g = 0; g < child.face_count(); ++g)
    if (origins.parent_face[size_t(g)] == p.face) candidates.push_back(g);
  return child_faces(parent, child, origins, p, triangles, candidates);
}

std::vector<ChildFace> child_faces(const Level& parent, const Level& child, const ChildOrigins& origins,
                                   const FacePoint& p, bool triangles, std::span<const Index> candidates) {
  const ParentFrame frame = parent_frame(parent, p, triangles);
  std::vector<ChildFace> out;
  for (Index g : candidates) {
    ChildFace c;
    c.face = g;
    bool mapped = true;
    for (Index v : child.face(g)) {
      c.corners.push_back(child_coordinates(parent, origins, frame, p.face, v));
      mapped &= std::isfinite(c.corners.back()[0]);
    }
    if (mapped && c.corners.size() >= 3) out.push_back(std::move(c));
  }
  return out;
}

std::optional<FacePoint> point_in_child(const ChildFace& child, const FacePoint& p, bool triangles, double eps) {
  return in_child(child.corners, p, child.face, eps, triangles);
}

std::optional<FacePoint> locate(std::span<const ChildFace> children, const FacePoint& p, bool triangles, int* which) {
  for (double eps : {0.0, 1e-12})
    for (size_t i = 0; i < children.size(); ++i)
      if (auto q = in_child(children[i].corners, p, children[i].face, eps, triangles)) {
        if (which) *which = int(i);
        return q;
      }
  return std::nullopt;
}

std::optional<FacePoint> child_face_point(const Level& parent, const Level& child, const ChildOrigins& origins,
                                          const FacePoint& p, bool triangles) {
  const std::vector<ChildFace> children = child_faces(parent, child, origins, p, triangles);
  return locate(children, p, triangles, nullptr);
}

}  // namespace subdiv
