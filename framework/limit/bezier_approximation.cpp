#include "framework/limit/bezier_approximation.h"

#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <tuple>
#include <unordered_map>

#include "framework/limit/limit_surface.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

Point3 operator+(const Point3& a, const Point3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point3 operator-(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point3 operator*(double s, const Point3& a) { return {s * a[0], s * a[1], s * a[2]}; }

// The quads by their directed edges: the face and corner each directed edge a -> b starts at.
class QuadMesh {
public:
  QuadMesh(const Level& level, std::span<const double> positions) : level_(level), positions_(positions) {
    for (Index f = 0; f + 1 < Index(level.face_offsets.size()); ++f) {
      const Index size = level.face_offsets[size_t(f) + 1] - level.face_offsets[size_t(f)];
      if (size != 4)
        throw Error(fmt::format("face {} has {} sides: Loop & Schaefer's patches are one per quad; refine the mesh "
                                "once (subdiv refine -l 1 makes every face a quad) and approximate that",
                                f, size));
      for (int k = 0; k < 4; ++k)
        if (!edge_.emplace(key(vertex(f, k), vertex(f, k + 1)), std::pair{f, k}).second)
          throw Error(fmt::format("face {}: its edge {}-{} is used twice in one direction (a non-manifold or "
                                  "inconsistently oriented edge); the masks need a closed manifold quad mesh",
                                  f, vertex(f, k), vertex(f, k + 1)));
    }
    for (Index f = 0; f + 1 < Index(level.face_offsets.size()); ++f)  // the first boundary edge in face order
      for (int k = 0; k < 4; ++k)
        if (!edge_.contains(key(vertex(f, k + 1), vertex(f, k))))
          throw Error(fmt::format("face {}: its edge {}-{} is a boundary edge; Loop & Schaefer's masks are those of "
                                  "interior vertices (a closed mesh)",
                                  f, vertex(f, k), vertex(f, k + 1)));
  }

  Index vertex(Index f, int k) const {
    return level_.face_vertices[size_t(level_.face_offsets[size_t(f)]) + size_t(((k % 4) + 4) % 4)];
  }
  Point3 point(Index v) const {
    const size_t i = 3 * size_t(v);
    return {positions_[i], positions_[i + 1], positions_[i + 2]};
  }
  // The face and corner where the directed edge a -> b starts.
  std::pair<Index, int> face_of(Index a, Index b) const { return edge_.at(key(a, b)); }
  int valence(Index v, Index f, int k) const {
    int n = 0;
    Index g = f;
    int c = k;
    do {  // around v: the face holding v -> (g's previous vertex)
      const Index prev = vertex(g, c + 3);
      std::tie(g, c) = face_of(v, prev);
      ++n;
    } while (g != f);
    return n;
  }

private:
  static std::uint64_t key(Index a, Index b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }
  const Level& level_;
  std::span<const double> positions_;
  std::unordered_map<std::uint64_t, std::pair<Index, int>> edge_;
};

// Interior point next to corner k of face f: (n v + 2 e_a + 2 e_b + d) / (n + 5).
Point3 interior_point(const QuadMesh& m, Index f, int k) {
  const double n = m.valence(m.vertex(f, k), f, k);
  const Point3 s = n * m.point(m.vertex(f, k)) + 2.0 * m.point(m.vertex(f, k + 1)) +
                   2.0 * m.point(m.vertex(f, k + 3)) + m.point(m.vertex(f, k + 2));
  return (1.0 / (n + 5)) * s;
}

// Edge point next to v = vertex(f, k) on the edge v -> w: the mean of the interior points
// next to v in the edge's two quads. Both quads compute it from the same two points in
// the same order, so their boundary curves agree to the bit.
Point3 edge_point(const QuadMesh& m, Index v, Index w) {
  const auto [f, k] = m.face_of(v, w);
  const auto [g, l] = m.face_of(w, v);
  return 0.5 * (interior_point(m, f, k) + interior_point(m, g, (l + 1) % 4));
}

// The limit tangent along the edge v -> w, for the patch parameter of unit speed where v
// is regular: Catmull-Clark's tangent mask (the subdominant left eigenvectors; Halstead,
// Kass & DeRose 1993, used by Loop & Schaefer 2008 section 4): over v's ring, edge
// neighbours e_i (e_0 = w) weighted A cos(2 pi i / n), face neighbours d_i (between e_i and
// e_{i+1}) weighted B cos((2i + 1) pi / n), B = 1 / (n sqrt(4 + cos^2(pi / n))),
// A = 1/n + cos(pi / n) B. Tangents along consecutive edges then satisfy
// t_{i-1} + t_{i+1} = 2 cos(2 pi / n) t_i, which the tangent patches rely on.
Point3 corner_tangent(const QuadMesh& m, Index v, Index w, int n) {
  const double pi = std::numbers::pi, c = std::cos(pi / n);
  const double b = 1.0 / (n * std::sqrt(4 + c * c)), a = 1.0 / n + c * b;
  Point3 t{0, 0, 0};
  auto [f, k] = m.face_of(v, w);
  for (int i = 0; i < n; ++i) {
    t = t + (a * std::cos(2 * pi * i / n)) * m.point(m.vertex(f, k + 1));
    t = t + (b * std::cos((2 * i + 1) * pi / n)) * m.point(m.vertex(f, k + 2));
    std::tie(f, k) = m.face_of(v, m.vertex(f, k + 3));
  }
  return t;
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
  std::array<int, 4> n{};
  std::array<double, 4> cosine{};
  std::array<Index, 4> v{};
  for (int k = 0; k < 4; ++k) {
    v[size_t(k)] = m.vertex(f, k);
    n[size_t(k)] = m.valence(v[size_t(k)], f, k);
    cosine[size_t(k)] = n[size_t(k)] == 4 ? 0.0 : std::cos(2 * std::numbers::pi / n[size_t(k)]);
    const size_t i = 3 * size_t(v[size_t(k)]);
    local(k, 0, 0) = {limits[i], limits[i + 1], limits[i + 2]};
    local(k, 1, 1) = interior_point(m, f, k);
    local(k, 1, 0) = edge_point(m, v[size_t(k)], m.vertex(f, k + 1));
    local(k, 0, 1) = edge_point(m, v[size_t(k)], m.vertex(f, k + 3));
  }
  auto T = [&](int k, int to) { return corner_tangent(m, v[size_t(k)], v[size_t(to)], n[size_t(k)]); };
  auto U = [&p](int i, int j) -> Point3& { return p.tangent_u[size_t(j * 3 + i)]; };
  auto V = [&p](int i, int j) -> Point3& { return p.tangent_v[size_t(j * 4 + i)]; };
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 3; ++i) U(i, j) = 3.0 * (at(i + 1, j) - at(i, j));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) V(i, j) = 3.0 * (at(i, j + 1) - at(i, j));
  // Along the edges: the corner derivatives from the tangent masks.
  U(0, 0) = T(0, 1), U(2, 0) = -1.0 * T(1, 0), U(0, 3) = T(3, 2), U(2, 3) = -1.0 * T(2, 3);
  V(0, 0) = T(0, 3), V(0, 2) = -1.0 * T(3, 0), V(3, 0) = T(1, 2), V(3, 2) = -1.0 * T(2, 1);
  // Across the edges. Edge 0 (v = 0, corners 0 -> 1): +V points into the quad.
  std::tie(V(1, 0), V(2, 0)) = cross_points({U(0, 0), U(1, 0), U(2, 0)}, cosine[0], cosine[1],
                                            3.0 * (at(1, 1) - at(1, 0)), 3.0 * (at(2, 1) - at(2, 0)));
  // Edge 2 (v = 1, corners 3 -> 2): -V points into the quad.
  auto [x12, x22] = cross_points({U(0, 3), U(1, 3), U(2, 3)}, cosine[3], cosine[2], 3.0 * (at(1, 2) - at(1, 3)),
                                 3.0 * (at(2, 2) - at(2, 3)));
  V(1, 2) = -1.0 * x12, V(2, 2) = -1.0 * x22;
  // Edge 3 (u = 0, corners 0 -> 3): +U points into the quad.
  std::tie(U(0, 1), U(0, 2)) = cross_points({V(0, 0), V(0, 1), V(0, 2)}, cosine[0], cosine[3],
                                            3.0 * (at(1, 1) - at(0, 1)), 3.0 * (at(1, 2) - at(0, 2)));
  // Edge 1 (u = 1, corners 1 -> 2): -U points into the quad.
  auto [x21, x22u] = cross_points({V(3, 0), V(3, 1), V(3, 2)}, cosine[1], cosine[2], 3.0 * (at(2, 1) - at(3, 1)),
                                  3.0 * (at(2, 2) - at(3, 2)));
  U(2, 1) = -1.0 * x21, U(2, 2) = -1.0 * x22u;
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
    // The cubic B-spline basis (control points at -1, 0, 1, 2).
    auto basis = [](double s) {
      const double r = 1 - s;
      return std::array<double, 4>{r * r * r / 6, (3 * s * s * s - 6 * s * s + 4) / 6,
                                   (-3 * s * s * s + 3 * s * s + 3 * s + 1) / 6, s * s * s / 6};
    };
    const Index face = id(3, 3);
    for (const auto& uv : {std::array{0.3, 0.7}, std::array{0.55, 0.15}}) {
      const auto bu = basis(uv[0]), bv = basis(uv[1]);
      double bspline = 0;
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) bspline += bu[size_t(i)] * bv[size_t(j)] * values[size_t(id(2 + i, 2 + j))];
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

std::vector<BezierPatch> bezier_patches(const Level& topology, std::span<const double> positions,
                                        const CornerLimits& corner_limits) {
  const QuadMesh mesh(topology, positions);
  std::vector<Index> faces(size_t(topology.vertex_count), kNone);
  std::vector<double> uv(2 * size_t(topology.vertex_count), 0.0);
  constexpr double corner_u[4] = {0, 1, 1, 0}, corner_v[4] = {0, 0, 1, 1};
  for (Index f = 0; f + 1 < Index(topology.face_offsets.size()); ++f)
    for (int k = 0; k < 4; ++k) {
      const Index v = mesh.vertex(f, k);
      if (faces[size_t(v)] != kNone) continue;
      faces[size_t(v)] = f;
      uv[2 * size_t(v)] = corner_u[k];
      uv[2 * size_t(v) + 1] = corner_v[k];
    }
  for (Index v = 0; v < topology.vertex_count; ++v)
    if (faces[size_t(v)] == kNone) throw Error(fmt::format("vertex {} is in no face", v));
  const std::vector<double> limits = corner_limits(faces, uv);
  std::vector<BezierPatch> patches;
  patches.reserve(topology.face_offsets.size() - 1);
  for (Index f = 0; f + 1 < Index(topology.face_offsets.size()); ++f)
    patches.push_back(face_patch(mesh, f, limits));
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
