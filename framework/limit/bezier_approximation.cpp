#include "framework/limit/bezier_approximation.h"

#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <tuple>
#include <unordered_map>

#include "framework/limit/bezier_sectors.h"
#include "framework/limit/limit_surface.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

using bezier::QuadMesh;
using bezier::Sector;
using bezier::interior_point;
using bezier::tangent_cosine;
using bezier::operator+;
using bezier::operator-;
using bezier::operator*;

// Edge point next to v on the edge v-w. Along a boundary or infinitely sharp edge the limit
// curve is the cubic B-spline of the feature polygon (its ends kept at corners), whose
// Bézier point next to v is (2 v + w) / 3. Elsewhere the mean of the interior points next to
// v in the edge's two quads: both quads compute it from the same two points in the same
// order, so their boundary curves agree to the bit.
Point3 edge_point(const QuadMesh& m, Index v, Index w, bool feature) {
  if (feature) return (1.0 / 3) * (2.0 * m.point(v) + m.point(w));
  const auto [f, k] = m.face_of(v, w);
  const auto [g, l] = m.face_of(w, v);
  return 0.5 * (interior_point(m, f, k) + interior_point(m, g, (l + 1) % 4));
}

// The two cross-boundary tangent points next to an edge from A to B, pointing into the
// quad: a = the edge's own tangent coefficients (degree 2) from A, cA = cos(2 pi / n_A),
// cB likewise, d1, d2 the geometry patch's cross differences 3 (interior - edge point).
// The two quads of the edge then have cross derivatives summing to
// (2 cA (1 - t) - 2 cB t) times the edge tangent (Loop & Schaefer 2008, section 4): both
// lie in one plane with it, so the normals agree along the edge.
std::pair<Point3, Point3> cross_points(const std::array<Point3, 3>& a, double cA, double cB, const Point3& d1,
                                       const Point3& d2) {
  return {(1.0 / 3) * (2 * cA * a[1] - cB * a[0]) + d1, (1.0 / 3) * (cA * a[2] - 2 * cB * a[1]) + d2};
}

BezierPatch face_patch(const QuadMesh& m, Index f, std::span<const double> limits) {
  BezierPatch p;
  auto& b = p.geometry;
  auto at = [&b](int i, int j) -> Point3& { return b[size_t(j * 4 + i)]; };
  // Corner k's frame: a steps along the edge k -> k+1, c steps along k -> k-1.
  auto local = [&at](int k, int a, int c) -> Point3& {
    switch (k) {
      case 0: return at(a, c);
      case 1: return at(3 - c, a);
      case 2: return at(3 - a, 3 - c);
      default: return at(c, 3 - a);
    }
  };
  std::array<double, 4> cosine{};
  for (int k = 0; k < 4; ++k) {
    cosine[size_t(k)] = tangent_cosine(m.sector(f, k));
    const size_t i = 3 * size_t(m.vertex(f, k));
    local(k, 0, 0) = {limits[i], limits[i + 1], limits[i + 2]};
    local(k, 1, 1) = interior_point(m, f, k);
    local(k, 1, 0) = edge_point(m, m.vertex(f, k), m.vertex(f, k + 1), m.feature(f, k));
    local(k, 0, 1) = edge_point(m, m.vertex(f, k), m.vertex(f, k + 3), m.feature(f, k + 3));
  }
  // The corner derivative at corner k along its edge to corner `to` (k + 1 or k - 1).
  auto T = [&](int k, int to) { return m.corner_tangent(f, k, to == (k + 1) % 4); };
  auto U = [&p](int i, int j) -> Point3& { return p.tangent_u[size_t(j * 3 + i)]; };
  auto V = [&p](int i, int j) -> Point3& { return p.tangent_v[size_t(j * 4 + i)]; };
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 3; ++i) U(i, j) = 3.0 * (at(i + 1, j) - at(i, j));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) V(i, j) = 3.0 * (at(i, j + 1) - at(i, j));
  // Along the edges: the corner derivatives from the tangent masks.
  U(0, 0) = T(0, 1), U(2, 0) = -1.0 * T(1, 0), U(0, 3) = T(3, 2), U(2, 3) = -1.0 * T(2, 3);
  V(0, 0) = T(0, 3), V(0, 2) = -1.0 * T(3, 0), V(3, 0) = T(1, 2), V(3, 2) = -1.0 * T(2, 1);
  // Across the edges that are not boundary or crease edges (across those the geometry's own
  // derivatives stay: the surface has no other side there, or one it need not match).
  // Edge 0 (v = 0, corners 0 -> 1): +V points into the quad.
  if (!m.feature(f, 0))
    std::tie(V(1, 0), V(2, 0)) = cross_points({U(0, 0), U(1, 0), U(2, 0)}, cosine[0], cosine[1],
                                              3.0 * (at(1, 1) - at(1, 0)), 3.0 * (at(2, 1) - at(2, 0)));
  // Edge 2 (v = 1, corners 3 -> 2): -V points into the quad.
  if (!m.feature(f, 2)) {
    const auto [x12, x22] = cross_points({U(0, 3), U(1, 3), U(2, 3)}, cosine[3], cosine[2],
                                         3.0 * (at(1, 2) - at(1, 3)), 3.0 * (at(2, 2) - at(2, 3)));
    V(1, 2) = -1.0 * x12, V(2, 2) = -1.0 * x22;
  }
  // Edge 3 (u = 0, corners 0 -> 3): +U points into the quad.
  if (!m.feature(f, 3))
    std::tie(U(0, 1), U(0, 2)) = cross_points({V(0, 0), V(0, 1), V(0, 2)}, cosine[0], cosine[3],
                                              3.0 * (at(1, 1) - at(0, 1)), 3.0 * (at(1, 2) - at(0, 2)));
  // Edge 1 (u = 1, corners 1 -> 2): -U points into the quad.
  if (!m.feature(f, 1)) {
    const auto [x21, x22] = cross_points({V(3, 0), V(3, 1), V(3, 2)}, cosine[1], cosine[2],
                                         3.0 * (at(2, 1) - at(3, 1)), 3.0 * (at(2, 2) - at(3, 2)));
    U(2, 1) = -1.0 * x21, U(2, 2) = -1.0 * x22;
  }
  return p;
}

