// Limit evaluation of √3 schemes with sharp creases and tagged vertices: the split keeps a
// sharp edge in the first step and trisects it in the second, as a boundary (Kobbelt 2000,
// section 5), so two steps are the triadic split where an edge is sharp for both steps of a
// pair or for neither. Against the limit masks (crease configurations; the route of
// `subdiv refine --limit`) at every vertex two steps make, continuity, affine invariance,
// linear precision along the crease curve, derivatives off the crease, the rate refined crease
// points approach their limit (sharpness that ends between two steps: sqrt3_odd_sharpness_test.cpp).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/engine/refiner.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/sanitizers.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"
#include "unit/limit/sqrt3_creased_meshes.h"
#include "unit/limit/sqrt3_points.h"

using namespace subdiv;

namespace {

using limit_test::bumped;
using limit_test::distance;
using namespace limit_test::sqrt3;

constexpr int kN = kCreasedTorusSize;

// The bumped octahedron with its equator infinitely sharp (crease vertices of valence 4) and
// a pole tagged as a corner.
Tagged creased_octahedron() {
  Tagged t = octahedron_with_equator(kInfinitelySharp);
  t.level.vertex_sharpness.assign(size_t(t.level.vertex_count), 0.f);
  t.level.vertex_sharpness[4] = kInfinitelySharp;
  return t;
}

std::vector<Tagged> meshes() {
  return {creased_torus(kInfinitelySharp), creased_torus(2.f), creased_torus(1.5f), creased_octahedron()};
}

}  // namespace

TEST_CASE("sqrt3 with creases: the limit at the vertices two steps make equals their limit masks") {
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    int which = 0;
    for (const Tagged& t : meshes()) {
      const int mesh = which++;
      CAPTURE(mesh);
      const auto scheme = load_scheme(name);
      const LimitSurface s(scheme, t.level);
      RefineOptions ro;
      ro.levels = 2;
      const Hierarchy h = refine(*scheme, t.level, ro);
      const std::vector<double> p1 = h.stencils[0].apply(t.mesh.positions, 3);
      const std::vector<double> p2 = h.stencils[1].apply(p1, 3);
      LimitOptions lo;
      lo.first_step = 2;
      const LimitResult masks = limit_positions(*scheme, h.levels[2], p2, lo);
      double worst = 0;
      for (Index v = 0; v < h.levels[2].vertex_count; ++v) {
        const Where x = where_two_steps_put(t.level, h, v);
        const LimitSample p = s.evaluate(x.face, x.uv[0], x.uv[1], t.mesh.positions, 3, 0);
        worst = std::max(worst, distance(p.position, std::span(masks.positions).subspan(size_t(3 * v), 3)));
      }
      MESSAGE(std::string(name) << " mesh " << mesh << ": level 2 " << worst);
      CHECK(masks.approximate == 0);
      CHECK(worst < 1e-13);
    }
  }
}

TEST_CASE("sqrt3 with creases: continuous across every edge, affine invariant, derivatives off the crease") {
  const double A[3][3] = {{0.8, -0.3, 0.2}, {0.1, 1.1, -0.4}, {0.5, 0.2, 0.9}}, shift[3] = {1.5, -2, 0.25};
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    for (const Tagged& t : meshes()) {
      const Level& L = t.level;
      const std::vector<double>& P = t.mesh.positions;
      const LimitSurface s(load_scheme(name), L);
      CHECK(worst_edge_gap(s, L, P, {0.2, 0.731}) < 1e-13);
      std::vector<double> moved(P.size());
      for (size_t v = 0; v < moved.size() / 3; ++v)
        for (int r = 0; r < 3; ++r)
          moved[3 * v + size_t(r)] = shift[r] + A[r][0] * P[3 * v] + A[r][1] * P[3 * v + 1] + A[r][2] * P[3 * v + 2];
      std::mt19937 rng(7);
      std::uniform_real_distribution<double> U(0.1, 0.8);
      double worst_affine = 0, worst_difference = 0;
      for (Index f = 0; f < L.face_count(); f += 3) {
        double u = U(rng), v = U(rng);
        if (u + v > 0.9) u = 0.9 - u, v = 0.9 - v, u = std::max(u, 0.05), v = std::max(v, 0.05);
        const LimitSample p = s.evaluate(f, u, v, P, 3);
        const LimitSample q = s.evaluate(f, u, v, moved, 3);
        REQUIRE(p.has_derivatives);
        for (int r = 0; r < 3; ++r) {
          double x = shift[r];
          for (int c = 0; c < 3; ++c) x += A[r][c] * p.position[size_t(c)];
          worst_affine = std::max(worst_affine, std::fabs(q.position[size_t(r)] - x));
        }
        const double h = 1e-5;
        const LimitSample a = s.evaluate(f, u + h, v, P, 3, 0), b = s.evaluate(f, u - h, v, P, 3, 0);
        const LimitSample c = s.evaluate(f, u, v + h, P, 3, 0), d = s.evaluate(f, u, v - h, P, 3, 0);
        for (size_t r = 0; r < 3; ++r) {
          worst_difference = std::max(worst_difference, std::fabs((a.position[r] - b.position[r]) / (2 * h) - p.du[r]));
          worst_difference = std::max(worst_difference, std::fabs((c.position[r] - d.position[r]) / (2 * h) - p.dv[r]));
        }
      }
      CHECK(worst_affine < 1e-13);
      CHECK(worst_difference < 1e-5);
    }
  }
}

