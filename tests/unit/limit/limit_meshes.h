#pragma once
// Meshes for the limit tests.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <map>
#include <random>
#include <vector>
#include <utility>
#include <span>

#include <doctest/doctest.h>

#include "framework/io/mesh_data.h"
#include "framework/limit/limit_surface.h"
#include "support/test_meshes.h"

namespace subdiv::limit_test {

// test::octahedron() spelt out: GCC 12 warns (a false -Wstringop-overflow) when it inlines
// that one's add_vertex calls into these tests.
inline test::Mesh octahedron() {
  test::Mesh m;
  m.vertex_count = 6;
  m.positions = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  m.corners = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  m.offsets = {0, 3, 6, 9, 12, 15, 18, 21, 24};
  return m;
}

// The mesh with every vertex moved by a smooth, non-polynomial amount (z by up to
// `z_amplitude`), so that closed forms and symmetry cannot hide a wrong weight.
inline test::Mesh bumped(test::Mesh m, double z_amplitude = 0.1) {
  for (Index v = 0; v < m.vertex_count; ++v) {
    m.positions[size_t(3 * v)] += 0.07 * std::sin(2.3 * v + 0.1);
    m.positions[size_t(3 * v + 1)] += 0.05 * std::cos(1.1 * v + 0.4);
    m.positions[size_t(3 * v + 2)] += z_amplitude * std::sin(1.7 * v + 0.3);
  }
  return m;
}

// A regular n x n quad torus whose control points sit at their own grid coordinates
// (i, j, 0), vertex j n + i: unrolled away from the seam, so faces whose neighbourhood
// does not reach it have the plane (i + u, j + v) as limit for a scheme with linear precision.
inline test::Mesh unrolled_torus(int n) {
  test::Mesh m = test::torus(n, n);
  for (Index v = 0; v < m.vertex_count; ++v) {
    m.positions[size_t(3 * v)] = double(v % n);
    m.positions[size_t(3 * v + 1)] = double(v / n);
    m.positions[size_t(3 * v + 2)] = 0;
  }
  return m;
}

// The (u, v) of the point at t along a quad's edge k (from corner k to corner k + 1).
inline std::array<double, 2> quad_edge_point(int k, double t) {
  switch (k) {
    case 0: return {t, 0};
    case 1: return {1, t};
    case 2: return {1 - t, 1};
    default: return {0, 1 - t};
  }
}

// The Euclidean distance between two points (or any two equally long vectors).
inline double distance(std::span<const double> a, std::span<const double> b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

// The largest difference between the first derivatives evaluated at (face, u, v) and central
// differences (step h) of the evaluated positions.
inline double central_difference_error(const LimitSurface& s, Index face, double u, double v,
                                       std::span<const double> positions, double h = 1e-5) {
  const LimitSample p = s.evaluate(face, u, v, positions, 3);
  REQUIRE(p.has_derivatives);
  const LimitSample a = s.evaluate(face, u + h, v, positions, 3, 0), b = s.evaluate(face, u - h, v, positions, 3, 0);
  const LimitSample e = s.evaluate(face, u, v + h, positions, 3, 0), g = s.evaluate(face, u, v - h, positions, 3, 0);
  double worst = 0;
  for (size_t r = 0; r < 3; ++r) {
    worst = std::max(worst, std::fabs((a.position[r] - b.position[r]) / (2 * h) - p.du[r]));
    worst = std::max(worst, std::fabs((e.position[r] - g.position[r]) / (2 * h) - p.dv[r]));
  }
  return worst;
}

// Every face with n sides split into n quads at its centroid and edge midpoints (a bilinear
// step): the centroids get valence n, so triangles, pentagons and hexagons make quad meshes
// with extraordinary vertices of valence 3, 5 and 6.
inline test::Mesh quad_split(const test::Mesh& m) {
  test::Mesh q;
  q.positions = m.positions;
  q.vertex_count = m.vertex_count;
  std::map<std::pair<Index, Index>, Index> mid;
  auto edge = [&](Index a, Index b) {
    const auto key = std::minmax(a, b);
    auto [it, added] = mid.emplace(std::pair{key.first, key.second}, q.vertex_count);
    if (added)
      q.add_vertex((m.positions[3 * size_t(a)] + m.positions[3 * size_t(b)]) / 2,
                   (m.positions[3 * size_t(a) + 1] + m.positions[3 * size_t(b) + 1]) / 2,
                   (m.positions[3 * size_t(a) + 2] + m.positions[3 * size_t(b) + 2]) / 2);
    return it->second;
  };
  for (size_t f = 0; f + 1 < m.offsets.size(); ++f) {
    const Index first = m.offsets[f], n = m.offsets[f + 1] - first;
    double c[3] = {0, 0, 0};
    for (Index k = 0; k < n; ++k)
      for (int x = 0; x < 3; ++x) c[x] += m.positions[3 * size_t(m.corners[size_t(first + k)]) + size_t(x)] / n;
    const Index centre = q.vertex_count;
    q.add_vertex(c[0], c[1], c[2]);
    for (Index k = 0; k < n; ++k) {
      const Index v = m.corners[size_t(first + k)], next = m.corners[size_t(first + (k + 1) % n)],
                  prev = m.corners[size_t(first + (k + n - 1) % n)];
      const Index a = edge(v, next), b = edge(prev, v);
      q.add_face({v, a, centre, b});
    }
  }
  return q;
}

// A grid whose heights are not a low-degree polynomial, so that exactness means something.
inline test::Mesh bumpy(test::Mesh m) {
  for (Index v = 0; v < m.vertex_count; ++v) {
    double* p = &m.positions[3 * size_t(v)];
    p[2] += 0.3 * std::sin(1.7 * p[0] + 0.4 * p[1] * p[1]) + 0.1 * p[0] * p[1];
  }
  return m;
}

// Every edge of the mesh whose ends pass `on_crease`, as an infinitely sharp crease.
inline std::vector<CreaseTag> creases_along(const test::Mesh& m, const std::function<bool(Index, Index)>& on_crease) {
  std::vector<CreaseTag> out;
  for (size_t f = 0; f + 1 < m.offsets.size(); ++f)
    for (Index k = m.offsets[f]; k < m.offsets[f + 1]; ++k) {
      const Index a = m.corners[size_t(k)];
      const Index b = m.corners[size_t(k + 1 == m.offsets[f + 1] ? m.offsets[f] : k + 1)];
      if (a < b && on_crease(a, b)) out.push_back({a, b, 10.0});
    }
  return out;
}

// A 4 x 4 grid without its middle 2 x 2 faces, made bumpy: the hole's corners have three faces.
inline test::Mesh bumpy_plane_with_hole() {
  test::Mesh m = test::grid(4, 4);
  test::Mesh out;
  out.positions = m.positions;
  out.vertex_count = m.vertex_count;
  for (size_t f = 0; f + 1 < m.offsets.size(); ++f)
    if (f != 5 && f != 6 && f != 9 && f != 10)
      out.add_face({m.corners[4 * f], m.corners[4 * f + 1], m.corners[4 * f + 2], m.corners[4 * f + 3]});
  return bumpy(out);
}

// `count` points (face, u, v) drawn uniformly over faces 0 .. faces - 1.
struct FacePoints {
  std::vector<Index> faces;
  std::vector<double> uv;
};
inline FacePoints random_face_points(int count, Index faces, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  FacePoints out;
  for (int i = 0; i < count; ++i) {
    out.faces.push_back(Index(rng() % unsigned(faces)));
    out.uv.push_back(unit(rng));
    out.uv.push_back(unit(rng));
  }
  return out;
}

// Points (face, u, v) at parameters `ts` along every boundary edge of `level`'s quads.
inline FacePoints boundary_edge_points(const Level& level, std::initializer_list<double> ts) {
  FacePoints out;
  for (Index f = 0; f < level.face_count(); ++f)
    for (int k = 0; k < 4; ++k)
      if (level.edge_on_boundary(level.face_edges[size_t(4 * f + k)]))
        for (double t : ts) {
          out.faces.push_back(f);
          const auto at = quad_edge_point(k, t);
          out.uv.insert(out.uv.end(), {at[0], at[1]});
        }
  return out;
}

// Every directed edge (a, b) of `level`'s faces: the face and corner it starts at.
inline std::map<std::pair<Index, Index>, std::pair<Index, int>> directed_edges(const Level& level) {
  std::map<std::pair<Index, Index>, std::pair<Index, int>> directed;
  for (Index f = 0; f < level.face_count(); ++f) {
    const auto face = level.face(f);
    for (size_t k = 0; k < face.size(); ++k) directed[{face[k], face[(k + 1) % face.size()]}] = {f, int(k)};
  }
  return directed;
}
inline std::map<std::pair<Index, Index>, std::pair<Index, int>> directed_quad_edges(const Level& level) {
  return directed_edges(level);
}

// The angle between two vectors, and their cross product.
inline double angle(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const std::array<double, 3> c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double s = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  return std::atan2(s, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

inline std::array<double, 3> normal(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace subdiv::limit_test
