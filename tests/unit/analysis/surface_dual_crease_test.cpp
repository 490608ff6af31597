// Dual schemes next to boundaries and creases (docs/features.md, "Creases in dual schemes";
// docs/analysis.md). The closed forms come from the rules, not from the engine:
//
// - Along a boundary or crease the new points are Chaikin's (Chaikin 1974: 3/4 a + 1/4 b and
//   1/4 a + 3/4 b on each segment), and they depend on the crease polygon only. On the
//   crease points of the analysed ring (a segment and m - 2 neighbours) Chaikin's local
//   matrix has the segment's block [[3/4, 1/4], [1/4, 3/4]] (eigenvalues 1, 1/2), 1/4 on the
//   diagonal for each first neighbour (its point 1/4 p_-1 + 3/4 p_0 weighs it by 1/4) and 0
//   for points further out: spectrum 1, 1/2, 1/4, 1/4, 0, ...
// - At the regular boundary (two quads at the vertex) Doo-Sabin is a tensor product. Across
//   the boundary: the boundary row stays on the boundary, the next row is 1/4 c + 3/4 p_1
//   (Doo-Sabin's regular weights 9/16, 3/16, 3/16, 1/16 are (3/4, 1/4) x (3/4, 1/4)), the row
//   after 3/4 p_1 + 1/4 p_2: the matrix [[1, 0, 0], [1/4, 3/4, 0], [0, 3/4, 1/4]], spectrum
//   1, 3/4, 1/4. Along it, Chaikin's 1, 1/2, 1/4, 1/4. S is their Kronecker product, so its
//   spectrum is the products (Doo & Sabin 1978's biquadratic B-spline, with Nasri 1987's
//   boundary).
// - At the regular crease (valence 4, two quads on each side) the across matrix on
//   (p_-1, c, p_1, p_2) is 1, 3/4, 3/4, 1/4: the two sides are independent given the crease.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <string>
#include <vector>

#include "framework/analysis/surface/dual_sector_patch.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"

using namespace subdiv;

namespace {

std::vector<double> products(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out;
  for (double x : a)
    for (double y : b) out.push_back(x * y);
  std::sort(out.rbegin(), out.rend());
  return out;
}

std::vector<double> real_parts(const std::vector<std::complex<double>>& ev) {
  std::vector<double> out;
  for (const auto& z : ev) {
    CHECK(std::abs(z.imag()) < 1e-9);
    out.push_back(z.real());
  }
  std::sort(out.rbegin(), out.rend());
  return out;
}

void check_same(const std::vector<double>& got, const std::vector<double>& want) {
  REQUIRE(got.size() == want.size());
  for (size_t i = 0; i < got.size(); ++i) CHECK(got[i] == doctest::Approx(want[i]).epsilon(1e-9));
}

LocalConfig dual_config(int valence, bool boundary, std::vector<int> sharp) {
  LocalConfig c;
  c.centre = CentreKind::Face;
  c.valence = valence;
  c.boundary = boundary;
  c.sharp = std::move(sharp);
  return c;
}

// Whether a vertex of the patch lies on the boundary or on an infinitely sharp edge.
bool on_crease(const Level& L, Index v) {
  for (Index e : L.ring_edges(v))
    if (L.edge_on_boundary(e) || L.edge_sharp(e) >= 1.f) return true;
  return false;
}

}  // namespace

TEST_CASE("dual boundary: Doo-Sabin at the regular boundary is Chaikin along x (1, 3/4, 1/4) across") {
  const auto scheme = load_scheme("doo-sabin");
  const SurfaceAnalysis a = analyse_configuration(*scheme, dual_config(3, true, {}));
  REQUIRE(a.error.empty());
  CHECK(a.size == 12);  // the boundary quad's 1-ring: 4 along x 3 across
  check_same(real_parts(a.eigenvalues), products({1, 0.5, 0.25, 0.25}, {1, 0.75, 0.25}));
  CHECK(a.lambda1 == doctest::Approx(0.75));
  CHECK(a.lambda2 == doctest::Approx(0.5));  // the boundary curve's
  CHECK(a.c1);
}

TEST_CASE("dual crease: Doo-Sabin at the regular crease is Chaikin along x (1, 3/4, 3/4, 1/4) across") {
  const auto scheme = load_scheme("doo-sabin");
  const SurfaceAnalysis a = analyse_configuration(*scheme, dual_config(4, false, {0, 2}));
  REQUIRE(a.error.empty());
  CHECK(a.size == 16);
  check_same(real_parts(a.eigenvalues), products({1, 0.5, 0.25, 0.25}, {1, 0.75, 0.75, 0.25}));
  CHECK(a.c1);  // both sides C1, each as at the regular boundary
}

