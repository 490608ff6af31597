// A plugin's split is analysed with what it says of itself (SplitterInfo: scale, period,
// centre), exactly like a built-in split: the sqrt2 split turns the grid by 45 degrees and
// shrinks it by sqrt 2, so the analysis must study two steps at once.
#include <cmath>
#include <doctest/doctest.h>

#include "framework/analysis/surface/surface_analysis.h"
#include "framework/refine/splitter.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

TEST_CASE("the sqrt2 plugin's split is analysed with its own scale and period") {
  load_example_plugins();
  const auto scheme = load_scheme("sqrt2");
  const SplitterInfo& info = splitter_info(scheme->split());
  CHECK(info.origin != "built-in");
  CHECK(info.period == 2);
  CHECK(info.scale == doctest::Approx(std::sqrt(2.0)));
  CHECK(analysis_steps(*scheme) == 2);
  CHECK(analysis_centre(*scheme) == CentreKind::Vertex);
  CHECK(analysis_cells(*scheme) == PatchCells::Quads);

  // Two sqrt2 steps are one dyadic refinement of the regular grid, and the scheme
  // reproduces linear functions (centroids, then symmetric averaging): x and y are
  // eigenvectors of S^2 with eigenvalue exactly 1/2. Analysing one step alone would see the
  // 45-degree turn as a complex pair of modulus 1/sqrt 2 instead.
  const SurfaceAnalysis regular = analyse_valence(*scheme, 4);
  REQUIRE(regular.error.empty());
  CHECK(regular.steps == 2);
  CHECK(regular.subdominant_real);
  CHECK(regular.subdominant_equal);
  CHECK(regular.lambda1 == doctest::Approx(0.5).epsilon(1e-10));
  CHECK(regular.lambda2 == doctest::Approx(0.5).epsilon(1e-10));
  CHECK(regular.characteristic_map.computed);
  CHECK(regular.characteristic_map.injective);

  // At other valences the same machinery runs on S^2: real subdominant eigenvalues below 1.
  for (int n : {3, 5, 6}) {
    CAPTURE(n);
    const SurfaceAnalysis a = analyse_valence(*scheme, n);
    REQUIRE(a.error.empty());
    CHECK(a.steps == 2);
    CHECK(a.lambda0_one);
    CHECK(a.subdominant_real);
    CHECK(a.lambda1 < 1.0);
  }
}
