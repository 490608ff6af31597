#pragma once
// Test meshes with sharp features, shared by the OpenSubdiv agreement tests and the
// closed-form feature tests. Positions are perturbed off their regular layout so that
// every rule moves points and a wrong weight shows up in the coordinates.
#include <cmath>
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"

namespace subdiv::feature_test {

struct FeatureMesh {
  std::string name;
  MeshData mesh;

  Index add_vertex(double x, double y, double z) {
    mesh.positions.insert(mesh.positions.end(), {x, y, z});
    return mesh.vertex_count() - 1;
  }
  void add_face(std::initializer_list<Index> vs) {
    mesh.face_vertices.insert(mesh.face_vertices.end(), vs.begin(), vs.end());
    mesh.face_offsets.push_back(Index(mesh.face_vertices.size()));
  }
  void crease(Index a, Index b, double s) { mesh.creases.push_back({a, b, s}); }
  // A crease along consecutive vertices of a path, one tag per edge.
  void crease_path(const std::vector<Index>& path, double s) {
    for (size_t i = 0; i + 1 < path.size(); ++i) crease(path[i], path[i + 1], s);
  }
  void corner(Index v, double s) { mesh.corners.push_back({v, s}); }
  // Deterministic bumps so no coordinate is on a lattice.
  void perturb(double amount) {
    for (size_t i = 0; i < mesh.positions.size(); ++i)
      mesh.positions[i] += amount * std::sin(12.9898 * double(i) + 78.233 * double(i % 7));
  }
};

// A closed cube [-1, 1]^3 with outward CCW quads; vertex i has coordinates from its bits.
inline FeatureMesh cube() {
  FeatureMesh m{"cube", {}};
  for (int i = 0; i < 8; ++i) m.add_vertex(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  m.add_face({0, 2, 3, 1});
  m.add_face({4, 5, 7, 6});
  m.add_face({0, 1, 5, 4});
  m.add_face({2, 6, 7, 3});
  m.add_face({0, 4, 6, 2});
  m.add_face({1, 3, 7, 5});
  m.perturb(0.05);
  return m;
}

// An open nx x ny grid of quads (or split into triangles) in the plane, with a wavy height.
// Vertex (i, j) is j * (nx + 1) + i.
inline FeatureMesh grid(int nx, int ny, bool triangles = false) {
  FeatureMesh m{triangles ? "triangle grid" : "grid", {}};
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.add_vertex(i, j, 0.3 * std::sin(1.3 * i + 0.7 * j) + 0.1 * i * j / (nx * ny));
  auto id = [&](int i, int j) { return Index(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (triangles) {
        // Alternate the diagonal so vertex valences vary (4, 5, 6, 7, 8).
        if ((i + j) % 2 == 0) {
          m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
          m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        } else {
          m.add_face({id(i, j), id(i + 1, j), id(i, j + 1)});
          m.add_face({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
      } else {
        m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  m.perturb(0.04);
  return m;
}
inline Index grid_id(int i, int j, int nx) { return Index(j * (nx + 1) + i); }

// A closed nu x nv torus of quads (or triangles); vertex (i, j) is j * nu + i, i around
// the main axis, j around the tube.
inline FeatureMesh torus(int nu, int nv, bool triangles = false) {
  FeatureMesh m{triangles ? "triangle torus" : "torus", {}};
  const double pi = std::acos(-1.0);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      m.add_vertex((3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v));
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
  m.perturb(0.05);
  return m;
}
inline Index torus_id(int i, int j, int nu) { return Index(j * nu + i); }

// A closed octahedron (Loop), valence 4 everywhere.
inline FeatureMesh octahedron() {
  FeatureMesh m{"octahedron", {}};
  m.add_vertex(1, 0, 0), m.add_vertex(-1, 0, 0), m.add_vertex(0, 1, 0);
  m.add_vertex(0, -1, 0), m.add_vertex(0, 0, 1), m.add_vertex(0, 0, -1);
  m.add_face({0, 2, 4}), m.add_face({2, 1, 4}), m.add_face({1, 3, 4}), m.add_face({3, 0, 4});
  m.add_face({2, 0, 5}), m.add_face({1, 2, 5}), m.add_face({3, 1, 5}), m.add_face({0, 3, 5});
  m.perturb(0.05);
  return m;
}

// An open fan of n quads around one interior vertex 0 (an extraordinary valence-n vertex
// with a boundary ring): rim vertices 1..2n alternate edge and corner vertices.
inline FeatureMesh fan(int n) {
  FeatureMesh m{"fan" + std::to_string(n), {}};
  const double pi = std::acos(-1.0);
  m.add_vertex(0, 0, 0.5);
  for (int k = 0; k < 2 * n; ++k) {
    const double a = pi * k / n, r = k % 2 ? 1.6 : 1.0;
    m.add_vertex(r * std::cos(a), r * std::sin(a), 0.1 * k);
  }
  for (int k = 0; k < n; ++k) {
    const Index e0 = Index(1 + 2 * k), c = Index(2 + 2 * k), e1 = Index(1 + (2 * k + 2) % (2 * n));
    m.add_face({0, e0, c, e1});
  }
  m.perturb(0.03);
  return m;
}

}  // namespace subdiv::feature_test
