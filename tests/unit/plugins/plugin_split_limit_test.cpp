// Limit evaluation on a plugin's split: the example √2 plugin (the 4-8 / √2 split of Li, Ma &
// Bao 2004, which turns a quad grid by 45 degrees each step and is a binary quad split every
// second step) with its JSON scheme (face points at centroids, v' = v/2 + mean of its new face
// points / 2). Against the limit masks of the surface analysis at base vertices and at the
// vertices two steps make (face centres and edge middles), continuity across every edge,
// linear precision on a regular grid, derivatives against central differences, stencils
// against evaluation, and the refusals.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/engine/refiner.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv;

namespace {

using limit_test::distance;

using limit_test::bumped;

// (u, v) of the point t of the way along edge k of a quad.
std::array<double, 2> edge_uv(int k, double t) {
  constexpr double c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const int l = (k + 1) % 4;
  return {c[k][0] + t * (c[l][0] - c[k][0]), c[k][1] + t * (c[l][1] - c[k][1])};
}

// Stencil weights over the vertices applied to their positions.
std::array<double, 3> applied(const std::vector<Index>& vertices, const std::vector<double>& weights,
                              const std::vector<double>& positions) {
  std::array<double, 3> x{};
  for (size_t i = 0; i < vertices.size(); ++i)
    for (size_t c = 0; c < 3; ++c) x[c] += weights[i] * positions[size_t(3 * vertices[i]) + c];
  return x;
}

int edge_in_face(const Level& L, Index f, Index a, Index b) {
  const auto fv = L.face(f);
  for (int k = 0; k < 4; ++k)
    if (fv[size_t(k)] == a && fv[size_t((k + 1) % 4)] == b) return k;
  return -1;
}

}  // namespace

TEST_CASE("A plugin's split (sqrt2): base vertices and the vertices two steps make against their limit masks") {
  test::load_example_plugins();
  const auto scheme = load_scheme("sqrt2");
  const test::Mesh m = bumped(test::cube());
  const Level L = m.level();
  const LimitSurface s(scheme, L);
  const LimitResult masks = limit_positions(*scheme, L, m.positions);
  double worst = 0;
  for (Index f = 0; f < L.face_count(); ++f)
    for (int k = 0; k < 4; ++k) {
      const auto uv = edge_uv(k, 0);
      const LimitSample p = s.evaluate(f, uv[0], uv[1], m.positions, 3);
      worst = std::max(worst, distance(p.position, std::span(masks.positions).subspan(size_t(3 * L.face(f)[size_t(k)]), 3)));
      CHECK(!p.has_derivatives);  // every cube vertex has valence 3
    }
  CHECK(worst < 1e-13);
  // Two steps: level 1 adds a point per face (vertex V + f, at the face's centre), level 2 a
  // point per level-1 face, one per base edge e (vertex V + F + e, at the edge's middle).
  RefineOptions ro;
  ro.levels = 2;
  const Hierarchy h = refine(*scheme, L, ro);
  const std::vector<double> p2 = h.stencils[1].apply(h.stencils[0].apply(m.positions, 3), 3);
  LimitOptions lo;
  lo.first_step = 2;
  const LimitResult level2 = limit_positions(*scheme, h.levels[2], p2, lo);
  REQUIRE(h.levels[2].vertex_count == L.vertex_count + L.face_count() + L.edge_count());
  worst = 0;
  for (Index f = 0; f < L.face_count(); ++f) {
    const LimitSample p = s.evaluate(f, 0.5, 0.5, m.positions, 3, 0);
    worst = std::max(worst, distance(p.position, std::span(level2.positions).subspan(size_t(3 * (L.vertex_count + f)), 3)));
  }
  for (Index e = 0; e < L.edge_count(); ++e) {
    const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
    const Index f = L.edge_faces[size_t(2 * e)];
    const auto uv = edge_uv(edge_in_face(L, f, a, b), 0.5);
    const LimitSample p = s.evaluate(f, uv[0], uv[1], m.positions, 3, 0);
    const Index v = L.vertex_count + L.face_count() + e;
    worst = std::max(worst, distance(p.position, std::span(level2.positions).subspan(size_t(3 * v), 3)));
  }
  CHECK(worst < 1e-13);
}

