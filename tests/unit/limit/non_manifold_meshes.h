#pragma once
// Non-manifold meshes for the limit tests (limit evaluation and adaptive refinement): fans of
// flaps on a hinge, two sheets through one vertex, a face running its shared edge the wrong
// way, and their triangulations.
#include <cmath>
#include <vector>

#include "support/test_meshes.h"

namespace subdiv::non_manifold_test {

// `pages` bent quad strips of 2 columns hinged on a line of `hinge` edges along y: the hinge
// edges have `pages` faces each; with hinge >= 2 its inner vertices are a non-manifold crease.
inline test::Mesh book(int pages, int hinge) {
  test::Mesh m;
  for (int j = 0; j <= hinge; ++j) m.add_vertex(0, j, 0.05 * j * j);
  for (int p = 0; p < pages; ++p) {
    const double angle = 2.0 * M_PI * p / pages + 0.3;
    const Index first = m.vertex_count;
    for (int c = 1; c <= 2; ++c)
      for (int j = 0; j <= hinge; ++j)
        m.add_vertex(c * std::cos(angle), j + 0.1 * c * p, c * std::sin(angle) + 0.2 * c * c + 0.03 * j * p);
    const auto at = [&](int c, int j) { return c == 0 ? Index(j) : first + Index((c - 1) * (hinge + 1) + j); };
    for (int c = 0; c < 2; ++c)
      for (int j = 0; j < hinge; ++j) m.add_face({at(c, j), at(c + 1, j), at(c + 1, j + 1), at(c, j + 1)});
  }
  return m;
}

// Two 2 x 2 quad grids whose centres are one vertex (0): each sheet is a closed fan around it.
inline test::Mesh bow_tie() {
  test::Mesh m;
  m.add_vertex(0, 0, 0);
  for (int sheet = 0; sheet < 2; ++sheet) {
    std::vector<Index> id(9);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        if (i == 1 && j == 1) {
          id[4] = 0;
          continue;
        }
        const double x = i - 1.0, y = j - 1.0;
        id[size_t(3 * j + i)] = m.vertex_count;
        if (sheet == 0) m.add_vertex(x, y, 0.1 * x * y + 0.05 * x);
        else m.add_vertex(0.2 * x * y, x, y + 0.1 * x);
      }
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        m.add_face({id[size_t(3 * j + i)], id[size_t(3 * j + i + 1)], id[size_t(3 * j + i + 4)], id[size_t(3 * j + i + 3)]});
  }
  return m;
}

// A 3 x 2 quad grid whose right column runs its shared edge the same way as its neighbour.
inline test::Mesh flipped_face() {
  test::Mesh m;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) m.add_vertex(i, j, 0.1 * std::sin(1.3 * i + 0.7 * j));
  const auto at = [](int i, int j) { return Index(4 * j + i); };
  for (int j = 0; j < 2; ++j) {
    m.add_face({at(0, j), at(1, j), at(1, j + 1), at(0, j + 1)});
    m.add_face({at(1, j), at(2, j), at(2, j + 1), at(1, j + 1)});
    m.add_face({at(2, j + 1), at(3, j + 1), at(3, j), at(2, j)});  // clockwise
  }
  return m;
}

inline test::Mesh triangulated(const test::Mesh& q) {
  test::Mesh t;
  t.vertex_count = q.vertex_count;
  t.positions = q.positions;
  for (size_t f = 0; f + 1 < q.offsets.size(); ++f) {
    const Index* c = q.corners.data() + q.offsets[f];
    t.add_face({c[0], c[1], c[2]});
    t.add_face({c[0], c[2], c[3]});
  }
  return t;
}

}  // namespace subdiv::non_manifold_test