TEST_CASE("dual crease and boundary: the crease points refine among themselves with Chaikin's spectrum") {
  for (const char* name : {"doo-sabin", "doo-sabin-centroid"}) {
    CAPTURE(name);
    const auto scheme = load_scheme(name);
    std::vector<LocalConfig> configs;
    for (int n = 3; n <= 6; ++n) configs.push_back(dual_config(n, true, {}));
    for (int n = 4; n <= 7; ++n) configs.push_back(dual_config(n, false, {0, n / 2}));
    for (const LocalConfig& c : configs) {
      CAPTURE(c.describe());
      const Patch p = make_dual_sector_patch(*scheme, c, 8, {});
      const SurfaceAnalysis a = analyse_patch(*scheme, p, c);
      REQUIRE(a.error.empty());
      std::vector<int> crease;
      for (int i = 0; i < a.size; ++i)
        if (on_crease(p.level, a.label_vertices[size_t(i)])) crease.push_back(i);
      REQUIRE(crease.size() >= 4);
      const int m = int(crease.size());
      Eigen::MatrixXd block(m, m);
      for (int i = 0; i < m; ++i) {
        double inside = 0;
        for (int j = 0; j < m; ++j) inside += block(i, j) = a.matrix[size_t(crease[size_t(i)])][size_t(crease[size_t(j)])];
        CHECK(inside == doctest::Approx(1.0).epsilon(1e-12));  // a crease row reads crease points only
      }
      std::vector<double> want{1, 0.5, 0.25, 0.25};
      want.resize(size_t(m), 0.0);
      Eigen::EigenSolver<Eigen::MatrixXd> solver(block, false);
      std::vector<std::complex<double>> ev(solver.eigenvalues().data(), solver.eigenvalues().data() + m);
      check_same(real_parts(ev), want);
    }
  }
}

TEST_CASE("dual boundary and crease: Doo-Sabin is C1 at boundary valences 3..7 and crease valences 4..7") {
  const auto scheme = load_scheme("doo-sabin");
  for (int n = 3; n <= 7; ++n) {
    CAPTURE(n);
    CHECK(analyse_configuration(*scheme, dual_config(n, true, {})).c1);
    if (n >= 4) CHECK(analyse_configuration(*scheme, dual_config(n, false, {0, n / 2})).c1);
  }
  // A sector of one face has no face of its own; a corner collapses to a point.
  const SurfaceAnalysis one = analyse_configuration(*scheme, dual_config(3, false, {0, 1}));
  CHECK(one.verdict.find("a sector of 1 face") != std::string::npos);
  const SurfaceAnalysis corner = analyse_configuration(*scheme, dual_config(2, true, {}));
  CHECK(!corner.c1);
}

TEST_CASE("crease analysis: judged by its sides where S is block triangular across the crease") {
  // Catmull-Clark's crease rules are its boundary rules and no smooth stencil crosses the
  // crease, so each side is a boundary; so are modified butterfly's, whose edges next to a
  // crease vertex take that end's sector stencil (docs/features.md), which stays on its side.
  LocalConfig c;
  c.valence = 4;
  c.sharp = {0, 2};
  const SurfaceAnalysis cc = analyse_configuration(*load_scheme("catmull-clark"), c);
  CHECK(cc.verdict.rfind("C1 on both sides of the crease (sides of 2 and 2 faces", 0) == 0);
  c.valence = 8;
  c.sharp = {0, 4};
  const SurfaceAnalysis cc8 = analyse_configuration(*load_scheme("catmull-clark"), c);
  CHECK(cc8.verdict.find("the side of 4 faces (boundary valence 5)") != std::string::npos);  // as --boundary finds
  c.valence = 6;
  c.sharp = {0, 3};
  const SurfaceAnalysis mb = analyse_configuration(*load_scheme("modified-butterfly"), c);
  CHECK(mb.verdict.rfind("C1 on both sides of the crease (sides of 3 and 3 faces", 0) == 0);
}

namespace {

// Lane & Riesenfeld (1980): one step of the uniform B-spline of degree d has the mask
// binomial(d + 1, i) / 2^d; a new point takes every second entry (the even or the odd ones).
std::vector<double> bspline_subdivision_weights(int d) {
  std::vector<double> mask(size_t(d + 2), 1.0);
  for (int i = 1; i <= d; ++i) mask[size_t(i)] = mask[size_t(i - 1)] * double(d + 2 - i) / double(i);
  for (double& w : mask) w /= std::ldexp(1.0, d);
  return mask;
}

LocalConfig crease_config(int valence) { return dual_config(valence, false, {0, valence / 2}); }

}  // namespace

