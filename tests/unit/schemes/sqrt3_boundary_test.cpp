// sqrt(3) on meshes with boundaries (Kobbelt 2000, section 5): boundaries are kept in odd
// steps and trisected in even steps with the ternary cubic B-spline, the triangle beside a
// boundary edge gets no face point in an even step, so two steps make a 1-to-9 split
// everywhere. Every expectation below is a closed form, not a recorded output.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "support/refine_helpers.h"

using namespace subdiv;

namespace {

// An open annulus: nu x nv quads around a ring, each split on a diagonal. Both boundary
// loops are smooth (no corners) and every boundary vertex has 3 faces (regular, valence 4).
// Positions are perturbed so that no symmetry hides a wrong weight.
test::Mesh annulus(int nu, int nv) {
  test::Mesh m;
  const double pi = std::acos(-1.0);
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double t = 2 * pi * i / nu, r = 1.0 + 0.5 * j + 0.07 * std::sin(3.0 * i + j);
      m.add_vertex(r * std::cos(t), r * std::sin(t), 0.1 * std::cos(2.0 * i - j));
    }
  auto id = [&](int i, int j) { return Index(j * nu + (i + nu) % nu); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

int boundary_edges(const Level& L) {
  int n = 0;
  for (Index e = 0; e < L.edge_count(); ++e) n += L.edge_on_boundary(e);
  return n;
}

// next[a] = b for every boundary edge a -> b, in the direction its face runs it.
std::map<Index, Index> boundary_successor(const Level& L) {
  std::map<Index, Index> next;
  for (Index e = 0; e < L.edge_count(); ++e)
    if (L.edge_on_boundary(e)) next[L.edge_vertices[2 * e]] = L.edge_vertices[2 * e + 1];
  return next;
}

long ipow3(int e) {
  long p = 1;
  while (e-- > 0) p *= 3;
  return p;
}

std::vector<double> refine_positions(const test::Mesh& m, const std::vector<double>& positions, int levels) {
  auto scheme = load_scheme("sqrt3");
  RefineOptions o;
  o.levels = levels;
  const Hierarchy h = refine(*scheme, m.level(), o);
  return interpolate(h, levels, positions, 3);
}

}  // namespace

TEST_CASE("sqrt3 with boundaries: F = 3^l F0, B = 3^floor(l/2) B0, V = chi + (F + B)/2, Euler kept") {
  // Every triangle has three edge sides and every step makes one triangle per side (odd
  // steps: a flipped edge's two triangles, or the kept boundary triangle; even steps: the
  // middle triangle of a boundary triangle replaces its boundary side), so F' = 3F. From
  // 3F = 2E - B and V - E + F = chi: V = chi + (F + B)/2.
  for (const test::Mesh& m : {test::grid(4, 3, true), annulus(7, 2), test::grid(1, 1, true)}) {
    const Level base = m.level();
    const long chi = euler_characteristic(base);
    const auto r = test::refine_mesh(m, "sqrt3", 4);
    const long F0 = base.face_count(), B0 = boundary_edges(base);
    for (int l = 0; l <= 4; ++l) {
      const Level& L = r.hierarchy.levels[l];
      CAPTURE(l);
      CHECK(L.face_count() == ipow3(l) * F0);
      CHECK(boundary_edges(L) == ipow3(l / 2) * B0);
      CHECK(2 * (L.vertex_count - chi) == L.face_count() + boundary_edges(L));
      CHECK(euler_characteristic(L) == chi);
      CHECK(L.all_faces_have_size(3));
    }
    // Two steps are a 1-to-9 split: V2 = V0 + 2E0 + F0 (two points per edge, one per face).
    CHECK(r.hierarchy.levels[2].vertex_count == base.vertex_count + 2 * base.edge_count() + base.face_count());
  }
}

TEST_CASE("sqrt3 boundary valences: +1 face in odd steps, back in even steps; new boundary vertices regular") {
  for (const test::Mesh& m : {test::grid(4, 3, true), annulus(6, 2)}) {
    const auto r = test::refine_mesh(m, "sqrt3", 4);
    const auto& levels = r.hierarchy.levels;
    int max0 = 0;
    for (Index v = 0; v < levels[0].vertex_count; ++v)
      if (levels[0].on_boundary(v)) max0 = std::max(max0, levels[0].valence(v));
    for (int l = 0; l + 1 <= 4; ++l) {
      const Level &P = levels[l], &C = levels[l + 1];
      const bool odd_step = l % 2 == 0;  // step index l counted from 0: the 1st, 3rd, ... steps
      for (Index v = 0; v < P.vertex_count; ++v) {
        if (!P.on_boundary(v)) continue;
        CAPTURE(l);
        CAPTURE(v);
        REQUIRE(C.on_boundary(v));  // child v is parent v
        CHECK(C.incident_face_count(v) == P.incident_face_count(v) + (odd_step ? 1 : -1));
      }
      // The trisection points of an even step: three faces, valence 4 (regular).
      if (!odd_step)
        for (Index v = P.vertex_count; v < C.vertex_count; ++v)
          if (C.on_boundary(v)) CHECK(C.incident_face_count(v) == 3);
      // Bounded: no boundary vertex ever exceeds max(base, 4) + 1.
      for (Index v = 0; v < C.vertex_count; ++v)
        if (C.on_boundary(v)) CHECK(C.valence(v) <= std::max(max0, 4) + (l % 2 == 0 ? 1 : 0));
    }
  }
}

TEST_CASE("sqrt3 boundary curve: odd steps keep it, even steps apply the ternary cubic B-spline") {
  // The ternary cubic B-spline has the symbol (1 + z + z^2)^4 / 27: around old point P_i the
  // new points are (4, 19, 4)/27 (at P_i), (1, 16, 10)/27 (1/3 towards P_{i+1}) and
  // (10, 16, 1)/27 over P_i, P_{i+1}, P_{i+2} (2/3 towards P_{i+1}).
  const test::Mesh m = annulus(9, 2);
  const auto r = test::refine_mesh(m, "sqrt3", 4);
  const auto& levels = r.hierarchy.levels;
  std::vector<std::vector<double>> P(5);
  P[0] = m.positions;
  for (int l = 1; l <= 4; ++l) P[l] = interpolate(r.hierarchy, l, m.positions, 3);
  for (int l : {0, 2}) {
    const Level &A = levels[l], &C = levels[l + 2];
    const auto next = boundary_successor(A), next2 = boundary_successor(C);
    // The odd step leaves every boundary vertex where it was.
    for (const auto& [v, w] : next)
      for (int c = 0; c < 3; ++c) CHECK(P[l + 1][3 * v + c] == P[l][3 * v + c]);
    for (const auto& [v, v_next] : next) {
      Index v_prev = kNone;
      for (const auto& [a, b] : next)
        if (b == v) v_prev = a;
      REQUIRE(v_prev != kNone);
      const Index v_next2 = next.at(v_next);
      // Level l+2 along the boundary: v, q1, q2, v_next.
      const Index q1 = next2.at(v), q2 = next2.at(q1);
      CHECK(next2.at(q2) == v_next);
      for (int c = 0; c < 3; ++c) {
        auto p = [&](Index i) { return P[l][3 * i + c]; };
        CAPTURE(l);
        CHECK(P[l + 2][3 * v + c] == doctest::Approx((4 * p(v_prev) + 19 * p(v) + 4 * p(v_next)) / 27).epsilon(1e-13));
        CHECK(P[l + 2][3 * q1 + c] == doctest::Approx((p(v_prev) + 16 * p(v) + 10 * p(v_next)) / 27).epsilon(1e-13));
        CHECK(P[l + 2][3 * q2 + c] == doctest::Approx((10 * p(v) + 16 * p(v_next) + p(v_next2)) / 27).epsilon(1e-13));
      }
    }
  }
}

TEST_CASE("sqrt3 boundary points depend only on boundary points") {
  for (const test::Mesh& m : {test::grid(4, 3, true), annulus(8, 3)}) {
    const auto r = test::refine_mesh(m, "sqrt3", 4);
    // Every stencil row of a boundary child uses parent boundary vertices only.
    for (int l = 0; l < 4; ++l) {
      const Level &P = r.hierarchy.levels[l], &C = r.hierarchy.levels[l + 1];
      const StencilTable& S = r.hierarchy.stencils[l];
      for (Index v = 0; v < C.vertex_count; ++v) {
        if (!C.on_boundary(v)) continue;
        for (Index i = S.offsets[v]; i < S.offsets[v + 1]; ++i)
          if (S.weights[i] != 0.0) CHECK(P.on_boundary(S.indices[i]));
      }
    }
    // So moving the interior control points leaves the refined boundary exactly in place.
    const Level base = m.level();
    std::vector<double> moved = m.positions;
    for (Index v = 0; v < base.vertex_count; ++v)
      if (!base.on_boundary(v))
        for (int c = 0; c < 3; ++c) moved[3 * v + c] += 0.25 + 0.1 * c;
    const auto fine = refine_positions(m, moved, 4);
    const Level& L4 = r.hierarchy.levels[4];
    for (Index v = 0; v < L4.vertex_count; ++v)
      if (L4.on_boundary(v))
        for (int c = 0; c < 3; ++c) CHECK(fine[3 * v + c] == r.positions[3 * v + c]);
  }
}

TEST_CASE("sqrt3 with boundaries: 1+1+1+1 levels and 1+3 levels equal 4 levels at once") {
  auto scheme = load_scheme("sqrt3");
  for (const test::Mesh& m : {test::grid(3, 2, true), annulus(6, 2)}) {
    RefineOptions all;
    all.levels = 4;
    const Hierarchy at_once = refine(*scheme, m.level(), all);
    const auto expected = interpolate(at_once, 4, m.positions, 3);
    for (const std::vector<int>& split : {std::vector<int>{1, 1, 1, 1}, std::vector<int>{1, 3}, std::vector<int>{2, 2}}) {
      Level level = m.level();
      std::vector<double> positions = m.positions;
      int done = 0;
      for (int levels : split) {
        RefineOptions o;
        o.levels = levels;
        o.first_step = done;
        const Hierarchy h = refine(*scheme, std::move(level), o);
        positions = interpolate(h, levels, positions, 3);
        level = h.levels.back();
        done += levels;
      }
      REQUIRE(level.vertex_count == at_once.levels[4].vertex_count);
      CHECK(level.face_vertices == at_once.levels[4].face_vertices);
      REQUIRE(positions.size() == expected.size());
      for (size_t i = 0; i < positions.size(); ++i) CHECK(positions[i] == doctest::Approx(expected[i]).epsilon(1e-13));
    }
  }
}

TEST_CASE("sqrt3 with an infinitely sharp crease: sides refined like boundaries, F = 3^l F0, crease x3 per two steps") {
  // The octahedron's equator as a crease: each side of a sharp edge is treated as a
  // boundary side (kept in odd steps, trisected without a face point in even ones).
  const test::Mesh m = test::octahedron();
  Level base = m.level();
  base.edge_sharpness.assign(base.edge_count(), 0.f);
  for (auto [a, b] : {std::pair<Index, Index>{0, 2}, {2, 1}, {1, 3}, {3, 0}}) base.edge_sharpness[find_edge(base, a, b)] = 10.f;
  auto scheme = load_scheme("sqrt3");
  RefineOptions o;
  o.levels = 4;
  const Hierarchy h = refine(*scheme, base, o);
  for (int l = 0; l <= 4; ++l) {
    const Level& L = h.levels[l];
    long sharp = 0;
    for (Index e = 0; e < L.edge_count(); ++e) sharp += L.edge_sharp(e) > 0.f;
    CAPTURE(l);
    CHECK(L.face_count() == ipow3(l) * 8);
    CHECK(sharp == ipow3(l / 2) * 4);
    CHECK(2 * (L.vertex_count - 2) == L.face_count());  // closed: 3F = 2E, so V = chi + F/2
    CHECK(euler_characteristic(L) == 2);
    // Crease vertices gain a face per side in odd steps and lose it in even ones: the
    // equator's vertices have 4 faces at even levels, the trisection points 6 (3 per side).
    for (Index v = 0; v < L.vertex_count; ++v) {
      int sharp_edges = 0;
      for (Index e : L.ring_edges(v)) sharp_edges += L.edge_sharp(e) > 0.f;
      if (sharp_edges == 2) CHECK(L.incident_face_count(v) == (v < 6 ? 4 : 6) + 2 * (l % 2));
    }
  }
}

TEST_CASE("sqrt3 trisecting step on a triangle with three boundary edges keeps its face point") {
  // A lone triangle refined as if it were an even step (first_step = 1): it has three
  // feature edges, so it keeps its face point, fanned to the 3 corners and 6 trisection
  // points: 9 triangles, 3 + 1 + 6 vertices, Euler 1.
  const test::Mesh m = test::grid(1, 1, true);
  test::Mesh tri;
  for (int i = 0; i < 3; ++i) tri.add_vertex(m.positions[3 * i], m.positions[3 * i + 1], 0);
  tri.add_face({0, 1, 2});
  RefineOptions o;
  o.levels = 1;
  o.first_step = 1;
  const Hierarchy h = refine(*load_scheme("sqrt3"), tri.level(), o);
  const Level& C = h.levels[1];
  CHECK(C.face_count() == 9);
  CHECK(C.vertex_count == 10);
  CHECK(euler_characteristic(C) == 1);
  CHECK(boundary_edges(C) == 9);
}