template <int D>
std::array<double, D + 1> bernstein(double t) {
  const double s = 1 - t;
  if constexpr (D == 3) return {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
  else return {s * s, 2 * t * s, t * t};
}

template <int DU, int DV, size_t N>
Point3 tensor(const std::array<Point3, N>& c, double u, double v) {
  const auto bu = bernstein<DU>(u);
  const auto bv = bernstein<DV>(v);
  Point3 r{0, 0, 0};
  for (int j = 0; j <= DV; ++j)
    for (int i = 0; i <= DU; ++i) r = r + (bu[size_t(i)] * bv[size_t(j)]) * c[size_t(j * (DU + 1) + i)];
  return r;
}

// A generic value per vertex of a regular torus grid (nu x nv), not a polynomial of low degree.
double generic_value(int i, int j) { return std::sin(1.3 * i + 0.7 * j * j + 0.11 * i * j) + 0.3 * i - 0.2 * j; }

// The uniform cubic B-spline basis over control points at -1, 0, 1, 2.
std::array<double, 4> bspline_basis(double s) {
  const double r = 1 - s;
  return {r * r * r / 6, (3 * s * s * s - 6 * s * s + 4) / 6, (-3 * s * s * s + 3 * s * s + 3 * s + 1) / 6,
          s * s * s / 6};
}

// The bicubic B-spline patch of the 4 x 4 values value(i, j), i, j in -1..2, at (u, v).
template <typename Value>
double bspline_patch(const Value& value, double u, double v) {
  const auto bu = bspline_basis(u), bv = bspline_basis(v);
  double sum = 0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) sum += bu[size_t(i)] * bv[size_t(j)] * value(i - 1, j - 1);
  return sum;
}

// A regular quad grid of `cells` x `cells` faces, vertex (i, j) numbered j * (cells + 1) + i.
Level open_grid(int cells) {
  std::vector<Index> offsets{0}, corners;
  const auto id = [cells](int i, int j) { return Index(j * (cells + 1) + i); };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      corners.insert(corners.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      offsets.push_back(Index(corners.size()));
    }
  return build_level((cells + 1) * (cells + 1), offsets, corners);
}

}  // namespace

