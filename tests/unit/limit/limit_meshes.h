#pragma once
// Meshes for the limit tests.
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

}  // namespace subdiv::limit_test
