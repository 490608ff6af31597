// quad-bspline of even degree d (Lane-Riesenfeld on quads): the dual step "bilinear split +
// one centroid pass A", then (d-2)/2 vertex-averaging passes (A twice). The expectations are
// closed forms: the tensor product of the degree-d B-spline's subdivision mask
// 2^-d C(d+1, i), Euler's formula and the counts of the dual split.
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;

namespace {

using Params = ParameterOverrides;

std::array<double, 3> point(const std::vector<double>& P, Index v) { return {P[3 * v], P[3 * v + 1], P[3 * v + 2]}; }

// The 3 x 3 grid around corner (f, c) of a closed all-quad mesh whose vertices all have
// valence 4: g[a+1][b+1] is the vertex a steps along the face's edge leaving the corner's
// vertex (towards the face for a = 1) and b steps along the edge arriving at it.
std::array<std::array<Index, 3>, 3> corner_grid(const Level& L, Index f, int c) {
  const Index v = L.face(f)[c];
  REQUIRE(L.valence(v) == 4);
  REQUIRE(!L.on_boundary(v));
  std::array<Index, 4> ring{}, diagonal{};
  int at = -1;
  for (int i = 0; i < 4; ++i) {
    const Index g = L.vertex_face_offsets[v] + i;
    const Index face = L.vertex_faces[g];
    const int corner = L.vertex_face_corner[g];
    REQUIRE(L.face_size(face) == 4);
    ring[i] = L.face(face)[(corner + 1) % 4];  // ring edge i leaves v along face i
    diagonal[i] = L.face(face)[(corner + 2) % 4];
    if (face == f && corner == c) at = i;
  }
  REQUIRE(at >= 0);
  auto r = [&](int i) { return ring[(at + i) % 4]; };
  auto d = [&](int i) { return diagonal[(at + i) % 4]; };
  CHECK(r(1) == L.face(f)[(c + 3) % 4]);  // the arriving edge's other end
  std::array<std::array<Index, 3>, 3> g{};
  g[1][1] = v;
  g[2][1] = r(0), g[1][2] = r(1), g[0][1] = r(2), g[1][0] = r(3);
  g[2][2] = d(0), g[0][2] = d(1), g[0][0] = d(2), g[2][0] = d(3);
  return g;
}

// Every new point of one level is the tensor product of the 1-D weights w[-1..1] over the
// corner's 3 x 3 grid (w[a] for the step along the leaving edge, w[b] along the arriving one).
void check_tensor_level(const Level& L, const std::vector<double>& coarse, const std::vector<double>& fine,
                        const std::array<double, 3>& w) {
  REQUIRE(fine.size() == 3 * size_t(L.corner_count()));
  for (Index f = 0; f < L.face_count(); ++f)
    for (int c = 0; c < 4; ++c) {
      const auto g = corner_grid(L, f, c);
      std::array<double, 3> expected{0, 0, 0};
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          const auto p = point(coarse, g[a][b]);
          for (int x = 0; x < 3; ++x) expected[x] += w[a] * w[b] * p[x];
        }
      const auto got = point(fine, L.face_offsets[f] + c);  // dual split: child = parent corner
      for (int x = 0; x < 3; ++x) CHECK(std::abs(got[x] - expected[x]) <= 1e-12);
    }
}

}  // namespace

TEST_CASE("quad-bspline d=2 on a regular torus is the biquadratic B-spline: (9, 3, 3, 1)/16 per corner") {
  // The biquadratic B-spline's refinement is Chaikin (3/4, 1/4) in each direction: the
  // tensor product gives 9/16 on the corner's vertex, 3/16 on its two face neighbours and
  // 1/16 on the opposite vertex. No weight lies behind the corner: w[-1] = 0.
  const test::Mesh m = test::torus(6, 5);
  const auto r = test::refine_mesh(m, "quad-bspline", 2, {}, Params{{"d", "2"}});
  const auto P1 = interpolate(r.hierarchy, 1, m.positions, 3);
  check_tensor_level(r.hierarchy.levels[0], m.positions, P1, {0.0, 3.0 / 4, 1.0 / 4});
  check_tensor_level(r.hierarchy.levels[1], P1, r.positions, {0.0, 3.0 / 4, 1.0 / 4});
}

