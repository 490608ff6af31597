// The analysis request (framework/pipeline/analysis_request.h): one analysis per valence in
// the request's order, checked against the closed form of Catmull-Clark's subdominant
// eigenvalue (Doo & Sabin 1978; Ball & Storry 1988): lambda_1 = (A_n + 4) / 16 with
// A_n = 1 + cos(2 pi / n) + cos(pi / n) sqrt(2 (9 + cos(2 pi / n))); and the refusals every
// front-end shares.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "framework/pipeline/analysis_request.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/option_spelling.h"

namespace subdiv {
namespace {

double catmull_clark_subdominant(int n) {
  const double c = std::cos(2 * std::numbers::pi / n);
  const double a = 1 + c + std::cos(std::numbers::pi / n) * std::sqrt(2 * (9 + c));
  return (a + 4) / 16;
}

TEST_CASE("one analysis per valence, in the request's order, with Catmull-Clark's closed-form subdominant eigenvalue") {
  ValenceAnalysisRequest r;
  r.scheme = load_scheme("catmull-clark");
  r.valences = {7, 3, 5};
  const auto analyses = analyse_valences(r);
  REQUIRE(analyses.size() == 3);
  for (size_t i = 0; i < analyses.size(); ++i) {
    CAPTURE(r.valences[i]);
    CHECK(analyses[i].config.valence == r.valences[i]);
    REQUIRE(analyses[i].eigenvalues.size() > 1);  // sorted by modulus: lambda_0 = 1, then lambda_1
    CHECK(analyses[i].eigenvalues[1].real() == doctest::Approx(catmull_clark_subdominant(r.valences[i])).epsilon(1e-10));
  }
}

TEST_CASE("valences out of range are refused in the front-end's words; dual schemes are analysed at boundaries") {
  ValenceAnalysisRequest r;
  r.scheme = load_scheme("catmull-clark");
  r.valences = {1};
  try {
    analyse_valences(r);
    FAIL("valence 1 was accepted");
  } catch (const OptionError& e) {
    CHECK(e.spelled({{"valences", "--valence"}}) == "--valence 1: valences must lie in 2..512");
  }
  // Inside a quad mesh valence 2 is two quads sharing two edges: analysed (not C1: its
  // -1/4 matches the subdominant 1/4, docs/analysis.md).
  r.valences = {2};
  CHECK_FALSE(analyse_valences(r).front().c1);
  r.valences = {513};
  CHECK_THROWS_AS(analyse_valences(r), OptionError);
  r.valences = {};
  CHECK_THROWS_AS(analyse_valences(r), OptionError);
  r.valences = {2, 3};
  r.boundary = true;
  CHECK(analyse_valences(r).size() == 2);  // valence 2 exists at a boundary

  r.scheme = load_scheme("doo-sabin");
  r.valences = {3};
  CHECK(analyse_valences(r).front().c1);  // at the face the boundary vertex's faces become
  r.crease = true;
  CHECK_THROWS_AS(analyse_valences(r), OptionError);  // one kind of vertex per request
}

}  // namespace
}  // namespace subdiv
