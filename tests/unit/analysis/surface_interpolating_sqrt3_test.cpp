// Interpolating sqrt(3) (Labsik & Greiner 2000): around a vertex of valence K the face point
// of face i is the vertex's stencil, ring point j weighted (a^2 + 2a cos((2j+1) pi/K) +
// 2a^2 cos((4j+2) pi/K))/K with a = (2/3) cos(pi/K). Its first Fourier component is a: the
// face points' frequency-1 part is a times the ring's. Two steps (one period of the split,
// which turns the ring by half a face) map the ring to the face points of the face points,
// so the subdominant eigenvalue of S^2 is a^2 (1/9 at K = 3, 2/9 at K = 4), and 1/3 at the
// regular valence, where sqrt(3) shrinks the mesh by 1/sqrt(3) per step.
#include <doctest/doctest.h>

#include <cmath>

#include "framework/analysis/surface/surface_analysis.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;

TEST_CASE("interpolating sqrt3: subdominant eigenvalue of S^2 is ((2/3) cos(pi/K))^2, C1 for K = 3..12") {
  const auto scheme = load_scheme("interpolating-sqrt3");
  for (int n = 3; n <= 12; ++n) {
    CAPTURE(n);
    const SurfaceAnalysis a = analyse_valence(*scheme, n);
    REQUIRE(a.error.empty());
    CHECK(a.steps == 2);
    const double c = 2.0 / 3 * std::cos(test::kPi / n);
    const double lambda = n == 6 ? 1.0 / 3 : c * c;
    CHECK(a.lambda1 == doctest::Approx(lambda).epsilon(1e-10));
    CHECK(a.subdominant_equal);
    CHECK(a.c1);
  }
}
