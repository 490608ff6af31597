#include <doctest/doctest.h>

#include <cmath>

#include "support/refine_helpers.h"

using namespace subdiv;
using test::weight_of;

namespace {

const double kPi = std::acos(-1.0);


}  // namespace

TEST_CASE("sqrt3 vertex rule: (1 - alpha_n) p + alpha_n/n sum p_i, alpha_n = (4 - 2 cos(2 pi/n))/9") {
  for (int n = 3; n <= 10; ++n) {
    const auto r = test::refine_mesh(test::bipyramid(n), "sqrt3", 1);
    const double alpha = (4 - 2 * std::cos(2 * kPi / n)) / 9;
    const auto& S = r.hierarchy.stencils[0];
    CHECK(weight_of(S, n, n) == doctest::Approx(1 - alpha).epsilon(1e-14));
    for (Index i = 0; i < n; ++i) CHECK(weight_of(S, n, i) == doctest::Approx(alpha / n).epsilon(1e-14));
  }
}

TEST_CASE("Doo-Sabin: every new corner point has Doo & Sabin 1978's weights gamma_j") {
  const test::Mesh m = test::pyramid();  // a quad and four triangles
  const Level L = m.level();
  const auto r = test::refine_mesh(m, "doo-sabin", 1);
  const auto& S = r.hierarchy.stencils[0];
  for (Index f = 0; f < L.face_count(); ++f) {
    const int k = L.face_size(f);
    for (int c = 0; c < k; ++c)
      for (int j = 0; j < k; ++j) {
        const double gamma = j == 0 ? (k + 5.0) / (4 * k) : (3 + 2 * std::cos(2 * kPi * j / k)) / (4 * k);
        CHECK(weight_of(S, L.face_offsets[f] + c, L.face(f)[(c + j) % k]) == doctest::Approx(gamma).epsilon(1e-14));
      }
  }
}

TEST_CASE("Doo-Sabin keeps face centroids: each F-face's centroid is its parent's, level after level") {
  for (const std::string scheme : {"doo-sabin", "doo-sabin-centroid"}) {
    const test::Mesh m = test::pyramid();
    const auto r = test::refine_mesh(m, scheme, 3);
    // Follow face 0 (the base quad) down its F-faces: the F-face of face f is child face f.
    std::vector<double> pos = m.positions;
    auto centroid = [](const Level& L, const std::vector<double>& p, Index f) {
      std::array<double, 3> c{0, 0, 0};
      for (Index v : L.face(f))
        for (int i = 0; i < 3; ++i) c[i] += p[3 * v + i] / L.face_size(f);
      return c;
    };
    const auto c0 = centroid(r.hierarchy.levels[0], pos, 0);
    for (int l = 1; l <= 3; ++l) {
      pos = r.hierarchy.stencils[l - 1].apply(pos, 3);
      const auto c = centroid(r.hierarchy.levels[l], pos, 0);
      for (int i = 0; i < 3; ++i) CHECK(c[i] == doctest::Approx(c0[i]).epsilon(1e-13));
    }
  }
}

TEST_CASE("Doo-Sabin boundary: boundary corners are Chaikin points of the boundary polygon") {
  const test::Mesh m = test::grid(3, 3);
  const Level L = m.level();
  const auto r = test::refine_mesh(m, "doo-sabin", 1);
  const auto& S = r.hierarchy.stencils[0];
  // Face 1 = (1,0)-(2,0)-(2,1)-(1,1): its corner at (1,0) lies on the boundary edge to (2,0).
  CHECK(weight_of(S, L.face_offsets[1], 1) == doctest::Approx(0.75));
  CHECK(weight_of(S, L.face_offsets[1], 2) == doctest::Approx(0.25));
  // Face 0's corner at (0,0) has two boundary edges: a corner that stays.
  CHECK(weight_of(S, L.face_offsets[0], 0) == 1.0);
}

