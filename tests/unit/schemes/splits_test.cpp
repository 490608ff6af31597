#include <doctest/doctest.h>

#include "support/refine_helpers.h"

using namespace subdiv;

namespace {

void check_manifold_counts(const Level& L, long euler) {
  CHECK(euler_characteristic(L) == euler);
  for (Index f = 0; f < L.face_count(); ++f) CHECK(L.face_size(f) >= 3);
}

int boundary_edge_count(const Level& L) {
  int n = 0;
  for (Index e = 0; e < L.edge_count(); ++e) n += L.edge_on_boundary(e);
  return n;
}

}  // namespace

TEST_CASE("sqrt3: faces x3 per step on closed meshes, Euler kept, two steps make 1-to-9") {
  const test::Mesh m = test::torus(6, 5, true);
  const auto r = test::refine_mesh(m, "sqrt3", 4);
  for (int l = 1; l <= 4; ++l) {
    const Level& L = r.hierarchy.levels[l];
    CHECK(L.face_count() == 3 * r.hierarchy.levels[l - 1].face_count());
    CHECK(L.vertex_count == r.hierarchy.levels[l - 1].vertex_count + r.hierarchy.levels[l - 1].face_count());
    CHECK(L.all_faces_have_size(3));
    check_manifold_counts(L, 0);
  }
  CHECK(r.hierarchy.levels[2].face_count() == 9 * m.level().face_count());
}

TEST_CASE("sqrt3 on an open grid: boundary kept in odd steps, trisected in even steps") {
  const test::Mesh m = test::grid(3, 3, true);
  const auto r = test::refine_mesh(m, "sqrt3", 2);
  const int b0 = boundary_edge_count(r.hierarchy.levels[0]);
  CHECK(boundary_edge_count(r.hierarchy.levels[1]) == b0);
  CHECK(boundary_edge_count(r.hierarchy.levels[2]) == 3 * b0);
  // Two steps are a 1-to-9 split everywhere, boundary triangles included (Kobbelt's
  // boundary rule: no face point beside a boundary edge in the trisecting step).
  CHECK(r.hierarchy.levels[2].face_count() == 9 * m.level().face_count());
  check_manifold_counts(r.hierarchy.levels[2], 1);
  // Odd step: boundary vertices stay.
  const auto& S = r.hierarchy.stencils[0];
  for (Index v = 0; v < m.vertex_count; ++v)
    if (m.level().on_boundary(v)) CHECK(test::weight_of(S, v, v) == 1.0);
}

TEST_CASE("sqrt3: refining one level twice equals two levels at once (step parity travels)") {
  const test::Mesh m = test::grid(3, 2, true);
  auto scheme = load_scheme("sqrt3");
  RefineOptions two;
  two.levels = 2;
  const Hierarchy at_once = refine(*scheme, m.level(), two);
  const auto expected = interpolate(at_once, 2, m.positions, 3);
  RefineOptions one;
  one.levels = 1;
  const Hierarchy first = refine(*scheme, m.level(), one);
  const auto middle = interpolate(first, 1, m.positions, 3);
  RefineOptions second = one;
  second.first_step = 1;
  Level mid = first.levels[1];
  const Hierarchy again = refine(*scheme, std::move(mid), second);
  const auto twice = interpolate(again, 1, middle, 3);
  REQUIRE(twice.size() == expected.size());
  for (size_t i = 0; i < twice.size(); ++i) CHECK(twice[i] == doctest::Approx(expected[i]).epsilon(1e-14));
}

TEST_CASE("dual split: V' = corners, F' = F + interior E + interior V; Euler kept") {
  for (const auto& m : {test::cube(), test::pyramid(), test::torus(4, 5)}) {
    const Level L = m.level();
    const auto r = test::refine_mesh(m, "doo-sabin", 1);
    const Level& C = r.hierarchy.levels[1];
    CHECK(C.vertex_count == L.corner_count());
    CHECK(C.face_count() == L.face_count() + L.edge_count() + L.vertex_count);
    check_manifold_counts(C, euler_characteristic(L));
    // Every vertex of a Doo-Sabin mesh has valence 4 (Doo & Sabin 1978).
    for (Index v = 0; v < C.vertex_count; ++v) CHECK(C.valence(v) == 4);
  }
}

TEST_CASE("dual split with boundaries: no E-faces on boundary edges, V-faces where three or more faces meet") {
  const test::Mesh m = test::grid(3, 2);
  const Level L = m.level();
  const auto r = test::refine_mesh(m, "doo-sabin", 2);
  const Level& C = r.hierarchy.levels[1];
  int interior_edges = 0, vertex_faces = 0;
  for (Index e = 0; e < L.edge_count(); ++e) interior_edges += !L.edge_on_boundary(e);
  for (Index v = 0; v < L.vertex_count; ++v) vertex_faces += L.incident_face_count(v) >= 3;
  CHECK(C.face_count() == L.face_count() + interior_edges + vertex_faces);
  check_manifold_counts(C, 1);
  check_manifold_counts(r.hierarchy.levels[2], 1);
}

TEST_CASE("mid-edge split: V' = E, F' = F + V on closed meshes; the cube becomes a cuboctahedron") {
  const test::Mesh m = test::cube();
  const auto r = test::refine_mesh(m, "mid-edge", 2);
  const Level& C = r.hierarchy.levels[1];
  CHECK(C.vertex_count == 12);
  CHECK(C.face_count() == 14);
  check_manifold_counts(C, 2);
  CHECK(r.hierarchy.levels[2].vertex_count == C.edge_count());
  // Every new point is an edge midpoint.
  const Level& L = r.hierarchy.levels[0];
  for (Index e = 0; e < L.edge_count(); ++e) {
    CHECK(test::weight_of(r.hierarchy.stencils[0], e, L.edge_vertices[2 * e]) == 0.5);
    CHECK(test::weight_of(r.hierarchy.stencils[0], e, L.edge_vertices[2 * e + 1]) == 0.5);
  }
}

TEST_CASE("sqrt3 keeps one-face boundary corners fixed at every level (edges-and-corners)") {
  const test::Mesh m = test::grid(4, 3, true);
  const Level L = m.level();
  const auto r = test::refine_mesh(m, "sqrt3", 4);
  for (Index v = 0; v < m.vertex_count; ++v) {
    if (!L.on_boundary(v) || L.incident_face_count(v) != 1) continue;
    for (int i = 0; i < 3; ++i) CHECK(r.positions[3 * v + i] == m.positions[3 * v + i]);
  }
}
