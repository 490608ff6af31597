// Valences above 64: the local subdivision matrix split by the sector rotation into one
// Fourier block per frequency (rotation_blocks.h; Doo & Sabin 1978, Ball & Storry 1988,
// Stam 1998). Checked against a dense eigen-decomposition (random block-circulant matrices,
// and the analysis of small valences both ways), against the closed forms of the subdominant
// eigenvalue (Catmull-Clark: Doo & Sabin 1978 / Ball & Storry 1988; Loop 1987) and of the
// limit point (Halstead, Kass & DeRose 1993; Loop 1987) at valences 65, 100 and 360.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/rotation_blocks.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// Catmull-Clark's subdominant eigenvalue at valence n (Ball & Storry 1988; Halstead, Kass &
// DeRose 1993's (4 + A_n)/16).
double catmull_clark_lambda(int n) {
  const double c = std::cos(2 * kPi / n);
  return (5 + c + std::cos(kPi / n) * std::sqrt(2 * (9 + c))) / 16;
}
double loop_lambda(int n) { return 3.0 / 8 + std::cos(2 * kPi / n) / 4; }

// Every eigenvalue of `a` has one of `b` within tol, and the counts agree.
bool same_spectrum(std::vector<std::complex<double>> a, std::vector<std::complex<double>> b, double tol) {
  if (a.size() != b.size()) return false;
  for (const auto& z : a) {
    auto best = std::min_element(b.begin(), b.end(), [&](auto x, auto y) { return std::abs(x - z) < std::abs(y - z); });
    if (best == b.end() || std::abs(*best - z) > tol) return false;
    b.erase(best);
  }
  return true;
}

// A random matrix over 1 fixed label and `orbits` orbits of n labels (label 1 + t n + s is
// orbit t turned s times) that commutes with the turn: S[turn i][turn j] = S[i][j]. Rows sum
// to 1, so 1 is an eigenvalue with the constant right eigenvector.
struct Circulant {
  Eigen::MatrixXd dense;
  std::vector<int> turn;
};
Circulant random_circulant(int n, int orbits, unsigned seed) {
  const int m = 1 + orbits * n;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Circulant c;
  c.turn.resize(size_t(m));
  c.turn[0] = 0;
  for (int t = 0; t < orbits; ++t)
    for (int s = 0; s < n; ++s) c.turn[size_t(1 + t * n + s)] = 1 + t * n + (s + 1) % n;
  c.dense = Eigen::MatrixXd::Zero(m, m);
  // Choose the rows of the fixed label and of each orbit's first label, then turn them.
  for (int j = 0; j < orbits; ++j) {
    const double w = u(rng);
    for (int s = 0; s < n; ++s) c.dense(0, 1 + j * n + s) = w;
  }
  c.dense(0, 0) = u(rng);
  for (int t = 0; t < orbits; ++t) {
    Eigen::VectorXd row = Eigen::VectorXd::Zero(m);
    for (int j = 0; j < m; ++j) row(j) = u(rng) < 0.5 ? u(rng) : 0.0;
    for (int s = 0; s < n; ++s) {
      Eigen::VectorXd turned = Eigen::VectorXd::Zero(m);
      for (int j = 0; j < m; ++j) {
        int image = j;
        for (int k = 0; k < s; ++k) image = c.turn[size_t(image)];
        turned(image) = row(j);
      }
      c.dense.row(1 + t * n + s) = turned.transpose();
    }
  }
  for (int i = 0; i < m; ++i) c.dense.row(i) /= c.dense.row(i).sum();
  return c;
}

LocalRows rows_of(const Eigen::MatrixXd& s) {
  LocalRows r(static_cast<size_t>(s.rows()));
  for (Eigen::Index i = 0; i < s.rows(); ++i)
    for (Eigen::Index j = 0; j < s.cols(); ++j)
      if (s(i, j) != 0.0) r[size_t(i)].emplace_back(int(j), s(i, j));
  return r;
}

SurfaceAnalysisOptions fast() {
  SurfaceAnalysisOptions o;
  o.characteristic_map = false;
  return o;
}

}  // namespace