// Even-degree quad B-splines (`quad-bspline`, d = 4 ... 12): along an infinitely sharp
// crease the dual step is Lane & Riesenfeld's degree-d curve step on the crease polygon, so
// the crease points of the analysed ring refine among themselves by every second entry of
// the degree-d mask, and their block's spectrum starts 1, 1/2, 1/4, ..., 1/2^d (the uniform
// B-spline's, whose limit is C^(d-1)); across it each side is judged as a boundary.
TEST_CASE("dual crease: quad-bspline of even degree d follows the degree-d B-spline along the crease (1/2 along)") {
  struct Case {
    int d;
    std::vector<int> valences;
  };
  // Valence 4 has two faces on each side, 5 two and three, 6 three and three; the higher
  // degrees at 5 only (their rings are large: kept short for the sanitizer runs).
  for (const Case& c : {Case{4, {4, 5, 6}}, Case{6, {4, 5, 6}}, Case{8, {5}}, Case{10, {5}}, Case{12, {5}}}) {
    const auto scheme = load_scheme("quad-bspline", {{"d", std::to_string(c.d)}});
    const std::vector<double> mask = bspline_subdivision_weights(c.d);
    for (int n : c.valences) {
      CAPTURE(c.d);
      CAPTURE(n);
      const LocalConfig config = crease_config(n);
      const SurfaceAnalysis a = analyse_configuration(*scheme, config);
      REQUIRE(a.error.empty());
      CHECK(a.c1);
      CHECK(a.verdict.rfind(fmt::format("C1 on both sides of the crease (sides of {} and {} faces", n / 2, n - n / 2), 0) ==
            0);
      // Along: the crease block's spectrum, 1/2^j for j = 0 .. d first.
      REQUIRE(a.crease_eigenvalues.size() > size_t(c.d + 1));
      for (int j = 0; j <= c.d; ++j) {
        CHECK(std::abs(a.crease_eigenvalues[size_t(j)].imag()) < 1e-9);
        CHECK(a.crease_eigenvalues[size_t(j)].real() == doctest::Approx(std::ldexp(1.0, -j)).epsilon(1e-7));
      }
      for (size_t j = size_t(c.d + 1); j < a.crease_eigenvalues.size(); ++j)
        CHECK(std::abs(a.crease_eigenvalues[j]) <= std::ldexp(1.0, -c.d) + 1e-7);
      // ... and every crease row is every second entry of the mask (as a multiset: the even
      // and the odd entries are each other's reverse).
      std::vector<double> half;
      for (size_t i = 0; i < mask.size(); i += 2) half.push_back(mask[i]);
      std::sort(half.begin(), half.end());
      const Patch p = make_dual_sector_patch(*scheme, config, a.max_ring + 3, {});
      int rows = 0;
      for (int i = 0; i < a.size; ++i) {
        if (!on_crease(p.level, a.label_vertices[size_t(i)])) continue;
        std::vector<double> row;
        for (double w : a.matrix[size_t(i)])
          if (std::abs(w) > 1e-14) row.push_back(w);
        REQUIRE(row.size() == half.size());
        std::sort(row.begin(), row.end());
        for (size_t j = 0; j < half.size(); ++j) CHECK(row[j] == doctest::Approx(half[j]).epsilon(1e-12));
        ++rows;
      }
      CHECK(rows >= 4);
    }
  }
}

TEST_CASE("dual crease: quad-bspline's across eigenvalues are its sides' boundary ones; a sector of one face has none") {
  // S is block triangular across the crease, so its spectrum holds each side's: at valence
  // 5 the side of two faces (boundary valence 3) and the side of three (boundary valence 4).
  const auto scheme = load_scheme("quad-bspline", {{"d", "4"}});
  const SurfaceAnalysis crease = analyse_configuration(*scheme, crease_config(5));
  for (int side : {3, 4}) {
    CAPTURE(side);
    const SurfaceAnalysis b = analyse_configuration(*scheme, dual_config(side, true, {}));
    REQUIRE(b.c1);
    bool found = false;
    for (const auto& z : crease.eigenvalues) found = found || std::abs(z - std::complex<double>(b.lambda1)) < 1e-9;
    CHECK(found);
  }
  // Valence 3 (sides of one and two faces): the side of one face's F-face takes both crease
  // points and gains a corner at each corner between two crease edges, every level (a quad
  // becomes 5, 7, 11, 19 corners), so that side has no face of fixed size.
  const SurfaceAnalysis three = analyse_configuration(*scheme, crease_config(3));
  CHECK(three.verdict.find("a sector of 1 face") != std::string::npos);
}
