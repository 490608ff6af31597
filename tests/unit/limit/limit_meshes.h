#pragma once
// Meshes for the limit tests.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include <doctest/doctest.h>

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

}  // namespace subdiv::limit_test
