// Repeated evaluation (framework/engine/evaluator.h): an Evaluator made once carries any
// number of value sets through the levels. Each evaluation must be what step_values gives
// level by level (the same bits: the same kernels, plans and rules, made ready once, the
// flat kernels' neighbourhoods read off the topology once instead of walked each time), also
// on a second and third evaluation with other values (plans learnt by the first serve the
// next); the rules are affine, so moving the base values by any affine map moves the
// result by the same map; the same bits for any thread count; sequences of schemes,
// smoothing passes and per-vertex parameters as step_values takes them; and bad buffers
// are refused with a message.
#include <cmath>
#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include "framework/engine/evaluator.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// `channels` values per vertex that differ per channel and with `frame` (an animation).
std::vector<double> frame_values(const LevelCase& c, int channels, int frame) {
  std::vector<double> d(size_t(c.level.vertex_count) * channels);
  for (size_t i = 0; i < d.size(); ++i)
    d[i] = c.positions[i % c.positions.size()] * (1.0 + 0.1 * double(i % 7)) + 0.01 * double(i) +
           0.3 * std::sin(double(frame) + 0.7 * double(i));
  return d;
}

std::vector<double> stepped(std::span<const SchemeRun> runs, const Hierarchy& h, std::vector<double> values,
                            int channels, const RefineOptions& o) {
  for (int l = 0; l + 1 < int(h.levels.size()); ++l) values = step_values(runs, h, l, values, channels, o);
  return values;
}

// Three frames through one evaluator, each the same bits as step_values level by level.
void check_frames(std::span<const SchemeRun> runs, const LevelCase& c, const RefineOptions& o, int channels) {
  CAPTURE(channels);
  const Hierarchy h = refine_topology(runs, c.level, o);
  Evaluator evaluator(runs, h, o);
  REQUIRE(evaluator.levels() == int(h.levels.size()) - 1);
  for (int frame = 0; frame < 3; ++frame) {
    CAPTURE(frame);
    const std::vector<double> base = frame_values(c, channels, frame);
    CHECK(evaluator.evaluate(base, channels) == stepped(runs, h, base, channels, o));
  }
}

void check_scheme(const std::string& name, const std::vector<LevelCase>& cases, int levels) {
  CAPTURE(name);
  const auto scheme = load_scheme(name);
  const SchemeRun run{scheme.get(), levels};
  RefineOptions o;
  o.levels = levels;
  for (const LevelCase& c : cases)
    for (int channels : {3, 1, 4}) check_frames(std::span(&run, 1), c, o, channels);
}

}  // namespace

TEST_CASE("each evaluation equals step_values level by level, bit for bit, for every shipped surface scheme") {
  const std::vector<LevelCase> quads = {level_case(torus(6, 5)), level_case(grid(4, 3)), creased_cube_case(),
                                        level_case(torus(3, 3))};
  const std::vector<LevelCase> triangles = {level_case(torus(6, 5, true)), level_case(grid(4, 3, true)),
                                            level_case(bipyramid(7)), level_case(octahedron()),
                                            creased_case(torus(6, 5, true))};
  for (const char* name : {"catmull-clark", "catmull-clark-shape", "bilinear", "doo-sabin", "doo-sabin-centroid",
                           "mid-edge", "quad-bspline"})
    check_scheme(name, quads, 2);
  for (const char* name : {"loop", "butterfly", "modified-butterfly", "midpoint", "loop-composite"})
    check_scheme(name, triangles, 2);
  check_scheme("sqrt3", triangles, 3);  // boundaries trisected every second step
  check_scheme("catmull-clark", {level_case(pyramid())}, 3);  // a quad among triangles
}

TEST_CASE("an evaluator computes each point by the path step_values takes (flat kernels, kernels, plans, rules)") {
  // Its flat kernels read neighbourhoods resolved once; they must take the same elements as
  // the kernels that walk the topology, and leave the same ones (features, boundaries) to
  // the slower paths.
  for (const char* name : {"loop", "catmull-clark"}) {
    CAPTURE(name);
    const auto scheme = load_scheme(name);
    const bool triangles = std::string(name) == "loop";
    for (const LevelCase& c : {creased_case(torus(8, 6, triangles)), level_case(grid(5, 4, triangles))}) {
      RowPaths walked, resolved;
      RefineOptions o;
      o.levels = 2;
      const Hierarchy h = refine_topology(*scheme, c.level, o);
      o.evaluation.row_paths = &walked;
      const SchemeRun run{scheme.get(), 2};
      stepped(std::span(&run, 1), h, c.positions, 3, o);
      o.evaluation.row_paths = &resolved;
      Evaluator(*scheme, h, o).evaluate(c.positions, 3);
      CHECK(resolved.flat.load() == walked.flat.load());
      CHECK(resolved.kernel.load() == walked.kernel.load());
      CHECK(resolved.plan.load() == walked.plan.load());
      CHECK(resolved.generic.load() == walked.generic.load());
      CHECK(walked.flat.load() > 0);
      CHECK(walked.plan.load() + walked.generic.load() + walked.kernel.load() > walked.flat.load());
    }
  }
}

