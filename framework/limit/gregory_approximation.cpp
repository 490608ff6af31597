#include "framework/limit/gregory_approximation.h"

#include <cmath>
#include <numbers>
#include <tuple>

#include "framework/limit/bezier_sectors.h"

namespace subdiv {
namespace {

using bezier::QuadMesh;
using bezier::interior_point;
using bezier::tangent_cosine;
using bezier::operator+;
using bezier::operator-;
using bezier::operator*;

// The index j * 4 + i of control point (a, c) in corner k's frame: a steps along the edge
// k -> k + 1, c along k -> k - 1.
size_t local(int k, int a, int c) {
  const auto at = [](int i, int j) { return size_t(j * 4 + i); };
  switch (k) {
    case 0: return at(a, c);
    case 1: return at(3 - c, a);
    case 2: return at(3 - a, 3 - c);
    default: return at(c, 3 - a);
  }
}

Point3 limit_position(std::span<const double> limits, Index v) {
  const size_t i = 3 * size_t(v);
  return {limits[i], limits[i + 1], limits[i + 2]};
}

// The edge point of v = corner k of face f on its edge to corner k + 1 (towards_next) or
// k - 1. Inside the surface (Loop, Schaefer, Ni & Castaño 2009, section 3): with v's edges
// E_i in walk order (E_0 the edge to k + 1), Ê_i the Bézier edge point of Loop & Schaefer
// (2008) along E_i (the mean of the interior points either side) and lambda Catmull-Clark's
// subdominant eigenvalue (c + 5 + sqrt((c + 9)(c + 1))) / 16, c = cos(2 pi / n),
//   e_j = p + 1 / (n lambda) sum_i cos(2 pi (i - j) / n) Ê_i,
// a tangent from the ring's first Fourier mode, which at valence 4 is the B-spline patch's.
// Projected onto the plane of v's exact limit normal, so that the corner tangent plane is the
// limit's (the mode mixes the subdominant eigenvector with a smaller one). The projection is
// linear, so the tangents keep t_(j-1) + t_(j+1) = 2 c t_j, which the face points rely on.
// Along a boundary or crease edge v-w: (2 v + w) / 3, the cubic B-spline curve's (both sides
// of a crease compute it alike). At other edges of a boundary, crease or corner vertex: p plus
// a third of the Bézier mode's limit tangent (bezier_sectors.h: Biermann, Levin & Zorin 2000),
// which keeps t_(j-1) + t_(j+1) = 2 cos(pi / k) t_j inside a sector of k faces.
Point3 edge_point(const QuadMesh& m, std::span<const double> limits, Index f, int k, bool towards_next) {
  const Index v = m.vertex(f, k);
  if (m.curve_at(f, k, towards_next))
    return (1.0 / 3) * (2.0 * m.point(v) + m.point(m.vertex(f, towards_next ? k + 1 : k + 3)));
  if (!m.sector(f, k).closed) return limit_position(limits, v) + (1.0 / 3) * m.corner_tangent(f, k, towards_next);
  const int n = m.sector(f, k).faces;
  std::vector<Point3> interior;  // F_i in face g_i of the walk, E_i between g_(i-1) and g_i
  for (auto [g, c] = std::pair{f, k}; int(interior.size()) < n; std::tie(g, c) = m.step_forward(g, c))
    interior.push_back(interior_point(m, g, c));
  const double pi = std::numbers::pi, cosine = std::cos(2 * pi / n);
  const double lambda = (cosine + 5 + std::sqrt((cosine + 9) * (cosine + 1))) / 16;
  const int j = towards_next ? 0 : 1;
  Point3 t{0, 0, 0};
  for (int i = 0; i < n; ++i) {
    const Point3 edge = 0.5 * (interior[size_t(i)] + interior[size_t((i + n - 1) % n)]);
    t = t + std::cos(2 * pi * (i - j) / n) * edge;
  }
  return limit_position(limits, v) + m.projected(v, (1.0 / (n * lambda)) * t);
}

// r for corner k of face f on its edge to corner k + 1, pointing into f: the difference of
// v's other neighbours (1/3) and of the opposite corners (1/6) in f and in the face across
// the edge (Loop, Schaefer, Ni & Castaño 2009, section 3).
Point3 twist(const QuadMesh& m, Index f, int k) {
  const auto [g, l] = m.face_of(m.vertex(f, k + 1), m.vertex(f, k));  // in g: l = w, l + 1 = v
  return (1.0 / 3) * (m.point(m.vertex(f, k + 3)) - m.point(m.vertex(g, l + 2))) +
         (1.0 / 6) * (m.point(m.vertex(f, k + 2)) - m.point(m.vertex(g, l + 3)));
}

// The face point next to p0 on its edge to p1 (Loop, Schaefer, Ni & Castaño 2009, section 3):
// e0, e1 the two ends' edge points on the edge, c0, c1 their cosines, r the twist.
Point3 face_point(double c0, double c1, const Point3& p0, const Point3& e0, const Point3& e1, const Point3& r) {
  return (1.0 / 3) * (c1 * p0 + (3 - 2 * c0 - c1) * e0 + 2 * c0 * e1 + r);
}

GregoryPatch face_patch(const QuadMesh& m, Index f, std::span<const double> limits) {
  GregoryPatch p{};
  std::array<double, 4> cosine{};
  for (int k = 0; k < 4; ++k) {
    cosine[size_t(k)] = tangent_cosine(m.sector(f, k));
    p.boundary[local(k, 0, 0)] = limit_position(limits, m.vertex(f, k));
    p.boundary[local(k, 1, 0)] = edge_point(m, limits, f, k, true);
    p.boundary[local(k, 0, 1)] = edge_point(m, limits, f, k, false);
  }
  for (int k = 0; k < 4; ++k) {
    const int next = (k + 1) % 4, prev = (k + 3) % 4;
    const double c0 = cosine[size_t(k)];
    const Point3& p0 = p.boundary[local(k, 0, 0)];
    // Next to a boundary or crease edge the cross derivative need match nothing: Loop &
    // Schaefer's interior point, the B-spline patch's (with phantom points) where the
    // corner's sector is regular.
    if (m.feature(f, k)) p.face[size_t(2 * k)] = interior_point(m, f, k);
    // On the edge to k + 1: e_1 is corner k + 1's edge point back towards k.
    else
      p.face[size_t(2 * k)] = face_point(c0, cosine[size_t(next)], p0, p.boundary[local(k, 1, 0)],
                                         p.boundary[local(next, 0, 1)], twist(m, f, k));
    if (m.feature(f, k + 3)) p.face[size_t(2 * k + 1)] = interior_point(m, f, k);
    // On the edge to k - 1, whose twist is that of corner k in the face across it, reversed
    // (pointing into f): (a - a') / 3 + (d - d') / 6 with a = corner k + 1 here.
    else {
      const auto [g, l] = m.face_of(m.vertex(f, k), m.vertex(f, k + 3));  // in g: l = v, l + 1 = k - 1's vertex
      const Point3 r = (1.0 / 3) * (m.point(m.vertex(f, k + 1)) - m.point(m.vertex(g, l + 3))) +
                       (1.0 / 6) * (m.point(m.vertex(f, k + 2)) - m.point(m.vertex(g, l + 2)));
      p.face[size_t(2 * k + 1)] =
          face_point(c0, cosine[size_t(prev)], p0, p.boundary[local(k, 0, 1)], p.boundary[local(prev, 1, 0)], r);
    }
  }
  return p;
}

std::array<double, 4> bernstein(double t) {
  const double s = 1 - t;
  return {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
}

std::array<double, 4> bernstein_derivative(double t) {
  const double s = 1 - t;
  return {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t};
}

}  // namespace

std::vector<GregoryPatch> gregory_patches(const Level& topology, std::span<const double> positions,
                                          BoundaryInterpolation boundary, const VertexLimits& limits) {
  const QuadMesh mesh(topology, positions, boundary, limits.normals);
  std::vector<GregoryPatch> patches;
  patches.reserve(size_t(topology.face_count()));
  for (Index f = 0; f < topology.face_count(); ++f) patches.push_back(face_patch(mesh, f, limits.positions));
  return patches;
}

PatchSample evaluate_gregory(const GregoryPatch& p, double u, double v) {
  // The interior points and their derivatives: corner k's b = (w+ f+ + w- f-) / (w+ + w-),
  // each face point weighted by the distance to the other edge at that corner.
  std::array<Point3, 16> net = p.boundary, net_du{}, net_dv{};
  struct Blend {
    double plus, minus, plus_du, plus_dv, minus_du, minus_dv;
  };
  const std::array<Blend, 4> blends{Blend{u, v, 1, 0, 0, 1}, Blend{v, 1 - u, 0, 1, -1, 0},
                                    Blend{1 - u, 1 - v, -1, 0, 0, -1}, Blend{1 - v, u, 0, -1, 1, 0}};
  for (int k = 0; k < 4; ++k) {
    const Blend& w = blends[size_t(k)];
    const Point3& fp = p.face[size_t(2 * k)];
    const Point3& fm = p.face[size_t(2 * k + 1)];
    const double sum = w.plus + w.minus;
    const size_t i = local(k, 1, 1);
    if (sum <= 0) {  // at the corner itself, where the point's Bernstein weight and its derivatives vanish
      net[i] = 0.5 * (fp + fm);
      continue;
    }
    const Point3 b = (1 / sum) * (w.plus * fp + w.minus * fm);
    net[i] = b;
    net_du[i] = (1 / sum) * (w.plus_du * (fp - b) + w.minus_du * (fm - b));
    net_dv[i] = (1 / sum) * (w.plus_dv * (fp - b) + w.minus_dv * (fm - b));
  }
  const auto bu = bernstein(u), bv = bernstein(v), du = bernstein_derivative(u), dv = bernstein_derivative(v);
  PatchSample s{};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const size_t x = size_t(j * 4 + i);
      const double w = bu[size_t(i)] * bv[size_t(j)];
      s.position = s.position + w * net[x];
      s.du = s.du + (du[size_t(i)] * bv[size_t(j)]) * net[x] + w * net_du[x];
      s.dv = s.dv + (bu[size_t(i)] * dv[size_t(j)]) * net[x] + w * net_dv[x];
    }
  s.geometry_du = s.du;
  s.geometry_dv = s.dv;
  return s;
}

}  // namespace subdiv
