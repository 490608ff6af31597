// step_values (framework/engine/refiner.h, rules/step_evaluator.h) carries values to the
// next level straight from the rules, with no stencil table. It must give what the tables
// give, for any channel count, with or without row plans, on meshes with boundaries,
// features and tiny closed rings: the same bits where the rules use no new points (the
// rows are the same), the same values to round-off where they do (Catmull-Clark reads its
// new face points back instead of expanding them); and the same bits for any thread count.
#include <cmath>
#include <limits>
#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// Per-vertex data of `channels` values that are not just positions (and differ per channel).
std::vector<double> data_for(const LevelCase& c, int channels) {
  std::vector<double> d(size_t(c.level.vertex_count) * channels);
  for (size_t i = 0; i < d.size(); ++i) d[i] = c.positions[i % c.positions.size()] * (1.0 + 0.1 * double(i % 7)) + 0.01 * double(i);
  return d;
}

// Level by level, through the tables and through step_values; `exact`: bit for bit.
void check_same_values(const std::string& name, const LevelCase& c, int levels, bool plans, int channels, bool exact) {
  CAPTURE(name);
  CAPTURE(levels);
  CAPTURE(plans);
  CAPTURE(channels);
  const auto scheme = load_scheme(name);
  RefineOptions o;
  o.levels = levels;
  o.evaluation.use_row_plans = plans;
  const Hierarchy topology = refine_topology(*scheme, c.level, o);
  const Hierarchy tables = refine(*scheme, c.level, o);
  std::vector<double> direct = data_for(c, channels), through_tables = direct;
  for (int l = 0; l < levels; ++l) {
    CAPTURE(l);
    direct = step_values(*scheme, topology, l, direct, channels, o);
    through_tables = apply_step(tables, l, through_tables, channels);
    REQUIRE(direct.size() == through_tables.size());
    if (exact) {
      CHECK(direct == through_tables);
      continue;
    }
    double worst = 0.0;
    for (size_t i = 0; i < direct.size(); ++i) worst = std::max(worst, std::abs(direct[i] - through_tables[i]));
    CHECK(worst < 1e-12);
  }
}

// Catmull-Clark's rules use new face points; step_values reads them back (round-off). The
// butterflies' roles overlap (an end's ring holds the other end and the wings): a table row
// merges a point's weights before summing, the compiled kernels sum term by term (round-off).
bool exact_for(const std::string& scheme) {
  return scheme != "catmull-clark" && scheme != "catmull-clark-shape" && scheme != "butterfly" &&
         scheme != "modified-butterfly";
}

}  // namespace

TEST_CASE("step_values equals the stencil tables, bit for bit where the rules use no new points and no point twice") {
  const std::vector<LevelCase> quads = {level_case(torus(6, 5)), level_case(cube()), level_case(grid(4, 3)),
                                        creased_cube_case(), level_case(torus(3, 3))};
  const std::vector<LevelCase> triangles = {level_case(torus(6, 5, true)), level_case(octahedron()),
                                            level_case(grid(4, 3, true)), level_case(bipyramid(7)),
                                            level_case(torus(3, 3, true))};
  for (bool plans : {true, false})
    for (int channels : {3, 1, 2}) {
      for (const char* scheme : {"catmull-clark", "catmull-clark-shape", "bilinear", "doo-sabin", "doo-sabin-centroid", "mid-edge"})
        for (const LevelCase& c : quads) check_same_values(scheme, c, 2, plans, channels, exact_for(scheme));
      for (const char* scheme : {"catmull-clark", "doo-sabin", "mid-edge"})
        check_same_values(scheme, level_case(pyramid()), 2, plans, channels, exact_for(scheme));  // a quad among triangles
      for (const char* scheme : {"loop", "butterfly", "modified-butterfly", "midpoint"})
        for (const LevelCase& c : triangles) check_same_values(scheme, c, 2, plans, channels, exact_for(scheme));
      for (const LevelCase& c : triangles) check_same_values("sqrt3", c, 3, plans, channels, true);
    }
  check_same_values("catmull-clark", creased_cube_case(), 4, true, 3, false);  // semi-sharp decays over levels
  check_same_values("loop", level_case(torus(6, 5, true)), 3, true, 3, true);
}

