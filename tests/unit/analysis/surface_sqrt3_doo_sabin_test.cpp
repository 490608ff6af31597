// sqrt(3) against Kobbelt 2000: the spectrum of the aligned two-step operator R S^2 on
// the vertex and its ring is (1/9)[9, (2 - 3 alpha_n)^2, 2 + 2 cos(2 pi k/n), k = 1..n-1],
// and alpha_n = (4 - 2 cos(2 pi/n))/9 makes (2 - 3 alpha_n)^2/9 the square of the
// subdominant (2 + 2 cos(2 pi/n))/9.
// Doo-Sabin against Doo & Sabin 1978: the circulant S of an N-gon's new points has the
// spectrum diag(1, 1/2, 1/4, ..., 1/4, 1/2); with the points around it (the ring's
// block: 1/16, 1/8, 1/8, 1/4, 1/4) nothing exceeds 1/4, so 1 > 1/2 = 1/2 > 1/4. Doo & Sabin
// 1978: the limit surface interpolates each face's centroid (the F-face keeps it).
#include <doctest/doctest.h>

#include <algorithm>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

std::vector<double> sorted_real(const std::vector<std::complex<double>>& ev) {
  std::vector<double> out;
  for (auto z : ev) {
    CHECK(std::abs(z.imag()) < 1e-10);
    out.push_back(z.real());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("sqrt3: spectrum of R S^2 on the 1-ring is Kobbelt's, n = 3..12") {
  const auto s3 = load_scheme("sqrt3");
  for (int n = 3; n <= 12; ++n) {
    CAPTURE(n);
    const SurfaceAnalysis a = analyse_valence(*s3, n);
    REQUIRE(a.error.empty());
    CHECK(a.steps == 2);
    REQUIRE(a.minimal_size == n + 1);
    const double alpha = (4 - 2 * std::cos(2 * kPi / n)) / 9;
    std::vector<double> seed{1.0, (2 - 3 * alpha) * (2 - 3 * alpha) / 9};
    for (int k = 1; k < n; ++k) seed.push_back((2 + 2 * std::cos(2 * kPi * k / n)) / 9);
    std::sort(seed.begin(), seed.end());
    const std::vector<double> got = sorted_real(a.minimal_eigenvalues);
    REQUIRE(got.size() == seed.size());
    for (size_t i = 0; i < seed.size(); ++i) CHECK(std::abs(got[i] - seed[i]) < 1e-12);
    // The subdominant of the analysed (wider) neighbourhood is Kobbelt's too.
    const double lambda = (2 + 2 * std::cos(2 * kPi / n)) / 9;
    CHECK(std::abs(a.lambda1 - lambda) < 1e-12);
    CHECK(a.subdominant_equal);
    // Kobbelt's choice of alpha_n: (2 - 3 alpha)^2 / 9 = lambda^2.
    CHECK((2 - 3 * alpha) * (2 - 3 * alpha) / 9 == doctest::Approx(lambda * lambda).epsilon(1e-12));
    CHECK(a.c1);
    // The limit point, from the 2x2 block S: the vertex and the mean of its ring map by
    // [[1 - alpha, alpha], [1/3, 2/3]] (new ring points (P + P_i + P_{i+1})/3), whose left
    // eigenvector of 1 gives the centre the weight 1/(1 + 3 alpha_n).
    REQUIRE(a.has_limit_mask);
    CHECK(std::abs(a.limit_mask[0] - 1 / (1 + 3 * alpha)) < 1e-12);
    for (int j = 1; j <= n; ++j) CHECK(std::abs(a.limit_mask[size_t(j)] - 3 * alpha / (1 + 3 * alpha) / n) < 1e-12);
  }
}

TEST_CASE("Doo-Sabin: 1, 1/2, 1/2, 1/4 ... at N-gon faces, N = 3..12 (Doo & Sabin 1978)") {
  const auto ds = load_scheme("doo-sabin");
  for (int n = 3; n <= 12; ++n) {
    CAPTURE(n);
    const SurfaceAnalysis a = analyse_valence(*ds, n);
    REQUIRE(a.error.empty());
    CHECK(a.config.centre == CentreKind::Face);
    REQUIRE(a.minimal_size == n);  // the face's own corners
    std::vector<double> seed{1.0, 0.5, 0.5};
    for (int k = 3; k < n; ++k) seed.push_back(0.25);
    std::sort(seed.begin(), seed.end());
    const std::vector<double> got = sorted_real(a.minimal_eigenvalues);
    REQUIRE(got.size() == seed.size());
    for (size_t i = 0; i < seed.size(); ++i) CHECK(std::abs(got[i] - seed[i]) < 1e-12);
    CHECK(std::abs(a.lambda1 - 0.5) < 1e-12);
    CHECK(std::abs(a.lambda2 - 0.5) < 1e-12);
    for (size_t i = 3; i < a.eigenvalues.size(); ++i) CHECK(std::abs(a.eigenvalues[i]) < 0.25 + 1e-6);  // J2(1/4) blocks: ~1e-8 round-off
    CHECK(a.c1);  // Doo & Sabin 1978: the limit surface is C1
    // The limit mask of a face: its centroid.
    REQUIRE(a.has_limit_mask);
    for (size_t i = 0; i < size_t(n); ++i) CHECK(a.limit_mask[i] == doctest::Approx(1.0 / n).epsilon(1e-12));
  }
}

TEST_CASE("Doo-Sabin: a vertex's limit is the centroid of the face it becomes (Doo & Sabin 1978)") {
  // One step turns vertex v into its V-face, whose centroid every later F-face keeps.
  for (const auto& mesh : {test::cube(), test::pyramid()}) {
    const auto ds = load_scheme("doo-sabin");
    RefineOptions o;
    o.levels = 2;
    const Hierarchy h = refine(*ds, mesh.level(), o);
    const auto p1 = h.stencils[0].apply(mesh.positions, 3);
    const auto p2 = h.stencils[1].apply(p1, 3);
    for (int l = 0; l < 2; ++l) {
      const auto& P = l == 0 ? mesh.positions : p1;
      const auto& C = l == 0 ? p1 : p2;
      LimitOptions lo;
      lo.first_step = l;
      const LimitResult r = limit_positions(*ds, h.levels[size_t(l)], P, lo);
      const Level& parent = h.levels[size_t(l)];
      const Level& child = h.levels[size_t(l) + 1];
      const ChildOrigins& o0 = h.origins[size_t(l)];
      for (Index v = 0; v < parent.vertex_count; ++v) {
        CAPTURE(v);
        Vec3 centroid{0, 0, 0};
        int count = 0;
        for (Index c = 0; c < child.vertex_count; ++c)
          if (parent.face(o0.parent[size_t(c)])[o0.local[size_t(c)]] == v) {
            const Vec3 q = at(C, c);
            for (int i = 0; i < 3; ++i) centroid[size_t(i)] += q[size_t(i)];
            ++count;
          }
        REQUIRE(count == parent.valence(v));
        for (double& x : centroid) x /= count;
        CHECK(distance(at(r.positions, v), centroid) < 1e-13);
        CHECK(r.exact[size_t(v)] == 1);
      }
    }
  }
}
