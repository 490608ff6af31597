// A scheme written without boundary rules (no "curve", no crease rule) refines a closed mesh
// without creases, so its limit there must be evaluable too: the neighbourhoods evaluation
// cuts out of the mesh have rims, which take stand-in rules (analysis/surface/rim_rules.h)
// that never reach the evaluated point. Catmull-Clark's rules without a curve must give the
// shipped Catmull-Clark's limit (itself checked against OpenSubdiv's Bfr) at random points
// and vertices; on a mesh with a boundary the scheme's own rules are missing and the
// evaluation says so.
#include <doctest/doctest.h>

#include <random>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/scheme_files.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

std::shared_ptr<const Scheme> catmull_clark_without_curve() {
  return load_scheme(test::write_scheme_file("limit-no-curve", "cc-no-curve", R"({"name": "cc-no-curve",
    "split": "quad",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
              "vertex": [{"at": "self", "w": "(n-2)/n"}, {"sum": "ring", "w": "1/n^2"},
                         {"sum": "faces", "new": "face", "w": "1/n^2"}]}})")
                         .string());
}

}  // namespace

TEST_CASE("a scheme without boundary rules: its limit on a closed mesh is the shipped scheme's") {
  const auto bare = catmull_clark_without_curve();
  REQUIRE(bare->curve == nullptr);
  const auto shipped = load_scheme("catmull-clark");
  const test::Mesh cube = limit_test::bumped(test::cube());
  const LimitSurface ours(bare, cube.level()), reference(shipped, cube.level());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uv(0, 1);
  double worst = 0;
  for (Index f = 0; f < 6; ++f)
    for (int k = 0; k < 8; ++k) {
      const double u = uv(rng), v = uv(rng);
      const LimitSample a = ours.evaluate(f, u, v, cube.positions, 3), b = reference.evaluate(f, u, v, cube.positions, 3);
      REQUIRE(a.has_derivatives);
      for (int c = 0; c < 3; ++c)
        worst = std::max({worst, std::abs(a.position[c] - b.position[c]), std::abs(a.du[c] - b.du[c]),
                          std::abs(a.dv[c] - b.dv[c])});
    }
  CHECK(worst < 1e-13);
  // The vertices' limit masks (refine --limit) likewise.
  const LimitResult masks = limit_positions(*bare, cube.level(), cube.positions, {});
  const LimitResult expected = limit_positions(*shipped, cube.level(), cube.positions, {});
  REQUIRE(masks.positions.size() == expected.positions.size());
  for (size_t i = 0; i < masks.positions.size(); ++i) CHECK(masks.positions[i] == doctest::Approx(expected.positions[i]).epsilon(1e-13));
  for (unsigned char exact : masks.exact) CHECK(exact);
}

TEST_CASE("a scheme without boundary rules: a mesh with a boundary is refused with the reason") {
  const test::Mesh grid = limit_test::bumped(test::grid(4, 4));
  const LimitSurface s(catmull_clark_without_curve(), grid.level());
  CHECK_THROWS_WITH_AS(s.evaluate(5, 0.3, 0.4, grid.positions, 3),
                       doctest::Contains("nor a curve scheme (\"curve\")"), Error);
}