TEST_CASE("quad-bspline d=4 on a regular torus is the quartic B-spline tensor product") {
  // Degree-4 Lane-Riesenfeld mask 2^-4 C(5, i) = (1, 5, 10, 10, 5, 1)/16: new point 2i gets
  // (1, 10, 5)/16 from P(i-1), P(i), P(i+1), new point 2i+1 gets (5, 10, 1)/16 from P(i),
  // P(i+1), P(i+2). The corner of a face at P(i) on the face's side is point 2i: weight 5/16
  // towards the face, 10/16 on the vertex, 1/16 behind it, in each direction.
  const test::Mesh m = test::torus(7, 6);
  const auto r = test::refine_mesh(m, "quad-bspline", 2, {}, Params{{"d", "4"}});
  const auto P1 = interpolate(r.hierarchy, 1, m.positions, 3);
  check_tensor_level(r.hierarchy.levels[0], m.positions, P1, {1.0 / 16, 10.0 / 16, 5.0 / 16});
  check_tensor_level(r.hierarchy.levels[1], P1, r.positions, {1.0 / 16, 10.0 / 16, 5.0 / 16});
}

TEST_CASE("quad-bspline even d: the dual step is the bilinear split followed by one centroid pass") {
  // A on the bilinear split: the child face (v, (v+e1)/2, c, (v+e0)/2) has centroid
  // v/2 + e1/8 + e0/8 + c/4, for any polygon. Checked against a bilinear refinement of the
  // pyramid (triangles and a quad, valence 3 and 4) and the cube.
  for (const test::Mesh& m : {test::pyramid(), test::cube()}) {
    const Level L = m.level();
    const auto bilinear = test::refine_mesh(m, "bilinear", 1);
    const Level& B = bilinear.hierarchy.levels[1];
    const auto even = test::refine_mesh(m, "quad-bspline", 1, {}, Params{{"d", "2"}});
    for (Index f = 0; f < L.face_count(); ++f)
      for (int c = 0; c < L.face_size(f); ++c) {
        const Index corner = L.face_offsets[f] + c;  // bilinear: child face = parent corner
        std::array<double, 3> centroid{0, 0, 0};
        for (Index u : B.face(corner))
          for (int x = 0; x < 3; ++x) centroid[x] += bilinear.positions[3 * u + x] / B.face_size(corner);
        const int k = L.face_size(f);
        std::array<double, 3> formula{0, 0, 0};
        for (int i = 0; i < k; ++i) {
          const double w = (i == 0 ? 0.5 : (i == 1 || i == k - 1) ? 0.125 : 0.0) + 0.25 / k;
          for (int x = 0; x < 3; ++x) formula[x] += w * m.positions[3 * L.face(f)[(c + i) % k] + x];
        }
        for (int x = 0; x < 3; ++x) {
          CHECK(even.positions[3 * corner + x] == doctest::Approx(centroid[x]).epsilon(1e-14));
          CHECK(even.positions[3 * corner + x] == doctest::Approx(formula[x]).epsilon(1e-14));
        }
      }
  }
}

TEST_CASE("quad-bspline: A twice is the vertex-averaging pass (d and d+2 differ by one pass)") {
  // On the d-level mesh, one more A-pair moves each vertex to the mean of the centroids of
  // its faces; with d = 2 -> 4 and 3 -> 5 on closed meshes of any valence.
  for (const test::Mesh& m : {test::cube(), test::pyramid()})
    for (int d : {2, 3}) {
      const auto lo = test::refine_mesh(m, "quad-bspline", 1, {}, Params{{"d", std::to_string(d)}});
      const auto hi = test::refine_mesh(m, "quad-bspline", 1, {}, Params{{"d", std::to_string(d + 2)}});
      const Level& C = lo.hierarchy.levels[1];
      REQUIRE(hi.hierarchy.levels[1].face_vertices == C.face_vertices);
      for (Index v = 0; v < C.vertex_count; ++v) {
        std::array<double, 3> mean{0, 0, 0};
        for (Index f : C.ring_faces(v))
          for (Index u : C.face(f))
            for (int x = 0; x < 3; ++x)
              mean[x] += lo.positions[3 * u + x] / (C.face_size(f) * double(C.incident_face_count(v)));
        for (int x = 0; x < 3; ++x) CHECK(hi.positions[3 * v + x] == doctest::Approx(mean[x]).epsilon(1e-13));
      }
    }
}