TEST_CASE("step_values applies smoothing passes one after another, equal to the composed tables") {
  const std::vector<LevelCase> triangles = {level_case(torus(6, 5, true)), level_case(grid(4, 3, true)), level_case(bipyramid(7))};
  for (const LevelCase& c : triangles) check_same_values("loop-composite", c, 2, true, 3, false);
  for (const LevelCase& c : {level_case(torus(6, 5)), level_case(grid(4, 3)), creased_cube_case()}) check_same_values("quad-bspline", c, 2, true, 3, false);
}

TEST_CASE("step_values gives the same bits on one thread and on two") {
  const LevelCase c = level_case(torus(300, 200));  // 60k faces: several parallel tasks per group
  const auto scheme = load_scheme("catmull-clark");
  RefineOptions o;
  o.levels = 1;
  const Hierarchy h = refine_topology(*scheme, c.level, o);
  std::vector<double> one, two;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = step_values(*scheme, h, 0, c.positions, 3, o);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = step_values(*scheme, h, 0, c.positions, 3, o);
  }
  CHECK(one == two);
  const std::vector<double> tables = interpolate(refine(*scheme, c.level, o), 1, c.positions, 3);
  double worst = 0.0;
  for (size_t i = 0; i < one.size(); ++i) worst = std::max(worst, std::abs(one[i] - tables[i]));
  CHECK(worst < 1e-12);
}

TEST_CASE("step_values refuses wrong buffers and steps with a message") {
  const auto scheme = load_scheme("catmull-clark");
  RefineOptions o;
  o.levels = 1;
  const LevelCase c = level_case(cube());
  const Hierarchy h = refine_topology(*scheme, c.level, o);
  CHECK_THROWS_WITH_AS(step_values(*scheme, h, 1, c.positions, 3, o), doctest::Contains("step 1 is not in 0..0"), Error);
  CHECK_THROWS_WITH_AS(step_values(*scheme, h, 0, std::vector<double>(5), 3, o),
                       doctest::Contains("5 values for 8 vertices of 3 channels"), Error);
}

TEST_CASE("step_values into the caller's memory: every value written, the same bits as the returned vector") {
  // quad-bspline has two smoothing passes after its split (they alternate between the
  // output and one scratch level), loop-composite one, catmull-clark none.
  const std::vector<std::pair<const char*, LevelCase>> cases = {
      {"catmull-clark", creased_cube_case()}, {"quad-bspline", level_case(grid(4, 3))}, {"loop-composite", level_case(bipyramid(7))}};
  for_each_refined_case(cases, 2, [&](const Scheme& scheme, const LevelCase& c, const Hierarchy& h, const RefineOptions& o) {
    std::vector<double> values = c.positions;
    for (int l = 0; l < 2; ++l) {
      const std::vector<double> returned = step_values(scheme, h, l, values, 3, o);
      std::vector<double> into(returned.size(), std::numeric_limits<double>::quiet_NaN());  // a value left unwritten shows
      step_values(scheme, h, l, values, into, 3, o);
      CHECK(into == returned);
      values = returned;
    }
  });
  const LevelCase c = level_case(cube());
  const auto scheme = load_scheme("catmull-clark");
  RefineOptions o;
  const Hierarchy h = refine_topology(*scheme, c.level, o);
  std::vector<double> small(10);
  CHECK_THROWS_WITH_AS(step_values(*scheme, h, 0, c.positions, small, 3, o),
                       doctest::Contains("room for 10 values, but level 1 has 26 vertices of 3 channels"), Error);
}
