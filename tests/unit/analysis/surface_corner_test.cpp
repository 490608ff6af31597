// The eigen-analysis at corner vertices (`subdiv analyze --corner`): three infinitely sharp
// ring edges cut the neighbourhood into three sectors that share only the crease curves, so
// each sector is judged on its own, as a boundary vertex tagged as a corner (its point
// stays), and the crease points refine among themselves by the crease curve's rule.
#include <doctest/doctest.h>

#include <algorithm>

#include "framework/analysis/surface/surface_analysis.h"
#include "framework/pipeline/analysis_request.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"

using namespace subdiv;

namespace {

SurfaceAnalysis corner_analysis(const char* scheme, int n) {
  ValenceAnalysisRequest r{load_scheme(scheme), {n}};
  r.corner = true;
  return analyse_valences(r).front();
}

}  // namespace

TEST_CASE("corner: three sectors of one face are C1 under Catmull-Clark, Loop and modified butterfly") {
  // A sector of one face at a corner is the regular corner patch (Catmull-Clark: the bicubic
  // B-spline with phantom points) and is C1 for the three schemes' boundary-corner rules.
  for (const char* scheme : {"catmull-clark", "loop", "modified-butterfly"}) {
    CAPTURE(scheme);
    const SurfaceAnalysis a = corner_analysis(scheme, 3);
    CAPTURE(a.verdict);
    CHECK(a.c1);
    CHECK(a.verdict.find("each of the corner's 3 sectors (sectors of 1, 1 and 1 faces") != std::string::npos);
  }
}

TEST_CASE("corner: the crease points refine as three cubic B-spline curves ending at the corner") {
  // Catmull-Clark's and Loop's crease curves are uniform cubic B-splines (1/8, 6/8, 1/8 and
  // 1/2, 1/2), whose end at a kept corner has eigenvalues 1, 1/2, 1/4, 1/8 per curve: the
  // corner's block has 1 once (the corner point) and 1/2 three times (each curve's tangent).
  for (const char* scheme : {"catmull-clark", "loop"}) {
    for (int n : {3, 6, 7}) {
      CAPTURE(scheme);
      CAPTURE(n);
      const SurfaceAnalysis a = corner_analysis(scheme, n);
      REQUIRE(a.crease_eigenvalues.size() >= 4);
      CHECK(a.crease_eigenvalues[0].real() == doctest::Approx(1.0));
      for (int i = 1; i <= 3; ++i) CHECK(std::abs(a.crease_eigenvalues[size_t(i)] - 0.5) < 1e-9);
      if (a.crease_eigenvalues.size() > 4) CHECK(std::abs(a.crease_eigenvalues[4]) < 0.5 - 1e-9);
    }
  }
}

TEST_CASE("corner: modified butterfly's sector of k >= 2 faces at a corner has 1/2 three times and is not C1") {
  // At a corner-tagged boundary vertex of k faces the local matrix is block triangular: the
  // two boundary curves, each the 4-point rule (Dyn, Levin & Gregory 1987) ending at the kept
  // corner, bring 1/2 once each, and the sector stencil's block (1/k)[cos((i - j) pi/k)]
  // (docs/features.md) brings its sine vector's 1/2: three eigenvectors of 1/2, so the tangent
  // plane at the corner depends on the data (Reif's condition fails) - the fold that Biermann,
  // Levin & Zorin 2000 report near corners of the standard rules.
  const auto mb = load_scheme("modified-butterfly");
  for (int k = 2; k <= 5; ++k) {
    CAPTURE(k);
    LocalConfig c;
    c.valence = k + 1;
    c.boundary = true;
    c.corner = true;
    const SurfaceAnalysis a = analyse_configuration(*mb, c);
    CHECK(a.lambda1 == doctest::Approx(0.5).epsilon(1e-9));
    CHECK(a.lambda2 == doctest::Approx(0.5).epsilon(1e-9));
    CHECK(a.lambda3 == doctest::Approx(0.5).epsilon(1e-9));
    CHECK_FALSE(a.c1);
  }
  // So a corner with a sector of two faces is reported with that sector.
  const SurfaceAnalysis a = corner_analysis("modified-butterfly", 4);
  CAPTURE(a.verdict);
  CHECK_FALSE(a.c1);
  CHECK(a.verdict.find("the sector of 2 faces (boundary corner-tagged valence 3)") != std::string::npos);
}

TEST_CASE("corner: a request is refused below valence 3 and together with boundary or crease") {
  ValenceAnalysisRequest r{load_scheme("catmull-clark"), {2, 5}};
  r.corner = true;
  CHECK_THROWS_WITH_AS(analyse_valences(r), doctest::Contains("valence 3 or more"), Error);
  r.valences = {5};
  r.crease = true;
  CHECK_THROWS_WITH_AS(analyse_valences(r), doctest::Contains("make one request for each"), Error);
}