TEST_CASE("interpolatory schemes keep old vertices; on a regular mesh butterfly and modified butterfly agree") {
  const test::Mesh m = test::torus(8, 6, true);
  const auto b = test::refine_mesh(m, "butterfly", 2);
  const auto mb = test::refine_mesh(m, "modified-butterfly", 2);
  for (Index v = 0; v < m.vertex_count; ++v)
    for (int i = 0; i < 3; ++i) {
      CHECK(b.positions[3 * v + i] == doctest::Approx(m.positions[3 * v + i]).epsilon(1e-15));
      CHECK(mb.positions[3 * v + i] == doctest::Approx(m.positions[3 * v + i]).epsilon(1e-15));
    }
  for (size_t i = 0; i < b.positions.size(); ++i) CHECK(mb.positions[i] == doctest::Approx(b.positions[i]).epsilon(1e-13));
  // Old vertices keep exact positions at an extraordinary vertex too.
  const test::Mesh o = test::octahedron();
  const auto ro = test::refine_mesh(o, "modified-butterfly", 3);
  for (Index v = 0; v < o.vertex_count; ++v) CHECK(ro.positions[3 * v] == o.positions[3 * v]);
}

TEST_CASE("butterfly edge rule: 1/2 ends, 1/8 wings, -1/16 far wings") {
  const test::Mesh m = test::torus(8, 6, true);
  const auto r = test::refine_mesh(m, "butterfly", 1);
  const Level& L = r.hierarchy.levels[0];
  const auto& S = r.hierarchy.stencils[0];
  for (Index e = 0; e < L.edge_count(); ++e) {
    const Index row = L.vertex_count + e;
    CHECK(S.row_size(row) == 8);
    double neg = 0, pos = 0;
    for (Index i = S.offsets[row]; i < S.offsets[row + 1]; ++i) (S.weights[i] < 0 ? neg : pos) += S.weights[i];
    CHECK(neg == doctest::Approx(-0.25));
    CHECK(weight_of(S, row, L.edge_vertices[2 * e]) == doctest::Approx(0.5));
  }
}

TEST_CASE("modified butterfly next to an extraordinary vertex uses its s_j weights (valence 3, 4, 5+)") {
  for (int n : {3, 4, 5, 7}) {
    const test::Mesh m = test::bipyramid(n);  // apex n has valence n; the equator vertices have valence 4
    const auto r = test::refine_mesh(m, "modified-butterfly", 1);
    const Level& L = r.hierarchy.levels[0];
    const Index apex = n;
    const Index e = find_edge(L, apex, 0);
    const auto& S = r.hierarchy.stencils[0];
    const Index row = L.vertex_count + e;
    // Both ends are extraordinary (valence n and 4): the two end stencils average.
    auto s = [](int k, int j) {
      if (k == 3) return j == 0 ? 5.0 / 12 : -1.0 / 12;
      if (k == 4) return j == 0 ? 3.0 / 8 : j == 2 ? -1.0 / 8 : 0.0;
      return (0.25 + std::cos(2 * kPi * j / k) + 0.5 * std::cos(4 * kPi * j / k)) / k;
    };
    // The apex's ring counted from vertex 0: equator vertices 0, 1, ..., n-1 in some rotation
    // direction; the weight on equator vertex 0 gets s_n(0)/2 from the apex side plus 3/8
    // (the end weight 3/4 halved) from its own side.
    CHECK(weight_of(S, row, 0) == doctest::Approx(0.5 * s(n, 0) + 0.375).epsilon(1e-13));
    CHECK(weight_of(S, row, apex) == doctest::Approx(0.375 + 0.5 * s(4, 0)).epsilon(1e-13));
    double sum = 0;
    for (Index i = S.offsets[row]; i < S.offsets[row + 1]; ++i) sum += S.weights[i];
    CHECK(sum == doctest::Approx(1.0));
  }
}
