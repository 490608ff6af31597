#include <doctest/doctest.h>

#include "framework/refine/splitter.h"
#include "support/test_meshes.h"

using namespace subdiv;

TEST_CASE("quad split counts: V' = V+E+F, F' = corners, E' = 2E + corners; Euler kept") {
  for (const auto& mesh : {test::cube(), test::pyramid(), test::grid(3, 2), test::torus(5, 4)}) {
    Level L = mesh.level();
    for (int level = 0; level < 3; ++level) {
      SplitResult r = split_quad(L);
      CHECK(r.child.vertex_count == L.vertex_count + L.edge_count() + L.face_count());
      CHECK(r.child.face_count() == L.corner_count());
      CHECK(r.child.edge_count() == 2 * L.edge_count() + L.corner_count());
      CHECK(euler_characteristic(r.child) == euler_characteristic(L));
      CHECK(r.child.all_faces_have_size(4));
      CHECK(r.origins.kind[L.vertex_count] == OriginKind::Edge);
      CHECK(r.origins.kind.back() == OriginKind::Face);
      L = std::move(r.child);
    }
  }
}

TEST_CASE("triangle split counts: V' = V+E, F' = 4F, E' = 2E + 3F; Euler kept") {
  for (const auto& mesh : {test::octahedron(), test::grid(2, 3, true), test::torus(4, 5, true)}) {
    Level L = mesh.level();
    for (int level = 0; level < 3; ++level) {
      SplitResult r = split_triangle(L);
      CHECK(r.child.vertex_count == L.vertex_count + L.edge_count());
      CHECK(r.child.face_count() == 4 * L.face_count());
      CHECK(r.child.edge_count() == 2 * L.edge_count() + 3 * L.face_count());
      CHECK(euler_characteristic(r.child) == euler_characteristic(L));
      L = std::move(r.child);
    }
  }
}

TEST_CASE("boundary vertices stay on the boundary after splitting") {
  const Level L = test::grid(2, 2).level();
  const SplitResult r = split_quad(L);
  for (Index v = 0; v < L.vertex_count; ++v) CHECK(r.child.on_boundary(v) == L.on_boundary(v));
  for (Index e = 0; e < L.edge_count(); ++e)
    CHECK(r.child.on_boundary(L.vertex_count + e) == L.edge_on_boundary(e));
}