std::string bezier_approximation_unsupported(const std::shared_ptr<const Scheme>& scheme) {
  if (std::string why = limit_surface_unsupported(*scheme); !why.empty()) return why;
  constexpr int kGrid = 7;  // a regular torus: every face has the full 4 x 4 neighbourhood
  std::vector<Index> offsets{0}, corners;
  std::vector<double> values;
  auto id = [](int i, int j) { return Index(((j + kGrid) % kGrid) * kGrid + (i + kGrid) % kGrid); };
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      values.push_back(generic_value(i, j));
      corners.insert(corners.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      offsets.push_back(Index(corners.size()));
    }
  try {
    const LimitSurface surface(scheme, build_level(kGrid * kGrid, offsets, corners));
    if (surface.triangles())
      return "its split makes triangles: Loop & Schaefer's patches are bicubic, one per quad";
    const Index face = id(3, 3);
    const auto around_face = [&](int i, int j) { return values[size_t(id(3 + i, 3 + j))]; };
    for (const auto& uv : {std::array{0.3, 0.7}, std::array{0.55, 0.15}}) {
      const double bspline = bspline_patch(around_face, uv[0], uv[1]);
      const double limit = surface.evaluate(face, uv[0], uv[1], values, 1, 0).position[0];
      if (!(std::abs(limit - bspline) <= 1e-9))
        return fmt::format("its limit over a regular quad is not the bicubic B-spline patch (at (u, v) = ({}, {}) of "
                           "a regular torus they differ by {:.3g}): Loop & Schaefer's patches reproduce exactly that "
                           "patch where every valence is 4",
                           uv[0], uv[1], std::abs(limit - bspline));
    }
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

std::string bezier_features_unsupported(const std::shared_ptr<const Scheme>& scheme, const FeatureOptions& features) {
  // An open 6 x 6 grid, corners kept: the limit over a face at the boundary, and over the
  // corner face, must be the bicubic B-spline patch with phantom points reflected across
  // the boundary (p(-1) = 2 p(0) - p(1), per direction), as Catmull-Clark's boundary rules
  // make it (the cubic B-spline boundary curve; OpenSubdiv's regular boundary and corner
  // patches). An infinitely sharp edge is then checked the same way from one side: the
  // grid's middle row made a crease.
  constexpr int kCells = 6;
  std::vector<double> values;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) values.push_back(generic_value(i, j));
  const auto grid = [&values](int i, int j) { return values[size_t(j * (kCells + 1) + i)]; };
  // The value at (i, j), reflected across the grid's edges and the row `crease` (from
  // below) where the point lies outside: the phantom points.
  const auto phantom = [&grid](int i, int j, int crease) {
    const auto column = [&grid, crease](int x, int y) {
      if (y < 0) return 2 * grid(x, 0) - grid(x, 1);
      if (crease > 0 && y > crease) return 2 * grid(x, crease) - grid(x, crease - 1);
      return grid(x, y);
    };
    if (i < 0) return 2 * column(0, j) - column(1, j);
    return column(i, j);
  };
  LimitSurfaceOptions options;
  options.features = features;
  options.features.boundary = BoundaryInterpolation::EdgesAndCorners;
  try {
    for (const int crease : {0, 3}) {
      Level level = open_grid(kCells);
      if (crease > 0) {
        level.edge_sharpness.assign(size_t(level.edge_count()), 0.f);
        for (Index e = 0; e < level.edge_count(); ++e)
          if (level.edge_vertices[2 * size_t(e)] / (kCells + 1) == crease &&
              level.edge_vertices[2 * size_t(e) + 1] / (kCells + 1) == crease)
            level.edge_sharpness[size_t(e)] = 10.f;
      }
      const LimitSurface surface(scheme, std::move(level), options);
      // Corner face (0, 0) and boundary face (2, 0); with the crease, the face (2, crease - 1)
      // below it, whose phantom row is reflected across the crease.
      const int row = crease > 0 ? crease - 1 : 0;
      for (const auto& face : {std::array{0, row}, std::array{2, row}}) {
        const int fi = face[0], fj = face[1];
        const auto value = [&](int i, int j) { return phantom(fi + i, fj + j, crease); };
        for (const auto& uv : {std::array{0.3, 0.7}, std::array{0.55, 0.15}}) {
          const double expected = bspline_patch(value, uv[0], uv[1]);
          const double limit = surface.evaluate(Index(fj * kCells + fi), uv[0], uv[1], values, 1, 0).position[0];
          if (!(std::abs(limit - expected) <= 1e-9))
            return fmt::format("its limit next to {} is not the bicubic B-spline patch with phantom points (at "
                               "(u, v) = ({}, {}) of face ({}, {}) of an open grid they differ by {:.3g}): the "
                               "patches' boundary and crease masks reproduce exactly that patch",
                               crease > 0 ? "an infinitely sharp crease" : "a boundary", uv[0], uv[1], fi, fj,
                               std::abs(limit - expected));
        }
      }
    }
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

std::vector<BezierPatch> bezier_patches(const Level& topology, std::span<const double> positions,
                                        BoundaryInterpolation boundary, const VertexLimits& limits) {
  const QuadMesh mesh(topology, positions, boundary, limits.normals);
  std::vector<BezierPatch> patches;
  patches.reserve(size_t(topology.face_count()));
  for (Index f = 0; f < topology.face_count(); ++f) patches.push_back(face_patch(mesh, f, limits.positions));
  return patches;
}

PatchSample evaluate_patch(const BezierPatch& p, double u, double v) {
  PatchSample s;
  s.position = tensor<3, 3>(p.geometry, u, v);
  s.du = tensor<2, 3>(p.tangent_u, u, v);
  s.dv = tensor<3, 2>(p.tangent_v, u, v);
  std::array<Point3, 12> gu, gv;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 3; ++i)
      gu[size_t(j * 3 + i)] = 3.0 * (p.geometry[size_t(j * 4 + i + 1)] - p.geometry[size_t(j * 4 + i)]);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      gv[size_t(j * 4 + i)] = 3.0 * (p.geometry[size_t((j + 1) * 4 + i)] - p.geometry[size_t(j * 4 + i)]);
  s.geometry_du = tensor<2, 3>(gu, u, v);
  s.geometry_dv = tensor<3, 2>(gv, u, v);
  return s;
}

}  // namespace subdiv
