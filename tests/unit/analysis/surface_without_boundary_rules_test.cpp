// A scheme written without boundary rules (no "curve", no crease rule) is analysed at
// interior vertices: the synthetic patch's rim takes stand-in rules (analysis/surface/
// rim_rules.h), which must not reach the invariant neighbourhood. Catmull-Clark's rules
// without a curve give Catmull-Clark's spectrum (the closed form of Doo & Sabin 1978, Ball &
// Storry 1988); a boundary or crease vertex still needs the scheme's own rules and fails
// with the reason.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "framework/analysis/surface/surface_analysis.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;

namespace {

constexpr const char* kNoCurve = R"({"name": "cc-no-curve", "split": "quad",
  "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
            "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
            "vertex": [{"at": "self", "w": "(n-2)/n"}, {"sum": "ring", "w": "1/n^2"},
                       {"sum": "faces", "new": "face", "w": "1/n^2"}]}})";

// Catmull-Clark's subdominant eigenvalue at valence n (Doo & Sabin 1978; Ball & Storry 1988).
double catmull_clark_lambda(int n) {
  const double c = std::cos(2 * std::numbers::pi / n);
  return (5 + c + std::cos(std::numbers::pi / n) * std::sqrt(2 * (9 + c))) / 16;
}

}  // namespace

TEST_CASE("a scheme without boundary rules is analysed at interior vertices: Catmull-Clark's spectrum") {
  const auto scheme = load_scheme(test::write_temp("cc-no-curve.json", kNoCurve).string());
  REQUIRE(scheme->curve == nullptr);
  const auto shipped = load_scheme("catmull-clark");
  for (int n : {3, 4, 5, 7}) {
    CAPTURE(n);
    const SurfaceAnalysis a = analyse_valence(*scheme, n);
    CAPTURE(a.verdict);
    REQUIRE(a.error.empty());
    CHECK(a.c1);
    CHECK(a.lambda1 == doctest::Approx(catmull_clark_lambda(n)).epsilon(1e-12));
    // The whole spectrum equals the shipped scheme's, whose rim has Catmull-Clark's own rules.
    const SurfaceAnalysis b = analyse_valence(*shipped, n);
    REQUIRE(a.eigenvalues.size() == b.eigenvalues.size());
    for (size_t i = 0; i < a.eigenvalues.size(); ++i) CHECK(std::abs(a.eigenvalues[i] - b.eigenvalues[i]) < 1e-12);
  }
}

TEST_CASE("a scheme without boundary rules: boundary and crease vertices fail with the reason") {
  const auto scheme = load_scheme(test::write_temp("cc-no-curve.json", kNoCurve).string());
  LocalConfig boundary;
  boundary.valence = 3, boundary.boundary = true;
  LocalConfig crease;
  crease.valence = 4, crease.sharp = {0, 2};
  for (const LocalConfig& c : {boundary, crease}) {
    const SurfaceAnalysis a = analyse_configuration(*scheme, c);
    CAPTURE(a.verdict);
    CHECK_FALSE(a.c1);
    CHECK(a.error.find("curve scheme (\"curve\")") != std::string::npos);
  }
}
