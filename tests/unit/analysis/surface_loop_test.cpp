// Loop at extraordinary vertices against Loop 1987 and Hoppe et al. 1994: the subdominant eigenvalue
// 3/8 + cos(2 pi/n)/4 for both Loop's and Warren's beta_n, and the limit point
// gamma_n V + (1 - gamma_n) mean(V_i). The gamma_n = 3/(11 - 8 beta_bar_n) comes from
// the 2x2 block [[beta_bar, 1 - beta_bar], [3/8, 5/8]] of the vertex and its ring, whose
// left eigenvector of 1 is (3, 8 (1 - beta_bar))/(11 - 8 beta_bar): it holds for any centre
// weight beta_bar = 1 - n beta_n, so for Warren's beta too (3/(3 + 8 n beta_n): 2/5 for
// n = 3, 1/2 for n > 3). Loop 1987 states it with his beta_bar = 3/8 + (3/8 + cos/4)^2.
#include <doctest/doctest.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

double loop_beta(int n) {
  const double t = 3.0 / 8 + std::cos(2 * kPi / n) / 4;
  return (5.0 / 8 - t * t) / n;
}
double warren_beta(int n) { return n == 3 ? 3.0 / 16 : 3.0 / (8 * n); }

}  // namespace

TEST_CASE("Loop: subdominant eigenvalue 3/8 + cos(2 pi/n)/4 for both beta variants, n = 3..12") {
  for (const char* variant : {"loop", "warren"}) {
    const auto loop = load_scheme("loop", {{"beta", variant}});
    for (int n = 3; n <= 12; ++n) {
      CAPTURE(variant);
      CAPTURE(n);
      const SurfaceAnalysis a = analyse_valence(*loop, n);
      REQUIRE(a.error.empty());
      const double lambda = 3.0 / 8 + std::cos(2 * kPi / n) / 4;
      CHECK(std::abs(a.eigenvalues[1].real() - lambda) < 1e-12);
      CHECK(std::abs(a.eigenvalues[2].real() - lambda) < 1e-12);
      CHECK(a.minimal_size == n + 1);  // the vertex and its ring
      // The ring's other eigenvalue, 5/8 - n beta_n: lambda^2 for Loop's beta (that is how
      // Loop's or Warren's beta_n is chosen), 1/4 for Warren's (n > 3) and 1/16 (n = 3).
      const double beta = std::string(variant) == "loop" ? loop_beta(n) : warren_beta(n);
      bool found = false;
      for (auto z : a.minimal_eigenvalues) found |= std::abs(z - (5.0 / 8 - n * beta)) < 1e-12;
      CHECK(found);
      if (std::string(variant) == "loop") CHECK(5.0 / 8 - n * beta == doctest::Approx(lambda * lambda).epsilon(1e-12));
      CHECK(a.c1);
    }
  }
}

TEST_CASE("Loop: limit point gamma_n V + (1 - gamma_n) mean V_i (Loop 1987), both variants") {
  for (const char* variant : {"loop", "warren"}) {
    const auto loop = load_scheme("loop", {{"beta", variant}});
    for (int n = 3; n <= 12; ++n) {
      CAPTURE(variant);
      CAPTURE(n);
      const double beta = std::string(variant) == "loop" ? loop_beta(n) : warren_beta(n);
      const double beta_bar = 1 - n * beta;  // the centre weight of the vertex rule
      const double gamma = 3 / (11 - 8 * beta_bar);
      if (std::string(variant) == "loop") {
        const double t = 3.0 / 8 + std::cos(2 * kPi / n) / 4;
        CHECK(gamma == doctest::Approx(3 / (11 - 8 * (3.0 / 8 + t * t))).epsilon(1e-14));  // Loop's form
      } else {
        CHECK(gamma == doctest::Approx(n == 3 ? 0.4 : 0.5).epsilon(1e-14));
      }
      const RandomPatch p = random_patch(PatchCells::Triangles, n, 100u + unsigned(n));
      const LimitResult r = limit_positions(*loop, p.level, p.positions);
      const auto ring = ring_neighbours(p.level, 0);
      Vec3 expected;
      for (int i = 0; i < 3; ++i) {
        double mean = 0;
        for (Index q : ring) mean += at(p.positions, q)[size_t(i)] / n;
        expected[size_t(i)] = gamma * p.positions[size_t(i)] + (1 - gamma) * mean;
      }
      CHECK(distance(at(r.positions, 0), expected) < 1e-12);
    }
  }
}
