// Schemes that must be reported as failing, with the reason: rules that break the
// rotational symmetry (lambda_1 != lambda_2), weights that are not affine, the classic
// butterfly at valence 3; and schemes the papers call C1 (the modified butterfly
// everywhere, the butterfly at regular vertices).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "framework/analysis/surface/surface_analysis.h"
#include "surface_report.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

std::string catmull_clark_with(const std::string& self, const std::string& ring) {
  return R"({"name": "broken", "split": "quad", "faces": "any", "curve": "cubic-bspline", "rules": {
    "face": [{"sum": "vertices", "w": "1/k"}],
    "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
    "vertex": [{"at": "self", "w": ")" + self + R"("}, {"sum": "ring", "w": ")" + ring + R"("},
               {"sum": "faces", "new": "face", "w": "1/n^2"}]}})";
}

}  // namespace

TEST_CASE("a vertex rule that keeps too much of the old vertex: lambda_1 != lambda_2") {
  // Affine, symmetric, but the centre keeps 0.5 more of itself: the radial eigenvalue of the
  // vertex and its ring (Fourier mode 0, simple) overtakes the tangent pair (modes +-1).
  const auto file = write_temp("heavy-centre.json", catmull_clark_with("(n-2)/n + 0.5", "1/n^2 - 0.5/n"));
  const auto s = load_scheme(file.string());
  for (int n : {3, 5, 7}) {
    CAPTURE(n);
    const SurfaceAnalysis a = analyse_valence(*s, n);
    CAPTURE(a.verdict);
    CHECK(a.affine);
    CHECK(a.lambda0_one);
    CHECK_FALSE(a.subdominant_equal);
    CHECK_FALSE(a.c1);
    CHECK(a.verdict.rfind("fails: lambda_1 != lambda_2", 0) == 0);
  }
}

TEST_CASE("the verdict as a field: Fails with the failed condition, C1, Unchecked without the characteristic map") {
  // The limit layer acts on `outcome` and words its refusals with `failure`; `verdict` is the
  // same judgement in words, "fails: " + failure.
  const auto runaway = load_scheme(write_temp("runaway.json", catmull_clark_with("3", "-2/n - 1/n^2")).string());
  const SurfaceAnalysis bad = analyse_valence(*runaway, 4);
  CHECK(bad.outcome == Verdict::Fails);
  CHECK(bad.failure.rfind("lambda_0 = 1 is not the simple dominant eigenvalue", 0) == 0);
  CHECK(bad.verdict == "fails: " + bad.failure);
  const auto heavy = load_scheme(write_temp("heavy.json", catmull_clark_with("(n-2)/n + 0.5", "1/n^2 - 0.5/n")).string());
  const SurfaceAnalysis unequal = analyse_valence(*heavy, 5);
  CHECK(unequal.outcome == Verdict::Fails);
  CHECK(unequal.failure.rfind("lambda_1 != lambda_2", 0) == 0);
  const auto cc = load_scheme("catmull-clark");
  const SurfaceAnalysis good = analyse_valence(*cc, 5);
  CHECK(good.outcome == Verdict::C1);
  CHECK(good.c1);
  CHECK(good.failure.empty());
  SurfaceAnalysisOptions no_map;
  no_map.characteristic_map = false;
  LocalConfig five;
  five.valence = 5;
  const SurfaceAnalysis unchecked = analyse_configuration(*cc, five, no_map);
  CHECK(unchecked.outcome == Verdict::Unchecked);
  CHECK_FALSE(unchecked.c1);
  CHECK(unchecked.failure.empty());
  CHECK(unchecked.verdict.rfind("eigenvalue conditions hold", 0) == 0);
}

TEST_CASE("weights that do not sum to one are reported, not refined") {
  const auto file = write_temp("not-affine.json", catmull_clark_with("(n-2)/n + 0.1", "1/n^2"));
  const auto s = load_scheme(file.string());
  const SurfaceAnalysis a = analyse_valence(*s, 5);
  CAPTURE(a.verdict);
  CHECK_FALSE(a.c1);
  CHECK(a.verdict.rfind("fails: ", 0) == 0);
  CHECK(a.verdict.find("affine") != std::string::npos);
  CHECK(a.verdict.find("1.1") != std::string::npos);  // the row sum
}

TEST_CASE("butterfly: C1 at regular vertices (Dyn, Levin & Gregory 1990), not at valence 3; modified butterfly C1 everywhere") {
  const auto b = load_scheme("butterfly");
  CHECK(analyse_valence(*b, 6).c1);
  const SurfaceAnalysis three = analyse_valence(*b, 3);
  CAPTURE(three.verdict);
  CHECK_FALSE(three.c1);
  CHECK(three.verdict.rfind("fails: ", 0) == 0);
  const auto mb = load_scheme("modified-butterfly");
  for (int n = 3; n <= 12; ++n) {
    CAPTURE(n);
    const SurfaceAnalysis a = analyse_valence(*mb, n);
    CHECK(a.c1);
    CHECK(a.has_limit_mask);
    CHECK(a.limit_mask[0] == doctest::Approx(1.0));  // interpolating: the limit is the vertex
  }
}

TEST_CASE("a report for every shipped surface scheme, without errors") {
  for (const auto& listing : list_schemes()) {
    if (listing.kind != "surface") continue;
    CAPTURE(listing.name);
    const auto s = load_scheme(listing.name);
    for (int n : {3, 5}) {
      const SurfaceAnalysis a = analyse_valence(*s, n);
      CAPTURE(a.verdict);
      CHECK(a.error.empty());
      CHECK_FALSE(a.verdict.empty());
      CHECK(surface_json(a)["verdict"] == a.verdict);
    }
  }
}