TEST_CASE("a sequence of schemes and per-vertex parameters evaluate as step_values takes them") {
  const SchemeSequence seq = load_scheme_sequence("catmull-clark-shape:1,catmull-clark", 3, {});
  const LevelCase c = creased_cube_case();
  RefineOptions o;
  std::vector<double> lambda(size_t(c.level.vertex_count));
  for (size_t v = 0; v < lambda.size(); ++v) lambda[v] = 0.4 + 0.6 * double((v * 5) % 9) / 8.0;
  o.vertex_parameters["lambda"] = lambda;
  check_frames(seq.runs, c, o, 3);
}

TEST_CASE("the rules are affine: an affine map of the base values maps the evaluation the same way") {
  // p -> A p + t on every vertex; A is not orthogonal, so any rule whose weights do not sum to
  // one, or that treats the channels differently, shows.
  const double A[3][3] = {{1.3, -0.4, 0.2}, {0.5, 0.9, -1.1}, {-0.3, 0.7, 2.0}}, t[3] = {4.0, -2.5, 0.75};
  auto mapped = [&](const std::vector<double>& p) {
    std::vector<double> q(p.size());
    for (size_t i = 0; i < p.size(); i += 3)
      for (int r = 0; r < 3; ++r) q[i + r] = A[r][0] * p[i] + A[r][1] * p[i + 1] + A[r][2] * p[i + 2] + t[r];
    return q;
  };
  const std::vector<std::pair<const char*, LevelCase>> cases = {
      {"catmull-clark", creased_cube_case()}, {"loop", level_case(grid(4, 3, true))}, {"doo-sabin", level_case(grid(4, 3))},
      {"sqrt3", level_case(torus(6, 5, true))}, {"modified-butterfly", level_case(bipyramid(7))}};
  for_each_refined_case(cases, 2, [&](const Scheme& scheme, const LevelCase& c, const Hierarchy& h, const RefineOptions& o) {
    Evaluator evaluator(scheme, h, o);
    const std::vector<double> moved_first = evaluator.evaluate(mapped(c.positions), 3);
    const std::vector<double> moved_after = mapped(evaluator.evaluate(c.positions, 3));
    REQUIRE(moved_first.size() == moved_after.size());
    double worst = 0.0;
    for (size_t i = 0; i < moved_first.size(); ++i) worst = std::max(worst, std::abs(moved_first[i] - moved_after[i]));
    CHECK(worst < 1e-12);
  });
}

TEST_CASE("an evaluator gives the same bits on one thread and on two") {
  const LevelCase c = level_case(torus(300, 200));  // 60k faces: several parallel tasks per group
  for (const char* name : {"catmull-clark", "loop"}) {
    CAPTURE(name);
    const auto scheme = load_scheme(name);
    const LevelCase in = std::string(name) == "loop" ? level_case(torus(300, 200, true)) : c;
    RefineOptions o;
    o.levels = 2;
    const Hierarchy h = refine_topology(*scheme, in.level, o);
    Evaluator evaluator(*scheme, h, o);
    std::vector<double> one, two;
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
      one = evaluator.evaluate(in.positions, 3);
    }
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
      two = evaluator.evaluate(in.positions, 3);
    }
    CHECK(one == two);
  }
}

TEST_CASE("zero levels copy the values; wrong buffers are refused with a message") {
  const auto scheme = load_scheme("catmull-clark");
  const LevelCase c = level_case(cube());
  RefineOptions o;
  o.levels = 0;
  const Hierarchy none = refine_topology(*scheme, c.level, o);
  Evaluator same(*scheme, none, o);
  CHECK(same.evaluate(c.positions, 3) == c.positions);

  o.levels = 1;
  const Hierarchy h = refine_topology(*scheme, c.level, o);
  Evaluator evaluator(*scheme, h, o);
  CHECK(evaluator.base_vertex_count() == 8);
  CHECK(evaluator.finest_vertex_count() == 26);
  std::vector<double> finest(26 * 3);
  CHECK_THROWS_WITH_AS(evaluator.evaluate(std::vector<double>(5), finest, 3),
                       doctest::Contains("5 base values for 8 vertices of 3 channels"), Error);
  CHECK_THROWS_WITH_AS(evaluator.evaluate(c.positions, std::span(finest).first(10), 3),
                       doctest::Contains("room for 10 values, but the finest level has 26 vertices"), Error);
  CHECK_THROWS_WITH_AS(evaluator.evaluate(c.positions, finest, 0), doctest::Contains("0 channels"), Error);
  std::vector<double> shared(26 * 3);
  std::copy(c.positions.begin(), c.positions.end(), shared.begin());
  CHECK_THROWS_WITH_AS(evaluator.evaluate(std::span(shared).first(24), shared, 3), doctest::Contains("share memory"),
                       Error);
  // A hierarchy of another number of levels than the runs.
  const SchemeRun two{scheme.get(), 2};
  CHECK_THROWS_WITH_AS(Evaluator(std::span(&two, 1), h, o), doctest::Contains("the runs give 2 levels but the hierarchy has 1"),
                       Error);
}
