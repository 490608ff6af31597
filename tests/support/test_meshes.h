#pragma once
// Small meshes built in code for tests: each with known counts and topology.
#include <cmath>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv::test {

struct Mesh {
  Index vertex_count = 0;
  std::vector<Index> offsets{0};
  std::vector<Index> corners;
  std::vector<double> positions;  // xyz

  void add_face(std::initializer_list<Index> vs) {
    corners.insert(corners.end(), vs.begin(), vs.end());
    offsets.push_back(Index(corners.size()));
  }
  void add_vertex(double x, double y, double z) {
    positions.push_back(x);  // not insert({x, y, z}): GCC 12 -O3 warns falsely (-Wstringop-overflow)
    positions.push_back(y);
    positions.push_back(z);
    ++vertex_count;
  }
  Level level() const { return build_level(vertex_count, offsets, corners); }
};

inline Mesh cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  // Outward-facing CCW quads.
  m.add_face({0, 2, 3, 1});
  m.add_face({4, 5, 7, 6});
  m.add_face({0, 1, 5, 4});
  m.add_face({2, 6, 7, 3});
  m.add_face({0, 4, 6, 2});
  m.add_face({1, 3, 7, 5});
  return m;
}

// An open (nx x ny)-quad grid in the plane z = 0, vertex (i, j) = j * (nx + 1) + i.
inline Mesh grid(int nx, int ny, bool triangles = false) {
  Mesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.add_vertex(i, j, 0);
  auto id = [&](int i, int j) { return Index(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (triangles) {
        m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  return m;
}

// A closed regular (nu x nv)-quad torus; with `triangles`, each quad split on a diagonal,
// giving a regular (valence 6) triangle mesh.
inline Mesh torus(int nu, int nv, bool triangles = false, double R = 3.0, double r = 1.0) {
  Mesh m;
  const double pi = std::acos(-1.0);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      m.add_vertex((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto id = [&](int i, int j) { return Index(((j + nv) % nv) * nu + (i + nu) % nu); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (triangles) {
        m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  return m;
}

// A double cone over a regular n-gon: apex n has valence n, apex n+1 too, the equator
// vertices valence 4. Closed triangle mesh.
inline Mesh bipyramid(int n) {
  Mesh m;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) m.add_vertex(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), 0);
  m.add_vertex(0, 0, 1), m.add_vertex(0, 0, -1);
  for (int i = 0; i < n; ++i) {
    m.add_face({Index(i), Index((i + 1) % n), Index(n)});
    m.add_face({Index((i + 1) % n), Index(i), Index(n + 1)});
  }
  return m;
}

inline Mesh octahedron() {
  Mesh m;
  m.add_vertex(1, 0, 0), m.add_vertex(-1, 0, 0), m.add_vertex(0, 1, 0);
  m.add_vertex(0, -1, 0), m.add_vertex(0, 0, 1), m.add_vertex(0, 0, -1);
  m.add_face({0, 2, 4}), m.add_face({2, 1, 4}), m.add_face({1, 3, 4}), m.add_face({3, 0, 4});
  m.add_face({2, 0, 5}), m.add_face({1, 2, 5}), m.add_face({3, 1, 5}), m.add_face({0, 3, 5});
  return m;
}

// A square pyramid: a quad base and four triangles (mixed polygons, valence 4 apex,
// valence 3 base corners).
inline Mesh pyramid() {
  Mesh m;
  m.add_vertex(0, 0, 0), m.add_vertex(1, 0, 0), m.add_vertex(1, 1, 0), m.add_vertex(0, 1, 0);
  m.add_vertex(0.5, 0.5, 1);
  m.add_face({0, 3, 2, 1});
  m.add_face({0, 1, 4}), m.add_face({1, 2, 4}), m.add_face({2, 3, 4}), m.add_face({3, 0, 4});
  return m;
}

}  // namespace subdiv::test