TEST_CASE("rotation blocks: the spectrum and null spaces of a random block-circulant matrix are the dense ones") {
  for (int n : {5, 6, 9}) {
    CAPTURE(n);
    const Circulant c = random_circulant(n, 3, 7u + unsigned(n));
    const auto blocks = RotationBlocks::split(rows_of(c.dense), c.turn, n);
    REQUIRE(blocks);
    CHECK(blocks->size() == int(c.dense.rows()));
    Eigen::EigenSolver<Eigen::MatrixXd> dense(c.dense, false);
    const std::vector<std::complex<double>> expected(dense.eigenvalues().data(),
                                                     dense.eigenvalues().data() + dense.eigenvalues().size());
    CHECK(same_spectrum(blocks->eigenvalues(), expected, 1e-11));
    // 1 is simple: the constant right eigenvector, and a left one l with l S = l.
    const Eigen::MatrixXd r = blocks->right_null(1.0, 1e-9), l = blocks->left_null(1.0, 1e-9);
    REQUIRE(r.cols() == 1);
    REQUIRE(l.cols() == 1);
    CHECK((r.col(0).array() - r(0, 0)).abs().maxCoeff() < 1e-12);
    CHECK((c.dense.transpose() * l.col(0) - l.col(0)).norm() < 1e-12);
    // Every real eigenvalue's eigenvectors, right and left, orthonormal.
    for (const auto& z : expected) {
      if (std::abs(z.imag()) > 1e-9) continue;
      const Eigen::MatrixXd right = blocks->right_null(z.real(), 1e-9), left = blocks->left_null(z.real(), 1e-9);
      CHECK(right.cols() >= 1);
      CHECK(right.cols() == left.cols());
      CHECK((c.dense * right - z.real() * right).norm() < 1e-10);
      CHECK((left.transpose() * c.dense - z.real() * left.transpose()).norm() < 1e-10);
      CHECK((right.transpose() * right - Eigen::MatrixXd::Identity(right.cols(), right.cols())).norm() < 1e-12);
    }
  }
}

TEST_CASE("rotation blocks: refused when the matrix does not commute with the turn, or the turn is no rotation") {
  const int n = 6;
  Circulant c = random_circulant(n, 2, 3u);
  CHECK(RotationBlocks::split(rows_of(c.dense), c.turn, n));
  CHECK_FALSE(RotationBlocks::split(rows_of(c.dense), c.turn, 3));  // orbits of 6, not 3
  Eigen::MatrixXd broken = c.dense;
  broken(2, 5) += 1e-6;  // one weight off: no longer symmetric
  CHECK_FALSE(RotationBlocks::split(rows_of(broken), c.turn, n));
  std::vector<int> not_a_permutation = c.turn;
  not_a_permutation[1] = not_a_permutation[2];
  CHECK_FALSE(RotationBlocks::split(rows_of(c.dense), not_a_permutation, n));
}

TEST_CASE("small valences analysed through the rotation blocks give the dense analysis' results") {
  for (const char* name : {"catmull-clark", "loop"}) {
    const auto scheme = load_scheme(name);
    for (int n : {3, 5, 8}) {
      CAPTURE(name);
      CAPTURE(n);
      SurfaceAnalysisOptions blocked;
      blocked.fourier_above = 0;
      const SurfaceAnalysis a = analyse_valence(*scheme, n), b = analyse_valence(*scheme, n, blocked);
      REQUIRE(a.error.empty());
      REQUIRE(b.error.empty());
      CHECK(b.verdict == a.verdict);
      // Defective eigenvalues (Jordan blocks of 0) come out of a dense solver only to about
      // eps^(1/k); the dominant part of the spectrum to round-off.
      CHECK(same_spectrum(a.eigenvalues, b.eigenvalues, 1e-6));
      CHECK(same_spectrum(a.minimal_eigenvalues, b.minimal_eigenvalues, 1e-6));
      for (size_t i = 0; i < 4; ++i) CHECK(std::abs(a.eigenvalues[i] - b.eigenvalues[i]) < 1e-12);
      REQUIRE(a.limit_mask.size() == b.limit_mask.size());
      for (size_t i = 0; i < a.limit_mask.size(); ++i) CHECK(std::abs(a.limit_mask[i] - b.limit_mask[i]) < 1e-13);
      REQUIRE(a.direction_masks.size() == b.direction_masks.size());
      for (size_t q = 0; q < a.direction_masks.size(); ++q) {
        REQUIRE(a.direction_masks[q].size() == b.direction_masks[q].size());
        for (size_t i = 0; i < a.direction_masks[q].size(); ++i)
          CHECK(std::abs(a.direction_masks[q][i] - b.direction_masks[q][i]) < 1e-12);
      }
      CHECK(b.characteristic_map.injective == a.characteristic_map.injective);
    }
  }
}

