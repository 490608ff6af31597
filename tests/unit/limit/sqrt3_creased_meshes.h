#pragma once
// Meshes with sharp and semi-sharp edges for the √3 limit tests.
#include <utility>

#include "framework/topology/level.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

namespace subdiv::limit_test::sqrt3 {

struct Tagged {
  test::Mesh mesh;
  Level level;
};

constexpr int kCreasedTorusSize = 8;

// A bumped regular (valence 6) torus with the row of edges (i, 2)-(i + 1, 2) at `sharpness`:
// a closed crease loop of regular crease vertices (two sharp edges straight across).
inline Tagged creased_torus(float sharpness) {
  const int n = kCreasedTorusSize;
  Tagged t{bumped(test::torus(n, n, true), 0.2), {}};
  t.level = t.mesh.level();
  t.level.edge_sharpness.assign(size_t(t.level.edge_count()), 0.f);
  for (int i = 0; i < n; ++i)
    t.level.edge_sharpness[size_t(find_edge(t.level, Index(2 * n + i), Index(2 * n + (i + 1) % n)))] = sharpness;
  return t;
}

// The bumped octahedron with its equator at `sharpness` (crease vertices of valence 4).
inline Tagged octahedron_with_equator(float sharpness) {
  Tagged t{bumped(octahedron()), {}};
  t.level = t.mesh.level();
  t.level.edge_sharpness.assign(size_t(t.level.edge_count()), 0.f);
  for (auto [a, b] : {std::pair<Index, Index>{0, 2}, {2, 1}, {1, 3}, {3, 0}})
    t.level.edge_sharpness[size_t(find_edge(t.level, a, b))] = sharpness;
  return t;
}

}  // namespace subdiv::limit_test::sqrt3