TEST_CASE("A plugin's split (sqrt2): continuous across every edge, derivatives, stencils") {
  test::load_example_plugins();
  const auto scheme = load_scheme("sqrt2");
  const test::Mesh m = bumped(test::cube());
  const Level L = m.level();
  const LimitSurface s(scheme, L);
  double worst = 0;
  for (Index e = 0; e < L.edge_count(); ++e) {
    const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
    const Index f0 = L.edge_faces[size_t(2 * e)], f1 = L.edge_faces[size_t(2 * e + 1)];
    for (double t : {0.3, 0.71}) {
      const auto x = edge_uv(edge_in_face(L, f0, a, b), t), y = edge_uv(edge_in_face(L, f1, b, a), 1 - t);
      worst = std::max(worst, distance(s.evaluate(f0, x[0], x[1], m.positions, 3, 0).position,
                                       s.evaluate(f1, y[0], y[1], m.positions, 3, 0).position));
    }
  }
  CHECK(worst < 1e-13);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> U(0.1, 0.9);
  double fd = 0;
  for (int k = 0; k < 4; ++k) {
    const Index f = Index(k);
    const double u = U(rng), v = U(rng), h = 1e-5;
    const LimitSample p = s.evaluate(f, u, v, m.positions, 3);
    REQUIRE(p.has_derivatives);
    const LimitSample a = s.evaluate(f, u + h, v, m.positions, 3, 0), b = s.evaluate(f, u - h, v, m.positions, 3, 0);
    const LimitSample c = s.evaluate(f, u, v + h, m.positions, 3, 0), d = s.evaluate(f, u, v - h, m.positions, 3, 0);
    for (size_t r = 0; r < 3; ++r) {
      fd = std::max(fd, std::fabs((a.position[r] - b.position[r]) / (2 * h) - p.du[r]));
      fd = std::max(fd, std::fabs((c.position[r] - d.position[r]) / (2 * h) - p.dv[r]));
    }
    const LimitStencil w = s.stencil(f, u, v);
    REQUIRE(w.has_derivatives);
    CHECK(distance(applied(w.vertices, w.position, m.positions), p.position) < 1e-13);
    CHECK(distance(applied(w.vertices, w.du, m.positions), p.du) < 1e-12);
  }
  CHECK(fd < 1e-6);
}

TEST_CASE("A plugin's split (sqrt2): linear precision on a regular grid, and the refusals") {
  test::load_example_plugins();
  const int n = 16;
  const test::Mesh m = limit_test::unrolled_torus(n);
  const LimitSurface s(load_scheme("sqrt2"), m.level());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  for (int k = 0; k < 4; ++k) {
    const int i = 7 + k % 2, j = 7 + (k / 2) % 2;
    const double u = U(rng), v = U(rng);
    const LimitSample p = s.evaluate(Index(j * n + i), u, v, m.positions, 3);
    CHECK(std::fabs(p.position[0] - (i + u)) < 1e-12);
    CHECK(std::fabs(p.position[1] - (j + v)) < 1e-12);
    REQUIRE(p.has_derivatives);
    CHECK(distance(p.du, std::array<double, 3>{1, 0, 0}) < 1e-12);
    CHECK(distance(p.dv, std::array<double, 3>{0, 1, 0}) < 1e-12);
  }
  CHECK_THROWS_WITH_AS(LimitSurface(load_scheme("sqrt2"), test::grid(3, 3).level()), doctest::Contains("boundary"),
                       Error);
  CHECK_THROWS_WITH_AS(LimitSurface(load_scheme("sqrt2"), test::pyramid().level()),
                       doctest::Contains("not all quads or all triangles"), Error);
}

