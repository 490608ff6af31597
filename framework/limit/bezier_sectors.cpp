#include "framework/limit/bezier_sectors.h"

#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <tuple>

#include "framework/features/sharpness.h"
#include "framework/util/error.h"

namespace subdiv::bezier {
namespace {

bool semi_sharp(float s) { return s > 0.f && s < kInfinitelySharp; }

// The valence the interior-point mask takes at a corner: the vertex's own inside the
// surface; twice the faces of its sector on a boundary or crease (the sector mirrored across
// its feature edges: 4 at a regular boundary); at a corner the faces a whole turn would hold
// at the sector's angle per face, 2 pi k / angle: 4 at a convex corner of one face (the
// B-spline patch with phantom points 2 v - w, whose interior point is
// (4 v + 2 e_a + 2 e_b + d) / 9), 4 at a concave corner of three.
double mask_valence(const Sector& s) {
  if (s.closed) return s.faces;
  return s.corner ? 2 * std::numbers::pi * s.faces / s.angle : 2 * s.faces;
}

// The angle at v between its edges to a and b, in the control mesh.
double angle_at(const Point3& v, const Point3& a, const Point3& b) {
  const Point3 x = a - v, y = b - v;
  const double dot = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
  const Point3 cross{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  return std::atan2(std::hypot(cross[0], cross[1], cross[2]), dot);
}

}  // namespace

double tangent_cosine(const Sector& s) {
  if (s.closed) return s.faces == 4 ? 0.0 : std::cos(2 * std::numbers::pi / s.faces);
  if (!s.corner) return s.faces == 2 ? 0.0 : std::cos(std::numbers::pi / s.faces);
  const double theta = s.angle / s.faces;  // pi / 2 (0 exactly) at the regular corners: 1 convex face, 3 concave
  return std::abs(theta - std::numbers::pi / 2) < 1e-12 ? 0.0 : std::cos(theta);
}

Point3 interior_point(const QuadMesh& m, Index f, int k) {
  const double n = mask_valence(m.sector(f, k));
  const Point3 s = n * m.point(m.vertex(f, k)) + 2.0 * m.point(m.vertex(f, k + 1)) +
                   2.0 * m.point(m.vertex(f, k + 3)) + m.point(m.vertex(f, k + 2));
  return (1.0 / (n + 5)) * s;
}

QuadMesh::QuadMesh(const Level& level, std::span<const double> positions, BoundaryInterpolation boundary,
                   std::span<const double> normals)
    : level_(level), positions_(positions), boundary_(boundary), normals_(normals) {
  for (Index f = 0; f < level.face_count(); ++f) {
    if (level.face_size(f) != 4)
      throw Error(fmt::format("face {} has {} sides: Loop & Schaefer's patches are one per quad; refine the mesh "
                              "once (subdiv refine -l 1 makes every face a quad) and approximate that",
                              f, level.face_size(f)));
    for (int k = 0; k < 4; ++k)
      if (!edge_.emplace(key(vertex(f, k), vertex(f, k + 1)), std::pair{f, k}).second)
        throw Error(fmt::format("face {}: its edge {}-{} is used twice in one direction (a non-manifold or "
                                "inconsistently oriented edge); the masks need a manifold quad mesh",
                                f, vertex(f, k), vertex(f, k + 1)));
  }
  find_sectors();
}

bool QuadMesh::feature(Index f, int k) const {
  const Index e = level_.face_edges[size_t(level_.face_offsets[size_t(f)]) + size_t(((k % 4) + 4) % 4)];
  return level_.edge_on_boundary(e) || level_.edge_sharp(e) >= kInfinitelySharp;
}

// Across edge k of f (to the next corner): the face running it the other way, and v's corner there.
std::pair<Index, int> QuadMesh::step_back(Index f, int k) const {
  const auto [g, l] = face_of(vertex(f, k + 1), vertex(f, k));
  return {g, (l + 1) % 4};
}

// The masks (bezier_approximation.cpp) cover: interior vertices without tags; vertices with
// exactly two feature edges and at least two faces between them on each side (a boundary,
// or a crease passing through); corners (a tagged corner, a boundary vertex of one face
// with corners kept, more than two feature edges) on a boundary or crease; darts. Each
// refusal names the first face where it happens.
void QuadMesh::find_sectors() {
  if (boundary_ == BoundaryInterpolation::None)
    for (Index e = 0; e < level_.edge_count(); ++e)
      if (level_.edge_on_boundary(e))
        throw Error(fmt::format("edge {}-{} is a boundary edge and the boundary interpolation is `none` (the limit "
                                "does not reach the boundary faces); use edges-and-corners",
                                level_.edge_vertices[2 * size_t(e)], level_.edge_vertices[2 * size_t(e) + 1]));
  for (Index e = 0; e < level_.edge_count(); ++e)
    if (semi_sharp(level_.edge_sharp(e)))
      throw Error(fmt::format("edge {}-{} is semi-sharp ({}): the masks are those of smooth vertices and of "
                              "infinitely sharp creases; refine until it has decayed (subdiv refine -l {}) and "
                              "approximate that mesh",
                              level_.edge_vertices[2 * size_t(e)], level_.edge_vertices[2 * size_t(e) + 1],
                              level_.edge_sharp(e), int(std::ceil(level_.edge_sharp(e)))));
  for (Index f = 0; f < level_.face_count(); ++f)
    for (int k = 0; k < 4; ++k) {
      const Index v = vertex(f, k);
      if (semi_sharp(level_.vertex_sharp(v)))
        throw Error(fmt::format("face {}: vertex {} is a semi-sharp corner ({}); refine until it has decayed and "
                                "approximate that mesh",
                                f, v, level_.vertex_sharp(v)));
      const Sector s = find_sector(f, k);
      const char* why = nullptr;
      if (s.closed && s.corner) why = "is a corner inside the surface (a cone point)";
      else if (!s.closed && !s.corner && s.faces < 2) why = "is on a boundary or crease with only one face on a side";
      if (why)
        throw Error(fmt::format("face {}: vertex {} {}: Loop & Schaefer's masks are built here for smooth vertices, "
                                "boundaries and creases with two or more faces on each side, and corners, and "
                                "refining keeps a vertex's faces; evaluate the exact limit instead",
                                f, v, why));
      sectors_.push_back(s);
    }
}

Sector QuadMesh::find_sector(Index f, int k) const {
  Sector s;
  const Index v = vertex(f, k);
  int features = 0;
  for (Index e : level_.ring_edges(v))
    features += level_.edge_on_boundary(e) || level_.edge_sharp(e) >= kInfinitelySharp;
  const bool boundary_corner = boundary_ == BoundaryInterpolation::EdgesAndCorners && level_.on_boundary(v) &&
                               level_.incident_face_count(v) == 1;
  s.corner = level_.vertex_sharp(v) >= kInfinitelySharp || features > 2 || boundary_corner;
  // A dart (one feature edge: a crease ending inside) takes the smooth vertex rule (Hoppe et
  // al. 1994, DeRose, Kass & Truong 1998): its sector is closed, its tangent plane the limit's.
  if (features <= 1) {
    s.closed = true;
    s.faces = level_.incident_face_count(v);
    return s;
  }
  Index g = f;
  int c = k;
  while (!feature(g, c)) {  // back to E_0
    std::tie(g, c) = step_back(g, c);
    ++s.index;
  }
  s.faces = 1;
  double mesh_angle = angle_at(point(v), point(vertex(g, c + 1)), point(vertex(g, c + 3)));
  while (!feature(g, c + 3)) {  // on to E_faces
    std::tie(g, c) = step_forward(g, c);
    mesh_angle += angle_at(point(v), point(vertex(g, c + 1)), point(vertex(g, c + 3)));
    ++s.faces;
  }
  const double pi = std::numbers::pi;
  s.angle = !s.corner ? pi : mesh_angle <= pi ? pi / 2 : 3 * pi / 2;
  return s;
}

// Closed sectors (n faces): Catmull-Clark's tangent mask (the subdominant left
// eigenvectors; Halstead, Kass & DeRose 1993, used by Loop & Schaefer 2008 section 4): over
// v's ring, edge neighbours e_i (e_0 the edge's end) weighted A cos(2 pi i / n), face
// neighbours d_i (between e_i and e_(i+1)) weighted B cos((2i + 1) pi / n),
// B = 1 / (n sqrt(4 + cos^2(pi / n))), A = 1/n + cos(pi / n) B. Tangents along consecutive
// edges then satisfy t_(i-1) + t_(i+1) = 2 cos(2 pi / n) t_i, which the tangent patches
// rely on.
//
// Open sectors (k faces between feature edges E_0 and E_k): t_j = cos(j pi / k) T1 +
// sin(j pi / k) T2 along E_j, with T1 = (E_0 - E_k) / 2 the feature curve's own (cubic
// B-spline) tangent and T2 the cross tangent of Biermann, Levin & Zorin (2000), "Piecewise
// smooth subdivision surfaces with normal control" (the mask OpenSubdiv's Sdc gives for
// Catmull-Clark's boundary and crease vertices): with theta = pi / k, over the sector's
// vertex v, edge neighbours E_j and opposite corners d_j of its faces,
// (4 R (cos theta - 1) v - R (1 + 2 cos theta) (E_0 + E_k) + sum_(0<j<k) 4 sin(j theta) E_j
//  + sum_j (sin(j theta) + sin((j+1) theta)) d_j) / (k (3 + cos theta)), R = (1 + cos theta) / sin theta.
// At k = 2 these are the B-spline patch's derivatives with phantom points across the feature
// edges, and t_(j-1) + t_(j+1) = 2 cos(pi / k) t_j along the interior edges.
//
// Corners (the vertex kept, k faces between two feature edges): along the feature edges
// E_0 - v and E_k - v, the B-spline curves' tangents with their ends interpolated (phantom
// points 2 v - E); between them t_j = (sin((k - j) theta) t_0 + sin(j theta) t_k) / sin(k theta),
// theta = angle / k: the tangents of a corner of that angle in the parameter plane (Biermann,
// Levin & Zorin 2000), which satisfy t_(j-1) + t_(j+1) = 2 cos(theta) t_j.
//
// A boundary vertex's sides: t_j is linear in T1 and T2, so the projection onto the limit's
// tangent plane (corner_tangent) keeps t_(j-1) + t_(j+1) = 2 c t_j, and with it the normal
// field's continuity across the sector's edges.
Point3 QuadMesh::corner_tangent(Index f, int k, bool towards_next) const {
  const Sector& s = sector(f, k);
  const Point3 t = mask_tangent(f, k, towards_next, s);
  // One tangent plane at the vertex: inside the surface, or on a boundary (not a crease,
  // whose sides have planes of their own, nor a corner, whose tangents are exact).
  const Index v = vertex(f, k);
  const bool one_plane = s.closed || (!s.corner && level_.on_boundary(v));
  return one_plane ? projected(v, t) : t;
}

// t minus its component along v's limit normal (t unchanged where there is none).
Point3 QuadMesh::projected(Index v, const Point3& t) const {
  if (normals_.empty()) return t;
  const Point3 n{normals_[3 * size_t(v)], normals_[3 * size_t(v) + 1], normals_[3 * size_t(v) + 2]};
  const double length2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (!(length2 > 0.5)) return t;  // no normal (zero), or not a unit vector
  const double along = (t[0] * n[0] + t[1] * n[1] + t[2] * n[2]) / length2;
  return t - along * n;
}

Point3 QuadMesh::corner_sector_tangent(Index first_face, int first_corner, const Sector& s, int j) const {
  const Index v = vertex(first_face, first_corner);
  const Point3 first = point(vertex(first_face, first_corner + 1)) - point(v);
  if (j == 0) return first;
  Index g = first_face;
  int c = first_corner;
  for (int i = 1; i < s.faces; ++i) std::tie(g, c) = step_forward(g, c);
  const Point3 last = point(vertex(g, c + 3)) - point(v);
  if (j == s.faces) return last;
  const double theta = s.angle / s.faces;
  return (1.0 / std::sin(s.angle)) * (std::sin((s.faces - j) * theta) * first + std::sin(j * theta) * last);
}

Point3 QuadMesh::mask_tangent(Index f, int k, bool towards_next, const Sector& s) const {
  const double pi = std::numbers::pi;
  const Index v = vertex(f, k);
  if (s.closed) {
    const int n = s.faces;
    const double c = std::cos(pi / n);
    const double b = 1.0 / (n * std::sqrt(4 + c * c)), a = 1.0 / n + c * b;
    Point3 t{0, 0, 0};
    Index g = f;
    int corner = k;
    if (!towards_next) std::tie(g, corner) = step_forward(g, corner);  // the edge to k - 1 is g's edge to next
    for (int i = 0; i < n; ++i) {
      t = t + (a * std::cos(2 * pi * i / n)) * point(vertex(g, corner + 1));
      t = t + (b * std::cos((2 * i + 1) * pi / n)) * point(vertex(g, corner + 2));
      std::tie(g, corner) = step_forward(g, corner);
    }
    return t;
  }
  const int j = s.index + (towards_next ? 0 : 1);
  // The sector's faces f_0 .. f_(k-1) from E_0 on.
  Index g = f;
  int corner = k;
  for (int i = 0; i < s.index; ++i) std::tie(g, corner) = step_back(g, corner);
  const int faces = s.faces;
  if (s.corner) return corner_sector_tangent(g, corner, s, j);
  const double theta = pi / faces, ct = std::cos(theta), st = std::sin(theta);
  const double denominator = faces * (3 + ct), r = (1 + ct) / st;
  Point3 first{}, last{}, cross = (4 * r * (ct - 1) / denominator) * point(v);
  for (int i = 0; i < faces; ++i) {
    const Point3 e = point(vertex(g, corner + 1));
    if (i == 0) first = e;
    else cross = cross + (4 * std::sin(i * theta) / denominator) * e;
    cross = cross + ((std::sin(i * theta) + std::sin((i + 1) * theta)) / denominator) * point(vertex(g, corner + 2));
    if (i + 1 == faces) last = point(vertex(g, corner + 3));
    else std::tie(g, corner) = step_forward(g, corner);
  }
  cross = cross + (-r * (1 + 2 * ct) / denominator) * (first + last);
  const Point3 along = 0.5 * (first - last);
  return std::cos(j * theta) * along + std::sin(j * theta) * cross;
}

}  // namespace subdiv::bezier
