// Catmull-Clark at extraordinary vertices against Halstead, Kass & DeRose 1993: the subdominant eigenvalue
// (4 + A_n)/16, the limit point (n^2 v + 4 sum e_j + sum f_j)/(n(n+5)) and the limit normal
// C_2 x C_3 (with their masks for C_2, C_3). Also the curve facts
// that Catmull-Clark boundaries and creases follow: the cubic B-spline limit
// (P_{i-1} + 4 P_i + P_{i+1})/6 (Lane & Riesenfeld 1980).
#include <doctest/doctest.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// Halstead, Kass & DeRose 1993: A_n = 1 + cos(2 pi/n) + cos(pi/n) sqrt(2 (9 + cos(2 pi/n))).
double seed_A(int n) {
  const double c = std::cos(2 * kPi / n);
  return 1 + c + std::cos(kPi / n) * std::sqrt(2 * (9 + c));
}

}  // namespace

TEST_CASE("Catmull-Clark: subdominant eigenvalue (4 + A_n)/16, n = 3..12 (Halstead, Kass & DeRose 1993)") {
  const auto cc = load_scheme("catmull-clark");
  for (int n = 3; n <= 12; ++n) {
    CAPTURE(n);
    const SurfaceAnalysis a = analyse_valence(*cc, n);
    REQUIRE(a.error.empty());
    const double lambda = (4 + seed_A(n)) / 16;
    CHECK(a.eigenvalues[0].real() == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(std::abs(a.eigenvalues[1].real() - lambda) < 1e-12);
    CHECK(std::abs(a.eigenvalues[2].real() - lambda) < 1e-12);
    CHECK(std::abs(a.eigenvalues[1].imag()) < 1e-12);
    CHECK(a.lambda0_one);
    CHECK(a.subdominant_equal);
    CHECK(a.subdominant_dominates);
    // Their S_n: V = [v, e_1..e_n, f_1..f_n], m = 2n + 1; the analysed ring is wider.
    CHECK(a.minimal_size == 2 * n + 1);
    CHECK(a.characteristic_map.regular);
    CHECK(a.characteristic_map.injective);
    CHECK(a.c1);
    CHECK(a.verdict == "C1 at valence " + std::to_string(n));
  }
}

TEST_CASE("Catmull-Clark: limit point (n^2 v + 4 sum e + sum f)/(n(n+5)) and normal C2 x C3 (Halstead, Kass & DeRose 1993)") {
  const auto cc = load_scheme("catmull-clark");
  for (int n = 3; n <= 12; ++n) {
    CAPTURE(n);
    const RandomPatch p = random_patch(PatchCells::Quads, n, 17u + unsigned(n));
    const LimitResult r = limit_positions(*cc, p.level, p.positions);
    const auto e = ring_neighbours(p.level, 0);
    const auto f = face_diagonals(p.level, 0);
    REQUIRE(int(e.size()) == n);
    // e_j are the edge neighbours (weight 4), f_j the face-diagonal points (weight 1).
    const CatmullClarkLimit expected = catmull_clark_limit(p.positions, 0, e, f);
    CHECK(distance(at(r.positions, 0), expected.point) < 1e-12);
    CHECK(r.exact[0] == 1);
    CHECK(dot(expected.normal, at(r.normals, 0)) > 1 - 1e-12);
  }
}

TEST_CASE("Catmull-Clark at interior valence 2: eigenvalues 1, 1/4, 1/4, -1/4, 1/8, limit point, no tangent plane") {
  // Catmull & Clark's rules are defined for n = 2 (vertex weight (n - 2)/n = 0). On the
  // 1-ring (v, e_0, f_0, e_1, f_1) the matrix has the eigenvalues 1, 1/4 (twice, two
  // eigenvectors: e_1 - e_0 and f_1 - f_0), -1/4 (eigenvector e_0 + e_1 - 2 v) and 1/8
  // (computed by hand from the rules; Stam 1998's blocks at n = 2 give 1/4 twice for the
  // frequency pi). |-1/4| = 1/4: the third eigenvalue is as large as the subdominant pair,
  // so there is no tangent plane (Karciauskas & Peters 2009: not C1).
  const auto cc = load_scheme("catmull-clark");
  const SurfaceAnalysis a = analyse_valence(*cc, 2);
  CAPTURE(a.verdict);
  REQUIRE(a.error.empty());
  CHECK(a.minimal_size == 5);
  REQUIRE(a.eigenvalues.size() > 5);
  const double expected[] = {1.0, 0.25, 0.25, -0.25};
  for (size_t i = 0; i < 4; ++i) {
    CHECK(std::abs(a.eigenvalues[i].real() - expected[i]) < 1e-12);
    CHECK(std::abs(a.eigenvalues[i].imag()) < 1e-12);
  }
  CHECK(std::abs(a.eigenvalues[4]) <= 0.125 + 1e-12);
  CHECK(std::abs(a.minimal_eigenvalues[4].real() - 0.125) < 1e-12);
  CHECK(a.lambda0_one);
  CHECK(a.subdominant_equal);
  CHECK(a.subdominant_semisimple);
  CHECK_FALSE(a.subdominant_dominates);
  CHECK_FALSE(a.c1);
  CHECK(a.verdict.find("lambda_3 = -0.25") != std::string::npos);
  CHECK(a.direction_masks.empty());
  // The limit point: the formula at n = 2, (4 v + 4 (e_0 + e_1) + f_0 + f_1)/14.
  const RandomPatch p = random_patch(PatchCells::Quads, 2, 41u);
  const LimitResult r = limit_positions(*cc, p.level, p.positions);
  const auto e = ring_neighbours(p.level, 0);
  const auto f = face_diagonals(p.level, 0);
  REQUIRE(e.size() == 2);
  Vec3 point{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    double sum = 4 * p.positions[size_t(i)];
    for (int j = 0; j < 2; ++j) sum += 4 * at(p.positions, e[size_t(j)])[size_t(i)] + at(p.positions, f[size_t(j)])[size_t(i)];
    point[size_t(i)] = sum / 14;
  }
  CHECK(distance(at(r.positions, 0), point) < 1e-14);
  CHECK(r.exact[0] == 1);
  CHECK(r.normal_exact[0] == 0);  // estimated from the limit points around: there is no exact one
}

TEST_CASE("Loop at interior valence 2: refused with the reason (two triangles closing into a sphere)") {
  const SurfaceAnalysis a = analyse_valence(*load_scheme("loop"), 2);
  CHECK(a.error.find("two-triangle sphere") != std::string::npos);
}

TEST_CASE("Catmull-Clark: the limit of a cube's corner and its radial normal") {
  // The cube is symmetric about its centre: the limit normal at a corner points away from it.
  const Mesh cube = test::cube();
  const auto cc = load_scheme("catmull-clark");
  const LimitResult r = limit_positions(*cc, cube.level(), cube.positions);
  const Level L = cube.level();
  for (Index v = 0; v < 8; ++v) {
    CAPTURE(v);
    const auto e = ring_neighbours(L, v);
    const auto f = face_diagonals(L, v);
    Vec3 expected{0, 0, 0};
    for (int i = 0; i < 3; ++i) {
      double sum = 9 * cube.positions[size_t(3 * v + i)];
      for (int j = 0; j < 3; ++j) sum += 4 * at(cube.positions, e[size_t(j)])[size_t(i)] + at(cube.positions, f[size_t(j)])[size_t(i)];
      expected[size_t(i)] = sum / 24;
    }
    CHECK(distance(at(r.positions, v), expected) < 1e-14);
    const Vec3 radial = unit({expected[0] - 0.5, expected[1] - 0.5, expected[2] - 0.5});
    CHECK(dot(radial, at(r.normals, v)) > 1 - 1e-12);
  }
}

TEST_CASE("Catmull-Clark: boundary and crease vertices follow the cubic B-spline limit (Lane & Riesenfeld 1980)") {
  const auto cc = load_scheme("catmull-clark");
  // A boundary vertex of valence n (n - 1 faces): the limit is (P_- + 4 P + P_+)/6 of its
  // two boundary neighbours.
  for (int n = 3; n <= 6; ++n) {
    CAPTURE(n);
    const RandomPatch p = random_patch(PatchCells::Quads, n, 5u + unsigned(n), 5, true);
    const LimitResult r = limit_positions(*cc, p.level, p.positions);
    const auto e = ring_neighbours(p.level, 0);
    Vec3 expected;
    for (int i = 0; i < 3; ++i)
      expected[size_t(i)] = (at(p.positions, e.front())[size_t(i)] + 4 * p.positions[size_t(i)] +
                             at(p.positions, e.back())[size_t(i)]) / 6;
    CHECK(distance(at(r.positions, 0), expected) < 1e-12);
    CHECK(r.exact[0] == 1);
    CHECK(std::abs(dot(at(r.normals, 0), at(r.normals, 0)) - 1) < 1e-12);
  }
  // A crease through a regular vertex of a torus: the same along the crease.
  Mesh torus = test::torus(12, 10);
  Level L = torus.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (int i = 0; i < 12; ++i) L.edge_sharpness[size_t(find_edge(L, i, (i + 1) % 12))] = 10.f;
  const LimitResult r = limit_positions(*cc, L, torus.positions);
  for (Index v = 0; v < 12; ++v) {
    Vec3 expected;
    for (int i = 0; i < 3; ++i)
      expected[size_t(i)] = (torus.positions[size_t(3 * ((v + 11) % 12) + i)] + 4 * torus.positions[size_t(3 * v + i)] +
                             torus.positions[size_t(3 * ((v + 1) % 12) + i)]) / 6;
    CHECK(distance(at(r.positions, v), expected) < 1e-12);
  }
  CHECK(r.approximate == 0);
}