TEST_CASE("A plugin's split with a vertex rule that is not C1 at regular vertices: derivatives refused") {
  // The sqrt2 plugin's scheme keeping 0.9 of the vertex (its own rule keeps 1/2): at a
  // regular vertex the period's subdominant eigenvalues are 0.540, 0.5 (`subdiv analyze`),
  // not the 1/2 by which two √2 steps shrink the parameters, so the limit has no derivatives
  // there; positions are evaluated.
  test::load_example_plugins();
  const auto stiff = load_scheme_text(R"({"name": "stiff-sqrt2", "split": "sqrt2", "curve": "cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "vertex": [{"at": "self", "w": "0.9"}, {"sum": "faces", "new": "face", "w": "0.1/n"}],
              "edge": [{"sum": "ends", "w": "1/2"}]}})",
                                      "stiff-sqrt2.json");
  const int n = 16;
  const test::Mesh m = limit_test::unrolled_torus(n);
  const LimitSurface s(stiff, m.level());
  const Index f = Index(7 * n + 7);
  CHECK_THROWS_WITH_AS(s.evaluate(f, 0.5, 0.5, m.positions, 3, 1),
                       doctest::Contains("scheme 'stiff-sqrt2' is not C1, so its limit has no derivatives"), Error);
  CHECK_THROWS_WITH_AS(s.evaluate(f, 0.3, 0.6, m.positions, 3, 1), doctest::Contains("needs 0.5"), Error);
  // Positions: the difference quotients at the face's centre do not settle (no derivative),
  // on heights that are no linear function (which a symmetric rule reproduces).
  std::vector<double> P = m.positions;
  for (size_t v = 0; 3 * v < P.size(); ++v) P[3 * v + 2] = 0.1 * double((v * 37) % 11);
  // At h = 2^-4, 2^-20, 2^-36 the quotients' changes grow (c h^-0.11 from the eigenvalue
  // 0.540 against 1/2) where a derivative would make each O(h) smaller than the last.
  const auto at = [&](double u) { return s.evaluate(f, u, 0.5, P, 3, 0).position; };
  const auto c = at(0.5);
  auto quotient = [&](int k) {
    const double h = std::ldexp(1.0, -k);
    const auto a = at(0.5 + h);
    return std::array<double, 3>{(a[0] - c[0]) / h, (a[1] - c[1]) / h, (a[2] - c[2]) / h};
  };
  const auto q4 = quotient(4), q20 = quotient(20), q36 = quotient(36);
  const double first = distance(q20, q4), second = distance(q36, q20);
  CAPTURE(first);
  CAPTURE(second);
  CHECK(second > first);
  // The plugin's own rule keeps its derivatives on the same grid (the test above).
  CHECK(LimitSurface(load_scheme("sqrt2"), m.level()).evaluate(f, 0.3, 0.6, m.positions, 3, 1).has_derivatives);
}

// A plugin's split in a sequence's head is followed one period at a time
// (plugin_period_children.h): its own levels before it change nothing, and another scheme
// after it is continuous across the base edges, with stencils and derivatives.
TEST_CASE("A plugin's split in a sequence's head (sqrt2:2,sqrt2 and sqrt2:4,sqrt2 equal sqrt2)") {
  test::load_example_plugins();
  const auto scheme = load_scheme("sqrt2");
  for (const test::Mesh& m : {bumped(test::cube()), bumped(test::torus(6, 5))}) {
    const Level L = m.level();
    const LimitSurface plain(scheme, L);
    for (int k : {2, 4}) {
      CAPTURE(k);
      const LimitSurface sequence({{scheme, k}}, scheme, L);
      std::mt19937 rng(unsigned(17 + k));
      std::uniform_real_distribution<double> U(0, 1);
      double worst = 0, worst_d = 0;
      for (int i = 0; i < 30; ++i) {
        const Index f = Index(i % L.face_count());
        const double u = U(rng), v = U(rng);
        const LimitSample a = plain.evaluate(f, u, v, m.positions, 3);
        const LimitSample b = sequence.evaluate(f, u, v, m.positions, 3);
        worst = std::max(worst, distance(a.position, b.position));
        REQUIRE(a.has_derivatives == b.has_derivatives);
        if (a.has_derivatives) worst_d = std::max(worst_d, distance(a.du, b.du) + distance(a.dv, b.dv));
      }
      CHECK(worst < 1e-13);
      CHECK(worst_d < 1e-10);
    }
  }
  CHECK_THROWS_WITH_AS(LimitSurface({{scheme, 1}}, load_scheme("catmull-clark"), test::cube().level()),
                       doctest::Contains("multiple of 2 levels"), Error);
  CHECK_THROWS_WITH_AS(LimitSurface({{scheme, 2}}, load_scheme("catmull-clark"), test::grid(3, 3).level()),
                       doctest::Contains("boundary"), Error);
}

