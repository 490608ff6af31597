#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <tbb/global_control.h>

#include "support/reference_rules.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using test::weight_of;

TEST_CASE("Catmull-Clark equals Catmull & Clark 1978's face, edge and vertex rules on n-gons and extraordinary vertices") {
  for (const auto& mesh : {test::cube(), test::pyramid(), test::torus(5, 3)}) {
    const auto r = test::refine_mesh(mesh, "catmull-clark", 1);
    const auto expected = test::catmull_clark_by_seed(mesh.level(), mesh.positions);
    REQUIRE(expected.size() == r.positions.size());
    for (size_t i = 0; i < expected.size(); ++i) CHECK(r.positions[i] == doctest::Approx(expected[i]).epsilon(1e-14));
  }
}

TEST_CASE("Catmull-Clark at regular interior vertices is bicubic B-spline refinement") {
  // Tensor products of the cubic B-spline rules (1/8, 3/4, 1/8) and (1/2, 1/2), Catmull & Clark 1978.
  const test::Mesh mesh = test::torus(6, 6);
  const auto r = test::refine_mesh(mesh, "catmull-clark", 1);
  const StencilTable& t = r.hierarchy.stencils[0];
  const Level& L = r.hierarchy.levels[0];
  auto id = [](int i, int j) { return Index(((j + 6) % 6) * 6 + (i + 6) % 6); };
  const Index v = id(2, 3);
  CHECK(t.row_size(v) == 9);
  CHECK(weight_of(t, v, v) == doctest::Approx(9.0 / 16));
  CHECK(weight_of(t, v, id(3, 3)) == doctest::Approx(3.0 / 32));
  CHECK(weight_of(t, v, id(2, 2)) == doctest::Approx(3.0 / 32));
  CHECK(weight_of(t, v, id(1, 2)) == doctest::Approx(1.0 / 64));
  CHECK(weight_of(t, v, id(3, 4)) == doctest::Approx(1.0 / 64));
  const Index e = find_edge(L, id(2, 3), id(3, 3));
  const Index row = L.vertex_count + e;
  CHECK(t.row_size(row) == 6);
  CHECK(weight_of(t, row, id(2, 3)) == doctest::Approx(3.0 / 8));
  CHECK(weight_of(t, row, id(3, 4)) == doctest::Approx(1.0 / 16));
  CHECK(weight_of(t, row, id(2, 2)) == doctest::Approx(1.0 / 16));
}

TEST_CASE("every stencil row sums to one (affine invariance) and translations commute") {
  const test::Mesh mesh = test::pyramid();
  const auto r = test::refine_mesh(mesh, "catmull-clark", 3);
  for (const auto& t : r.hierarchy.stencils)
    for (Index row = 0; row < t.row_count(); ++row) {
      double sum = 0;
      for (Index i = t.offsets[row]; i < t.offsets[row + 1]; ++i) sum += t.weights[i];
      CHECK(sum == doctest::Approx(1.0).epsilon(1e-13));
    }
  test::Mesh moved = mesh;
  for (Index v = 0; v < moved.vertex_count; ++v) {
    // An affine map: rotate about z by 0.3 rad, scale x by 2, translate.
    const double x = moved.positions[3 * v], y = moved.positions[3 * v + 1];
    moved.positions[3 * v] = 2 * (std::cos(0.3) * x - std::sin(0.3) * y) + 5;
    moved.positions[3 * v + 1] = std::sin(0.3) * x + std::cos(0.3) * y - 1;
    moved.positions[3 * v + 2] += 7;
  }
  const auto rm = test::refine_mesh(moved, "catmull-clark", 3);
  for (size_t v = 0; v < r.positions.size() / 3; ++v) {
    const double x = r.positions[3 * v], y = r.positions[3 * v + 1];
    CHECK(rm.positions[3 * v] == doctest::Approx(2 * (std::cos(0.3) * x - std::sin(0.3) * y) + 5).epsilon(1e-12));
    CHECK(rm.positions[3 * v + 2] == doctest::Approx(r.positions[3 * v + 2] + 7).epsilon(1e-12));
  }
}

TEST_CASE("planar input stays planar") {
  test::Mesh m = test::grid(4, 3);
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[3 * v + 2] = 0.5 * m.positions[3 * v] - 0.25 * m.positions[3 * v + 1] + 1;
  const auto r = test::refine_mesh(m, "catmull-clark", 3);
  for (size_t v = 0; v < r.positions.size() / 3; ++v)
    CHECK(r.positions[3 * v + 2] == doctest::Approx(0.5 * r.positions[3 * v] - 0.25 * r.positions[3 * v + 1] + 1).epsilon(1e-12));
}

TEST_CASE("same bits for any thread count") {
  const test::Mesh mesh = test::torus(40, 30);
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return test::refine_mesh(mesh, "catmull-clark", 3).positions;
  };
  const auto one = run(1), two = run(2);
  REQUIRE(one.size() == two.size());
  CHECK(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)) == 0);
}
