#include <doctest/doctest.h>

#include "support/refine_helpers.h"

using namespace subdiv;
using test::weight_of;

namespace {
Index gid(int i, int j, int nx) { return Index(j * (nx + 1) + i); }
}  // namespace

TEST_CASE("boundaries follow the cubic B-spline: vertex 1/8, 3/4, 1/8; edge 1/2, 1/2; corners stay") {
  for (const std::string scheme : {"catmull-clark", "loop"}) {
    const bool tri = scheme == "loop";
    const auto r = test::refine_mesh(test::grid(4, 3, tri), scheme, 1);
    const auto& t = r.hierarchy.stencils[0];
    const Level& L = r.hierarchy.levels[0];
    const Index b = gid(2, 0, 4);  // on the bottom boundary
    CHECK(t.row_size(b) == 3);
    CHECK(weight_of(t, b, b) == doctest::Approx(3.0 / 4));
    CHECK(weight_of(t, b, gid(1, 0, 4)) == doctest::Approx(1.0 / 8));
    CHECK(weight_of(t, b, gid(3, 0, 4)) == doctest::Approx(1.0 / 8));
    const Index e = find_edge(L, gid(2, 0, 4), gid(3, 0, 4));
    CHECK(t.row_size(L.vertex_count + e) == 2);
    CHECK(weight_of(t, L.vertex_count + e, gid(3, 0, 4)) == doctest::Approx(0.5));
    // (4, 0) has one incident face in both meshes: a corner that stays.
    const Index corner = gid(4, 0, 4);
    REQUIRE(L.incident_face_count(corner) == 1);
    CHECK(t.row_size(corner) == 1);
    CHECK(weight_of(t, corner, corner) == 1.0);
  }
}

TEST_CASE("--boundary edges: one-face boundary corners follow the curve rule") {
  RefineOptions options;
  options.features.boundary = BoundaryInterpolation::EdgesOnly;
  const auto r = test::refine_mesh(test::grid(2, 2), "catmull-clark", 1, options);
  const auto& t = r.hierarchy.stencils[0];
  const Index corner = gid(0, 0, 2);
  CHECK(weight_of(t, corner, corner) == doctest::Approx(3.0 / 4));
  CHECK(weight_of(t, corner, gid(1, 0, 2)) == doctest::Approx(1.0 / 8));
  CHECK(weight_of(t, corner, gid(0, 1, 2)) == doctest::Approx(1.0 / 8));
}

TEST_CASE("a straight boundary stays straight and its points follow cubic B-spline refinement") {
  // Boundary points of a refined grid are the cubic B-spline refinement of the boundary
  // polygon, independent of the interior: move interior points off the plane and check.
  test::Mesh m = test::grid(4, 4);
  for (int j = 1; j < 4; ++j)
    for (int i = 1; i < 4; ++i) m.positions[3 * gid(i, j, 4) + 2] = 0.3 * i - 0.2 * j;
  const auto r = test::refine_mesh(m, "catmull-clark", 3);
  const Level& fine = r.hierarchy.levels.back();
  for (Index v = 0; v < fine.vertex_count; ++v)
    if (fine.on_boundary(v)) CHECK(r.positions[3 * v + 2] == doctest::Approx(0.0).epsilon(1e-15));
}

TEST_CASE("bilinear and midpoint keep old vertices and put new ones at midpoints") {
  const auto q = test::refine_mesh(test::pyramid(), "bilinear", 1);
  const auto t = test::refine_mesh(test::octahedron(), "midpoint", 1);
  for (const auto* r : {&q, &t}) {
    const Level& L = r->hierarchy.levels[0];
    const auto& S = r->hierarchy.stencils[0];
    for (Index v = 0; v < L.vertex_count; ++v) CHECK(weight_of(S, v, v) == 1.0);
    for (Index e = 0; e < L.edge_count(); ++e) CHECK(weight_of(S, L.vertex_count + e, L.edge_vertices[2 * e]) == 0.5);
  }
}