TEST_CASE("A plugin's split in a sequence's head (sqrt2:2,catmull-clark): limit masks, continuity, stencils, "
          "derivatives") {
  test::load_example_plugins();
  const auto head = load_scheme("sqrt2");
  const auto tail = load_scheme("catmull-clark");
  const test::Mesh m = bumped(test::cube());
  const Level L = m.level();
  const LimitSurface s({{head, 2}}, tail, L);
  // Two √2 steps keep the base vertices (vertex v) and add a point per face (V + f, the face's
  // centre) and per edge (V + F + e, its middle); Catmull-Clark's limit masks on that level
  // are the limit there.
  RefineOptions ro;
  ro.levels = 2;
  const Hierarchy h = refine(*head, L, ro);
  const std::vector<double> p2 = h.stencils[1].apply(h.stencils[0].apply(m.positions, 3), 3);
  REQUIRE(h.levels[2].vertex_count == L.vertex_count + L.face_count() + L.edge_count());
  const LimitResult masks = limit_positions(*tail, h.levels[2], p2);
  auto mask = [&](Index v) { return std::span(masks.positions).subspan(size_t(3 * v), 3); };
  double worst = 0;
  for (Index f = 0; f < L.face_count(); ++f) {
    for (int k = 0; k < 4; ++k) {
      const auto uv = edge_uv(k, 0);
      worst = std::max(worst, distance(s.evaluate(f, uv[0], uv[1], m.positions, 3, 0).position, mask(L.face(f)[size_t(k)])));
    }
    worst = std::max(worst, distance(s.evaluate(f, 0.5, 0.5, m.positions, 3, 0).position, mask(L.vertex_count + f)));
  }
  for (Index e = 0; e < L.edge_count(); ++e) {
    const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
    const Index f = L.edge_faces[size_t(2 * e)];
    const auto uv = edge_uv(edge_in_face(L, f, a, b), 0.5);
    worst = std::max(worst, distance(s.evaluate(f, uv[0], uv[1], m.positions, 3, 0).position,
                                     mask(L.vertex_count + L.face_count() + e)));
  }
  CHECK(worst < 1e-13);
  double seam = 0;
  for (Index e = 0; e < L.edge_count(); ++e) {
    const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
    const Index f0 = L.edge_faces[size_t(2 * e)], f1 = L.edge_faces[size_t(2 * e + 1)];
    for (double t : {0.3, 0.71}) {
      const auto x = edge_uv(edge_in_face(L, f0, a, b), t), y = edge_uv(edge_in_face(L, f1, b, a), 1 - t);
      seam = std::max(seam, distance(s.evaluate(f0, x[0], x[1], m.positions, 3, 0).position,
                                     s.evaluate(f1, y[0], y[1], m.positions, 3, 0).position));
    }
  }
  CHECK(seam < 1e-13);
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> U(0.05, 0.95);
  double fd = 0, stencil = 0;
  for (Index f = 0; f < L.face_count(); ++f) {
    const double u = U(rng), v = U(rng);
    const LimitSample p = s.evaluate(f, u, v, m.positions, 3);
    REQUIRE(p.has_derivatives);
    fd = std::max(fd, limit_test::central_difference_error(s, f, u, v, m.positions, 1e-6));
    const LimitStencil w = s.stencil(f, u, v);
    stencil = std::max({stencil, distance(applied(w.vertices, w.position, m.positions), p.position),
                        distance(applied(w.vertices, w.du, m.positions), p.du)});
  }
  CHECK(fd < 1e-5);
  CHECK(stencil < 1e-12);
}
