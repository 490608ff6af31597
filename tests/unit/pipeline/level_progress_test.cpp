// The refinement's progress (RefineRequest::progress_fraction, issue 31): 0 first, 1 last,
// never back, and moving within a level — after each pass of the level's step (the split's
// rows, then each smoothing pass), and within a pass after each kind of new point (face,
// edge, vertex points), in proportion to their counts (util/step_progress.h) — not only
// between levels.
#include <doctest/doctest.h>

#include <vector>

#include "framework/pipeline/refine_pipeline.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

struct Run {
  std::vector<double> shares;
  std::vector<double> level_ends;  // the share at the end of each level, from its faces
};

// Refines the cube `levels` times with `scheme` (and `parameter`), recording every share told.
Run refine_recorded(const std::string& scheme, int levels, const ParameterOverrides& parameters = {}) {
  RefineRequest r;
  r.mesh = test::mesh_data(test::cube());
  r.mesh_name = "cube";
  r.scheme.text = scheme;
  r.scheme.parameters = parameters;
  r.levels = levels;
  Run run;
  r.progress_fraction = [&run](double done) { run.shares.push_back(done); };
  const RefineResult result = refine_mesh(r);
  // A level's work is its faces (+1), as the pipeline weighs it.
  double total = 0;
  for (size_t l = 1; l < result.hierarchy.levels.size(); ++l) total += result.hierarchy.levels[l].face_count() + 1;
  double done = 0;
  for (size_t l = 1; l < result.hierarchy.levels.size(); ++l) {
    done += result.hierarchy.levels[l].face_count() + 1;
    run.level_ends.push_back(done / total);
  }
  return run;
}

void check_never_back(const Run& run) {
  REQUIRE(run.shares.size() >= 2);
  CHECK(run.shares.front() == 0.0);
  CHECK(run.shares.back() == doctest::Approx(1.0).epsilon(1e-15));
  for (size_t i = 1; i < run.shares.size(); ++i) {
    INFO("share " << i << ": " << run.shares[i - 1] << " then " << run.shares[i]);
    CHECK(run.shares[i] >= run.shares[i - 1]);
    CHECK(run.shares[i] <= 1.0);
  }
}

// Shares strictly inside the last level (after the level before it ended, before it ends).
size_t inside_last_level(const Run& run) {
  const double begin = run.level_ends.size() > 1 ? run.level_ends[run.level_ends.size() - 2] : 0.0;
  const double end = run.level_ends.back();
  size_t n = 0;
  for (double s : run.shares) n += s > begin + 1e-12 && s < end - 1e-12;
  return n;
}

}  // namespace

TEST_CASE("the share moves within a level, once per pass of its step, and never goes back") {
  // Quad B-spline of degree 7 (Stam 2001; Lane & Riesenfeld 1980): a bilinear split, then 3
  // smoothing passes per level, so 4 passes: the shares 1/4, 2/4 and 3/4 of the last level
  // lie strictly inside it.
  const Run run = refine_recorded("quad-bspline", 3, {{"d", "7"}});
  check_never_back(run);
  const double begin = run.level_ends[1], end = run.level_ends[2];
  CHECK(inside_last_level(run) >= 3);
  for (const double quarter : {0.25, 0.5, 0.75}) {
    bool told = false;
    for (double s : run.shares) told = told || s == doctest::Approx(begin + quarter * (end - begin)).epsilon(1e-12);
    CHECK_MESSAGE(told, "no share at " << quarter << " of the last level");
  }
}

TEST_CASE("a scheme of one pass per level moves after each kind of new point, by their counts") {
  // Catmull-Clark's level 3 of the cube: its new points are level 2's 96 face points, 192
  // edge points and 98 vertex points (V - E + F = 2), made kind by kind in the order the
  // rules need them: the two shares inside the last level are sums of those counts over 386.
  const Run run = refine_recorded("catmull-clark", 3);
  check_never_back(run);
  CHECK(inside_last_level(run) == 2);
  const double begin = run.level_ends[1], end = run.level_ends[2];
  for (double s : run.shares) {
    if (s <= begin + 1e-12 || s >= end - 1e-12) continue;
    const double rows = (s - begin) / (end - begin) * 386.0;
    INFO("a share inside the last level at " << rows << " of its 386 new points");
    bool a_sum = false;
    for (const double sum : {96.0, 98.0, 192.0, 96.0 + 98.0, 96.0 + 192.0, 98.0 + 192.0})
      a_sum = a_sum || rows == doctest::Approx(sum).epsilon(1e-9);
    CHECK(a_sum);
  }
}

}  // namespace subdiv