TEST_CASE("sqrt3 with creases: linear precision along an infinitely sharp crease, its rate of convergence") {
  // The torus unrolled (control points at their grid coordinates, limit_meshes.h's
  // triangulated counterpart) with the crease loop along row 2: the crease curve is the curve
  // rule of the crease vertices alone, which reproduces lines with the trisection points at
  // the thirds. Face 2 (j n + i) is (i, j), (i+1, j), (i+1, j+1): its edge 0 runs along row j.
  const int n = 12;
  test::Mesh m = test::torus(n, n, true);
  for (Index v = 0; v < m.vertex_count; ++v)
    m.positions[size_t(3 * v)] = double(v % n), m.positions[size_t(3 * v + 1)] = double(v / n),
                        m.positions[size_t(3 * v + 2)] = 0;
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (int i = 0; i < n; ++i)
    L.edge_sharpness[size_t(find_edge(L, Index(6 * n + i), Index(6 * n + (i + 1) % n)))] = kInfinitelySharp;
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    const LimitSurface s(load_scheme(name), L);
    double worst = 0;
    for (int i = 3; i < n - 3; ++i)
      for (double u : {0.0, 0.17, 0.5, 0.93}) {
        const LimitSample p = s.evaluate(Index(2 * (6 * n + i)), u, 0, m.positions, 3, 0);
        worst = std::max(worst, distance(p.position, std::array<double, 3>{i + u, 6, 0}));
      }
    MESSAGE(std::string(name) << ": crease curve " << worst);
    CHECK(worst < 1e-12);
  }
  // A trisection point of the bumped torus's crease is a vertex from level 2 on; its distance
  // to its limit falls by 1/lambda^2 per double step, lambda the regular crease's subdominant
  // eigenvalue from the analysis.
  const auto scheme = load_scheme("sqrt3");
  LocalConfig config;
  config.valence = 6;
  config.sharp = {0, 3};
  const SurfaceAnalysis a = analyse_configuration(*scheme, config);
  REQUIRE(a.error.empty());
  const Tagged t = creased_torus(kInfinitelySharp);
  const LimitSurface s(scheme, t.level);
  RefineOptions ro;
  ro.levels = 6;
  const Hierarchy h = refine(*scheme, t.level, ro);
  const Index face = Index(2 * (2 * kN + 3));  // (3, 2), (4, 2), (4, 3): edge 0 on the crease
  Index v2 = kNone;
  // The trisection point of crease edge (3, 2)-(4, 2) next to (3, 2).
  for (Index v = 0; v < h.levels[2].vertex_count; ++v)
    if (h.origins[1].kind[size_t(v)] == OriginKind::Edge) {
      const Index e1 = h.origins[1].parent[size_t(v)], near = h.origins[1].local[size_t(v)];
      const Index a = h.origins[0].parent[size_t(h.levels[1].edge_vertices[size_t(2 * e1 + near)])];
      const Index b = h.origins[0].parent[size_t(h.levels[1].edge_vertices[size_t(2 * e1 + 1 - near)])];
      if (a == 2 * kN + 3 && b == 2 * kN + 4) v2 = v;
    }
  REQUIRE(v2 != kNone);
  const LimitSample limit = s.evaluate(face, 1.0 / 3, 0, t.mesh.positions, 3, 0);
  std::vector<double> p = t.mesh.positions;
  std::vector<double> d;
  for (int l = 0; l < 6; ++l) {
    p = h.stencils[size_t(l)].apply(p, 3);
    if (l % 2 == 1) d.push_back(distance(std::span(p).subspan(size_t(3 * v2), 3), limit.position));
  }
  MESSAGE("lambda_1 " << a.lambda1 << "; distances at levels 2, 4, 6: " << d[0] << " " << d[1] << " " << d[2]);
  const double rate = 1 / (a.lambda1 * a.lambda1);
  CHECK(d[0] / d[1] == doctest::Approx(rate).epsilon(0.05));
  CHECK(d[1] / d[2] == doctest::Approx(rate).epsilon(0.02));
}

TEST_CASE("sqrt3 with creases: no derivatives on the crease") {
  const Tagged t = creased_torus(kInfinitelySharp);
  const LimitSurface s(load_scheme("sqrt3"), t.level);
  const Index face = Index(2 * (2 * kN + 3));
  CHECK(!s.evaluate(face, 0.4, 0, t.mesh.positions, 3).has_derivatives);
  CHECK(s.evaluate(face, 0.4, 1e-6, t.mesh.positions, 3).has_derivatives);
}

TEST_CASE("sqrt3 with creases: points on a crease, next to its extraordinary vertices, every edge of a face") {
  // On the octahedron's equator every base crease vertex has valence 4: points along the
  // crease at 1e-200 from them and on every face edge are evaluated (no descent gives up).
  const Tagged t = creased_octahedron();
  const LimitSurface s(load_scheme("sqrt3"), t.level);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> U(0, 1);
  for (Index f = 0; f < t.level.face_count(); ++f)
    for (int k = 0; k < 6; ++k) {
      const double x = k < 3 ? U(rng) : std::ldexp(1.0, -600 + 100 * k);
      const std::array<double, 2> uv = k % 3 == 0 ? std::array<double, 2>{x, 0}
                                     : k % 3 == 1 ? std::array<double, 2>{0, x}
                                                  : std::array<double, 2>{x, 1 - x};
      const LimitSample p = s.evaluate(f, uv[0], uv[1], t.mesh.positions, 3);
      for (double c : p.position) CHECK(std::isfinite(c));
    }
}
