// The eigen-analysis of modified butterfly at boundary and crease vertices (docs/features.md,
// "Modified butterfly near boundaries and creases"). With the sector stencil next to a
// boundary vertex of k = n - 1 faces, the local subdivision matrix is block triangular: the
// boundary curve's block (the 4-point rule of Dyn, Levin & Gregory 1987: 1, 1/2, 1/4, ...)
// and the interior block (1/k)[cos((i - j) pi/k)] over the sector's interior ring points,
// of rank 2 with eigenvalues 1/2 (the sine vector) and 1/2 - 1/k (the cosine vector
// restricted to the interior). So lambda_1 = lambda_2 = 1/2 and, the rest of the
// neighbourhood contributing 1/4 (the 4-point rule's and the second harmonics'),
// |lambda_3| = max(1/4, 1/2 - 1/k) at k >= 2: a gap at every valence.
#include <doctest/doctest.h>

#include <algorithm>

#include "framework/analysis/surface/surface_analysis.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"

using namespace subdiv;

TEST_CASE("modified butterfly: C1 at boundary valences 2..9, lambda = 1, 1/2, 1/2, max(1/4, 1/2 - 1/k)") {
  const auto mb = load_scheme("modified-butterfly");
  for (int n = 2; n <= 9; ++n) {
    CAPTURE(n);
    LocalConfig c;
    c.valence = n;
    c.boundary = true;
    const SurfaceAnalysis a = analyse_configuration(*mb, c);
    CAPTURE(a.verdict);
    CHECK(a.c1);
    CHECK(a.lambda0_one);
    CHECK(a.lambda1 == doctest::Approx(0.5).epsilon(1e-9));
    CHECK(a.lambda2 == doctest::Approx(0.5).epsilon(1e-9));
    const int k = n - 1;
    if (k >= 2) CHECK(a.lambda3 == doctest::Approx(std::max(0.25, 0.5 - 1.0 / k)).epsilon(1e-6));
    else CHECK(a.lambda3 < 0.5);  // one face: no interior edge at the vertex
  }
}

TEST_CASE("modified butterfly: a crease vertex is C1 on both sides, sectors (3, 3), (2, 4), (1, 5), (4, 4)") {
  const auto mb = load_scheme("modified-butterfly");
  struct Split {
    int n, a;
  };
  for (const Split s : {Split{6, 3}, Split{6, 2}, Split{6, 1}, Split{8, 4}}) {
    CAPTURE(s.n);
    CAPTURE(s.a);
    LocalConfig c;
    c.valence = s.n;
    c.sharp = {0, s.a};
    const SurfaceAnalysis a = analyse_configuration(*mb, c);
    CAPTURE(a.verdict);
    // No stencil crosses the crease, so each side is judged as a boundary vertex.
    CHECK(a.verdict.rfind("C1 on both sides of the crease", 0) == 0);
    CHECK(a.c1);
  }
}
