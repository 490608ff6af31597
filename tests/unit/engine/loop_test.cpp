#include <doctest/doctest.h>

#include <cmath>

#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using test::weight_of;

namespace {

double loop_beta(int n) {
  const double c = 3.0 / 8 + std::cos(2 * std::acos(-1.0) / n) / 4;
  return (5.0 / 8 - c * c) / n;
}
double warren_beta(int n) { return n == 3 ? 3.0 / 16 : 3.0 / (8.0 * n); }

}  // namespace

TEST_CASE("Loop vertex rule gives Loop's and Warren's beta_n, valences 3..12") {
  for (int n = 3; n <= 12; ++n) {
    const test::Mesh m = test::bipyramid(n);
    const Index apex = n;  // valence n
    for (const std::string variant : {"loop", "warren"}) {
      const auto r = test::refine_mesh(m, "loop", 1, {}, {{"beta", variant}});
      const double beta = variant == "loop" ? loop_beta(n) : warren_beta(n);
      const auto& t = r.hierarchy.stencils[0];
      CHECK(weight_of(t, apex, apex) == doctest::Approx(1 - n * beta).epsilon(1e-14));
      for (Index i = 0; i < n; ++i) CHECK(weight_of(t, apex, i) == doctest::Approx(beta).epsilon(1e-14));
    }
  }
  // Regular valence 6: beta = 1/16 in Loop's form.
  CHECK(loop_beta(6) == doctest::Approx(1.0 / 16));
}

TEST_CASE("Loop edge rule: 3/8 on the ends, 1/8 on the opposite vertices") {
  const test::Mesh m = test::octahedron();
  const auto r = test::refine_mesh(m, "loop", 1);
  const Level& L = r.hierarchy.levels[0];
  const Index e = find_edge(L, 0, 2);
  const Index row = L.vertex_count + e;
  const auto& t = r.hierarchy.stencils[0];
  CHECK(t.row_size(row) == 4);
  CHECK(weight_of(t, row, 0) == doctest::Approx(3.0 / 8));
  CHECK(weight_of(t, row, 2) == doctest::Approx(3.0 / 8));
  CHECK(weight_of(t, row, 4) == doctest::Approx(1.0 / 8));
  CHECK(weight_of(t, row, 5) == doctest::Approx(1.0 / 8));
}

TEST_CASE("Loop refuses quads with a clear message") {
  CHECK_THROWS_WITH_AS(test::refine_mesh(test::cube(), "loop", 1),
                       doctest::Contains("needs triangles, but face 0 of the mesh has 4 vertices"), Error);
}