TEST_CASE("subdominant eigenvalues at valences 65, 100, 360: Catmull-Clark's closed form and Loop's 3/8 + cos(2 pi/n)/4") {
  const auto cc = load_scheme("catmull-clark"), loop = load_scheme("loop");
  for (int n : {65, 100, 360}) {
    CAPTURE(n);
    const SurfaceAnalysisOptions o = n == 65 ? SurfaceAnalysisOptions{} : fast();
    const SurfaceAnalysis a = analyse_valence(*cc, n, o), b = analyse_valence(*loop, n, o);
    CAPTURE(a.verdict);
    CAPTURE(b.verdict);
    REQUIRE(a.error.empty());
    REQUIRE(b.error.empty());
    CHECK(a.size == 6 * n + 1);  // the 2-ring: centre, and 6 points per sector
    CHECK(std::abs(a.lambda1 - catmull_clark_lambda(n)) < 1e-12);
    CHECK(std::abs(b.lambda1 - loop_lambda(n)) < 1e-12);
    for (const SurfaceAnalysis* r : {&a, &b}) {
      CHECK(std::abs(r->eigenvalues[0] - 1.0) < 1e-12);
      CHECK(r->lambda1 == r->lambda2);
      CHECK(r->subdominant_equal);
      CHECK(r->subdominant_dominates);
      CHECK(r->has_limit_mask);
      CHECK(r->direction_masks.size() == size_t(n));
    }
    if (n == 65) {
      CHECK(a.verdict == "C1 at valence 65");
      CHECK(b.verdict == "C1 at valence 65");
    }
  }
}

TEST_CASE("limit point and normal at valence 360: Halstead, Kass & DeRose's (n^2 v + 4 sum e + sum f)/(n(n + 5)), Loop's gamma_n") {
  const int n = 360;
  {
    const auto cc = load_scheme("catmull-clark");
    const RandomPatch p = random_patch(PatchCells::Quads, n, 5u, 3);
    const LimitResult r = limit_positions(*cc, p.level, p.positions);
    const auto e = ring_neighbours(p.level, 0);
    const auto f = face_diagonals(p.level, 0);
    REQUIRE(int(e.size()) == n);
    const CatmullClarkLimit expected = catmull_clark_limit(p.positions, 0, e, f);
    CHECK(r.exact[0] == 1);
    CHECK(distance(at(r.positions, 0), expected.point) < 1e-12);
    CHECK(r.normal_exact[0] == 1);
    CHECK(dot(expected.normal, at(r.normals, 0)) > 1 - 1e-12);
  }
  {
    // Loop 1987: gamma_n v + (1 - gamma_n) mean(e), gamma_n = 3/(11 - 8 beta_bar), beta_bar = 3/8 + lambda^2.
    const auto loop = load_scheme("loop");
    const RandomPatch p = random_patch(PatchCells::Triangles, n, 6u, 3);
    const LimitResult r = limit_positions(*loop, p.level, p.positions);
    const auto ring = ring_neighbours(p.level, 0);
    const double t = loop_lambda(n);
    const double gamma = 3 / (11 - 8 * (3.0 / 8 + t * t));
    Vec3 expected;
    for (int i = 0; i < 3; ++i) {
      double mean = 0;
      for (Index q : ring) mean += at(p.positions, q)[size_t(i)] / n;
      expected[size_t(i)] = gamma * p.positions[size_t(i)] + (1 - gamma) * mean;
    }
    CHECK(r.exact[0] == 1);
    CHECK(distance(at(r.positions, 0), expected) < 1e-12);
  }
}

TEST_CASE("above valence 64 a boundary or crease vertex is refused naming its valence and the limit") {
  const auto cc = load_scheme("catmull-clark");
  LocalConfig c;
  c.valence = 65;
  c.boundary = true;
  const SurfaceAnalysis a = analyse_configuration(*cc, c, fast());
  CHECK(a.verdict.find("boundary valence 65 cannot be analysed: above valence 64") != std::string::npos);
  const SurfaceAnalysis b = analyse_valence(*cc, 513, fast());
  CHECK(b.verdict.find("valence 513 cannot be analysed: valences 2..512") != std::string::npos);
}
