#include <doctest/doctest.h>

#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using test::weight_of;

TEST_CASE("catmull-clark-shape: v' = lambda v + (1 - lambda)(alpha E + (1 - alpha) F), alpha = 10/13 (Lin et al. 2015)") {
  const test::Mesh m = test::torus(6, 5);
  for (double lambda : {0.5, 0.8, 1.0}) {
    const auto r = test::refine_mesh(m, "catmull-clark-shape", 1, {}, {{"lambda", std::to_string(lambda)}});
    const auto& S = r.hierarchy.stencils[0];
    const Level& L = r.hierarchy.levels[0];
    const double alpha = 10.0 / 13;
    const Index v = 7;  // (1, 1) on the 6x5 torus
    CHECK(weight_of(S, v, v) == doctest::Approx(lambda).epsilon(1e-14));
    for (Index e : L.ring_edges(v))
      CHECK(weight_of(S, v, L.other_end(e, v)) == doctest::Approx((1 - lambda) * alpha / 4).epsilon(1e-14));
    CHECK(weight_of(S, v, 0) == doctest::Approx((1 - lambda) * (1 - alpha) / 4).epsilon(1e-14));  // diagonal (0, 0)
  }
  CHECK_THROWS_WITH_AS(load_scheme("catmull-clark-shape", {{"lambda", "0.35"}}), doctest::Contains("(0.35, 1]"), Error);
}

TEST_CASE("a scheme sequence applies each scheme for its levels") {
  const test::Mesh m = test::torus(6, 5);
  const SchemeSequence seq = load_scheme_sequence("catmull-clark-shape:1,catmull-clark:2", 0, {{"lambda", "0.6"}});
  CHECK(seq.total_levels == 3);
  const Hierarchy h = refine(seq.runs, m.level(), {});
  const auto got = interpolate(h, 3, m.positions, 3);
  // The same by hand: one shape step, then two Catmull-Clark levels on its result.
  const auto first = test::refine_mesh(m, "catmull-clark-shape", 1, {}, {{"lambda", "0.6"}});
  RefineOptions two;
  two.levels = 2;
  const Hierarchy rest = refine(*load_scheme("catmull-clark"), first.hierarchy.levels[1], two);
  const auto expected = interpolate(rest, 2, first.positions, 3);
  REQUIRE(got.size() == expected.size());
  for (size_t i = 0; i < got.size(); ++i) CHECK(got[i] == doctest::Approx(expected[i]).epsilon(1e-13));
  // A name without a count takes the remaining levels.
  CHECK(load_scheme_sequence("catmull-clark-shape:1,catmull-clark", 4, {}).runs[1].levels == 3);
  CHECK_THROWS_AS(load_scheme_sequence("catmull-clark:x", 1, {}), Error);
  CHECK_THROWS_WITH_AS(load_scheme_sequence("catmull-clark:1", 1, {{"lambda", "0.5"}}), doctest::Contains("has a parameter 'lambda'"), Error);
}