TEST_CASE("quad-bspline even d: counts of the dual split per level, Euler kept, valence 4") {
  // Dual split: V' = corners, F' = F + (interior edges) + (vertices with >= 3 faces); the
  // passes keep the topology. On a closed mesh every new vertex has valence 4.
  for (int d : {2, 4, 6})
    for (const test::Mesh& m : {test::cube(), test::pyramid(), test::torus(4, 3), test::grid(3, 2)}) {
      const auto r = test::refine_mesh(m, "quad-bspline", 3, {}, Params{{"d", std::to_string(d)}});
      const long chi = euler_characteristic(r.hierarchy.levels[0]);
      for (int l = 0; l < 3; ++l) {
        const Level &P = r.hierarchy.levels[l], &C = r.hierarchy.levels[l + 1];
        long interior_edges = 0, vertex_faces = 0;
        bool closed = true;
        for (Index e = 0; e < P.edge_count(); ++e) interior_edges += !P.edge_on_boundary(e), closed &= !P.edge_on_boundary(e);
        for (Index v = 0; v < P.vertex_count; ++v) vertex_faces += P.incident_face_count(v) >= 3;
        CAPTURE(d);
        CAPTURE(l);
        CHECK(C.vertex_count == P.corner_count());
        CHECK(C.face_count() == P.face_count() + interior_edges + vertex_faces);
        CHECK(euler_characteristic(C) == chi);
        if (closed)
          for (Index v = 0; v < C.vertex_count; ++v) CHECK(C.valence(v) == 4);
      }
    }
}

TEST_CASE("quad-bspline d=4 boundary: the quartic B-spline of the boundary polygon, (1, 10, 5)/16 and (5, 10, 1)/16") {
  // Along a boundary the dual split cuts Chaikin's corners (the split's own curve) and the
  // pass's crease rule (1/4, 1/2, 1/4) averages them: Lane-Riesenfeld of degree 4 on the
  // boundary polygon. Checked on the bottom side of a perturbed grid, away from its corners
  // (the pass's end rules reach four child points from a corner: dual_crease_ends_test.cpp).
  const int nx = 11, ny = 3;
  test::Mesh m = test::grid(nx, ny);
  for (Index v = 0; v < m.vertex_count; ++v) {
    m.positions[3 * v] += 0.1 * std::sin(1.7 * v);
    m.positions[3 * v + 1] += 0.05 * std::cos(0.9 * v);
    m.positions[3 * v + 2] = 0.3 * std::sin(0.6 * v * v);
  }
  const auto r = test::refine_mesh(m, "quad-bspline", 1, {}, Params{{"d", "4"}});
  auto p = [&](int i, int x) { return m.positions[3 * i + x]; };  // bottom row: vertex (i, 0) = i
  for (int i = 3; i + 4 <= nx; ++i) {
    const Index f = i;  // face (i, 0), corners (i,0), (i+1,0), (i+1,1), (i,1)
    for (int x = 0; x < 3; ++x) {
      CHECK(r.positions[3 * (4 * f) + x] == doctest::Approx((p(i - 1, x) + 10 * p(i, x) + 5 * p(i + 1, x)) / 16).epsilon(1e-13));
      CHECK(r.positions[3 * (4 * f + 1) + x] == doctest::Approx((5 * p(i, x) + 10 * p(i + 1, x) + p(i + 2, x)) / 16).epsilon(1e-13));
    }
  }
}

TEST_CASE("quad-bspline: one split per level, chosen by when; parity and range errors") {
  CHECK(load_scheme("quad-bspline", Params{{"d", "2"}})->split() == SplitKind::Dual);
  CHECK(load_scheme("quad-bspline", Params{{"d", "2"}})->steps.size() == 1);
  CHECK(load_scheme("quad-bspline", Params{{"d", "6"}})->steps.size() == 3);
  CHECK(load_scheme("quad-bspline", Params{{"d", "7"}})->split() == SplitKind::Quad);
  CHECK(load_scheme("quad-bspline", Params{{"d", "7"}})->steps.size() == 4);
  CHECK_THROWS_WITH_AS(load_scheme("quad-bspline", Params{{"d", "2.5"}}), doctest::Contains("repeat"), Error);
  CHECK_THROWS_AS(load_scheme("quad-bspline", Params{{"d", "1"}}), Error);
}
