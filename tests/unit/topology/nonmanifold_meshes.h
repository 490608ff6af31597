#pragma once
// Meshes OpenSubdiv accepts that are not manifold: fans of flaps on one edge, bow-ties,
// inconsistently oriented neighbours, a quad that repeats a vertex, and holes. Positions
// are perturbed (FeatureMesh::perturb) so that a wrong weight shows in the coordinates.
#include <algorithm>
#include <cmath>
#include <string>

#include "unit/features/feature_meshes.h"

namespace subdiv::nonmanifold_test {

using feature_test::FeatureMesh;

inline std::string fmt_name(int flaps, bool triangles) {
  return std::to_string(flaps) + (triangles ? " triangle flaps on one edge" : " quad flaps on one edge");
}

// `flaps` strips hinged on the edge (0, 1), every one a column of `depth` quads (or of
// 2 * depth triangles) going out from the hinge at its own angle: the hinge edge has
// `flaps` faces and its two ends are non-manifold.
inline FeatureMesh flap_fan(int flaps, bool triangles, int depth = 2) {
  FeatureMesh m{fmt_name(flaps, triangles), {}};
  m.add_vertex(0, 0, 0), m.add_vertex(0, 1, 0);
  for (int f = 0; f < flaps; ++f) {
    const double angle = 2.0 * M_PI * (f + 0.15 * f * f) / flaps;
    Index prev0 = 0, prev1 = 1;
    for (int d = 1; d <= depth; ++d) {
      const double r = d;
      const Index a = m.add_vertex(r * std::cos(angle), 0, r * std::sin(angle));
      const Index b = m.add_vertex(r * std::cos(angle), 1 + 0.1 * d, r * std::sin(angle));
      if (triangles) m.add_face({prev0, prev1, b}), m.add_face({prev0, b, a});
      else m.add_face({prev0, prev1, b, a});
      prev0 = a, prev1 = b;
    }
  }
  m.perturb(0.05);
  return m;
}

// Two open grids touching at one vertex: a bow-tie, whose shared vertex has two fans.
inline FeatureMesh bow_tie(bool triangles) {
  FeatureMesh m = feature_test::grid(2, 2, triangles);
  m.name = triangles ? "triangle bow-tie" : "quad bow-tie";
  const Index shared = feature_test::grid_id(2, 2, 2);  // the first grid's far corner
  const Index base = m.mesh.vertex_count();
  // The second grid, mirrored through the shared corner; its vertex (0, 0) is `shared`.
  auto id = [&](int i, int j) { return i == 0 && j == 0 ? shared : Index(base + j * 3 + i - 1); };
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i)
      if (i || j) m.add_vertex(2 + i, 2 + j, 0.2 * std::cos(1.1 * i + 0.4 * j));
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      if (triangles) m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)}), m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      else m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  m.perturb(0.03);
  return m;
}

// A grid with its middle face (or middle two triangles) written the other way round: its
// edges are run the same way by it and by its neighbours.
inline FeatureMesh flipped_face(bool triangles) {
  FeatureMesh m = feature_test::grid(3, 3, triangles);
  m.name = triangles ? "triangle grid with a flipped face" : "grid with a flipped face";
  const int k = triangles ? 3 : 4;
  const Index f = triangles ? 8 : 4;  // the middle cell
  std::reverse(m.mesh.face_vertices.begin() + f * k, m.mesh.face_vertices.begin() + (f + 1) * k);
  return m;
}

// A grid whose corner quad repeats its last vertex (a "quad pole": (a, b, c, c)).
inline FeatureMesh quad_pole() {
  FeatureMesh m = feature_test::grid(3, 3);
  m.name = "grid with a quad pole";
  // Cell (1, 1) becomes (v00, v10, v11, v11): its fourth corner collapses onto the third.
  Index* cell = m.mesh.face_vertices.data() + 4 * 4;
  cell[3] = cell[2];
  return m;
}

// A grid with faces of fewer than 3 distinct vertices, as in OpenSubdiv's regression shapes
// catmark_nonman_edges and loop_nonman_edges: one on an edge of the grid that repeats both
// its ends ((a, a, b, b), or (a, b, b) for triangles), one that is a single vertex four
// (three) times over. Far refines them; so does SubdivKit.
inline FeatureMesh collapsed_faces(bool triangles) {
  FeatureMesh m = feature_test::grid(3, 3, triangles);
  m.name = triangles ? "triangle grid with collapsed faces" : "grid with collapsed faces";
  const Index a = feature_test::grid_id(1, 1, 3), b = feature_test::grid_id(2, 1, 3), c = feature_test::grid_id(2, 2, 3);
  if (triangles) m.add_face({a, b, b}), m.add_face({c, c, c});
  else m.add_face({a, a, b, b}), m.add_face({c, c, c, c});
  return m;
}

}  // namespace subdiv::nonmanifold_test
