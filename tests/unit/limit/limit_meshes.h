#pragma once
// Meshes for the limit tests.
#include <cmath>
#include <span>

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

// The Euclidean distance between two points (or any two equally long vectors).
inline double distance(std::span<const double> a, std::span<const double> b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

}  // namespace subdiv::limit_test
