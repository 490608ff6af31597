// Limit evaluation of √3 schemes (Kobbelt 2000; Labsik & Greiner 2000's interpolating
// variant) at (face, u, v), in the triadic parameterisation of docs/limit.md: against the
// limit masks of the surface analysis at base vertices and at the vertices two steps make
// (the route of `subdiv refine --limit`), interpolation of the control points by the
// interpolating scheme, continuity across every edge, affine invariance, linear precision,
// the rate at which refined vertices approach their limit (9 per double step in a regular
// region: a second difference, h^2 with h = 3^-k), derivatives against central differences,
// stencils against evaluation, points next to vertices, and the refusals.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/engine/refiner.h"
#include "framework/limit/limit_surface.h"
#include "framework/limit/sqrt3_limit.h"
#include "framework/limit/tessellation.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"
#include "unit/limit/sqrt3_points.h"

using namespace subdiv;

namespace {

using limit_test::distance;

using limit_test::bumped;
using limit_test::sqrt3::on_edge;

// A tetrahedron: every vertex of valence 3, and a face's three neighbours share their far corner.
test::Mesh tetrahedron() {
  test::Mesh m;
  m.add_vertex(1, 1, 1), m.add_vertex(1, -1, -1), m.add_vertex(-1, 1, -1), m.add_vertex(-1, -1, 1);
  m.add_face({0, 1, 2}), m.add_face({0, 2, 3}), m.add_face({0, 3, 1}), m.add_face({1, 3, 2});
  return m;
}

// Meshes with extraordinary vertices: the octahedron (valence 4), the pentagonal bipyramid
// (valences 5 and 4) and the tetrahedron (3), bumped so that no symmetry hides an error.
std::vector<test::Mesh> meshes() { return {bumped(test::octahedron()), bumped(test::bipyramid(5)), bumped(tetrahedron())}; }

}  // namespace

TEST_CASE("sqrt3: the limit at a base vertex is its limit mask, and the interpolating scheme interpolates") {
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    for (const test::Mesh& m : meshes()) {
      const Level L = m.level();
      const LimitSurface s(load_scheme(name), L);
      const LimitResult masks = limit_positions(*load_scheme(name), L, m.positions);
      for (Index f = 0; f < L.face_count(); ++f)
        for (int k = 0; k < 3; ++k) {
          const std::array<double, 2> c[3] = {{0, 0}, {1, 0}, {0, 1}};
          const Index w = L.face(f)[size_t(k)];
          const LimitSample p = s.evaluate(f, c[k][0], c[k][1], m.positions, 3);
          CHECK(distance(p.position, std::span(masks.positions).subspan(size_t(3 * w), 3)) < 1e-13);
          if (std::string(name) == "interpolating-sqrt3")
            CHECK(distance(p.position, std::span(m.positions).subspan(size_t(3 * w), 3)) < 1e-13);
          // Extraordinary vertices (every vertex of these meshes) have no derivatives in (u, v).
          CHECK(!p.has_derivatives);
        }
    }
  }
}

TEST_CASE("sqrt3: the limit at the vertices two steps make equals their limit masks (refine --limit)") {
  // Two steps are the triadic split: the face points of level 1 at the base faces' centroids,
  // those of level 2 at the thirds of the base edges (the centroid of the level-1 triangle
  // (a, P(f0), P(f1)) over edge a-b is (2a + b)/3). Their limit masks on level 2 are the
  // independent route (analysis/surface/limit_evaluation.h, as `subdiv refine --limit`).
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    for (const test::Mesh& m : meshes()) {
      const Level L = m.level();
      const auto scheme = load_scheme(name);
      const LimitSurface s(scheme, L);
      RefineOptions ro;
      ro.levels = 2;
      const Hierarchy h = refine(*scheme, L, ro);
      std::vector<double> p1 = h.stencils[0].apply(m.positions, 3);
      std::vector<double> p2 = h.stencils[1].apply(p1, 3);
      LimitOptions lo;
      lo.first_step = 2;
      const LimitResult masks = limit_positions(*scheme, h.levels[2], p2, lo);
      const ChildOrigins& o1 = h.origins[0];
      const ChildOrigins& o2 = h.origins[1];
      double worst = 0;
      int checked = 0;
      for (Index v = 0; v < h.levels[2].vertex_count; ++v) {
        if (o2.kind[size_t(v)] == OriginKind::Vertex && o1.kind[size_t(o2.parent[size_t(v)])] != OriginKind::Face)
          continue;  // base vertices: the case above
        const auto [face, uv] = limit_test::sqrt3::where_two_steps_put(L, h, v);
        const LimitSample p = s.evaluate(face, uv[0], uv[1], m.positions, 3, 0);
        worst = std::max(worst, distance(p.position, std::span(masks.positions).subspan(size_t(3 * v), 3)));
        ++checked;
      }
      CHECK(checked == L.face_count() + 3 * L.face_count());
      CHECK(worst < 1e-13);
    }
  }
}

TEST_CASE("sqrt3: continuous across every edge, affine invariant, stencils equal evaluation") {
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    const test::Mesh m = bumped(test::octahedron());
    const Level L = m.level();
    const LimitSurface s(load_scheme(name), L);
    double worst_edge = 0;
    for (Index e = 0; e < L.edge_count(); ++e) {
      const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
      const Index f0 = L.edge_faces[size_t(2 * e)], f1 = L.edge_faces[size_t(2 * e + 1)];
      for (double t : {0.2, 0.5, 0.731}) {
        const auto x = on_edge(L, f0, a, b, t), y = on_edge(L, f1, a, b, t);
        const LimitSample p = s.evaluate(f0, x[0], x[1], m.positions, 3, 0);
        const LimitSample q = s.evaluate(f1, y[0], y[1], m.positions, 3, 0);
        worst_edge = std::max(worst_edge, distance(p.position, q.position));
      }
    }
    CHECK(worst_edge < 1e-13);
    // An affine image of the control points gives the affine image of the limit (the rows sum
    // to one) and of its derivatives (their rows sum to zero).
    const double A[3][3] = {{0.8, -0.3, 0.2}, {0.1, 1.1, -0.4}, {0.5, 0.2, 0.9}}, t[3] = {1.5, -2, 0.25};
    std::vector<double> moved(m.positions.size());
    for (size_t v = 0; v < moved.size() / 3; ++v)
      for (int r = 0; r < 3; ++r)
        moved[3 * v + size_t(r)] = t[r] + A[r][0] * m.positions[3 * v] + A[r][1] * m.positions[3 * v + 1] +
                                   A[r][2] * m.positions[3 * v + 2];
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(0, 1);
    for (int k = 0; k < 4; ++k) {
      double u = U(rng), v = U(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const Index f = Index(k % L.face_count());
      const LimitSample p = s.evaluate(f, u, v, m.positions, 3);
      const LimitSample q = s.evaluate(f, u, v, moved, 3);
      REQUIRE(p.has_derivatives);
      for (int r = 0; r < 3; ++r) {
        double x = t[r], du = 0, dv = 0;
        for (int c = 0; c < 3; ++c)
          x += A[r][c] * p.position[size_t(c)], du += A[r][c] * p.du[size_t(c)], dv += A[r][c] * p.dv[size_t(c)];
        CHECK(std::fabs(q.position[size_t(r)] - x) < 1e-13);
        CHECK(std::fabs(q.du[size_t(r)] - du) < 1e-12);
        CHECK(std::fabs(q.dv[size_t(r)] - dv) < 1e-12);
      }
      // The stencil applied to the control points.
      const LimitStencil w = s.stencil(f, u, v);
      REQUIRE(w.has_derivatives);
      std::array<double, 3> x{}, du{}, dv{};
      for (size_t i = 0; i < w.vertices.size(); ++i)
        for (size_t c = 0; c < 3; ++c) {
          const double pc = m.positions[size_t(3 * w.vertices[i]) + c];
          x[c] += w.position[i] * pc, du[c] += w.du[i] * pc, dv[c] += w.dv[i] * pc;
        }
      CHECK(distance(x, p.position) < 1e-13);
      CHECK(distance(du, p.du) < 1e-12);
      CHECK(distance(dv, p.dv) < 1e-12);
    }
  }
}

TEST_CASE("sqrt3: linear precision, derivatives against central differences, 34 double steps") {
  // A regular (valence 6) torus, 30 x 30 quads split on a diagonal, with the control points at
  // their own grid coordinates (unrolled away from the seam, which the faces evaluated here
  // do not read). Face 2 (j n + i) is (i, j), (i+1, j), (i+1, j+1), so its (u, v) is the grid
  // point (i + u + v, j + v); face 2 (j n + i) + 1 is (i, j), (i+1, j+1), (i, j+1): (i + u, j + u + v).
  // Both schemes reproduce linear functions on a regular grid (Kobbelt's vertex rule keeps a
  // vertex at its ring's mean, the face point is the centroid; Labsik & Greiner's stencil
  // reproduces cubics), so the limit is that plane and its derivatives the grid's axes.
  const int n = 30;
  test::Mesh m = test::torus(n, n, true);
  for (Index v = 0; v < m.vertex_count; ++v) {
    m.positions[size_t(3 * v)] = double(v % n);
    m.positions[size_t(3 * v + 1)] = double(v / n);
    m.positions[size_t(3 * v + 2)] = 0;
  }
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    const LimitSurface s(load_scheme(name), m.level());
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0, 1);
    for (int k = 0; k < 6; ++k) {
      const int i = 14 + k % 2, j = 14 + (k / 2) % 2, half = k % 3 == 0 ? 1 : 0;
      double u = U(rng), v = U(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const LimitSample p = s.evaluate(Index(2 * (j * n + i) + half), u, v, m.positions, 3);
      const std::array<double, 3> x = half ? std::array<double, 3>{i + u, j + u + v, 0}
                                           : std::array<double, 3>{i + u + v, j + v, 0};
      const std::array<double, 3> du = half ? std::array<double, 3>{1, 1, 0} : std::array<double, 3>{1, 0, 0};
      const std::array<double, 3> dv = half ? std::array<double, 3>{0, 1, 0} : std::array<double, 3>{1, 1, 0};
      CHECK(distance(p.position, x) < 1e-12);
      REQUIRE(p.has_derivatives);
      CHECK(distance(p.du, du) < 1e-12);
      CHECK(distance(p.dv, dv) < 1e-12);
      // A point in a regular region is taken at its nearest vertex after 34 double steps (a
      // triangle 3^-34 < 2^-53 of the base one): the error is that size times the derivative.
      CHECK(p.steps == Sqrt3Limit::kRoundOffSteps);
    }
  }
  // Derivatives against central differences of positions on curved surfaces, with
  // extraordinary vertices near.
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    for (const test::Mesh& c : meshes()) {
      const LimitSurface s(load_scheme(name), c.level());
      std::mt19937 rng(2);
      std::uniform_real_distribution<double> U(0.1, 0.8);
      double worst = 0;
      for (int k = 0; k < 3; ++k) {
        double u = U(rng), v = U(rng);
        if (u + v > 0.9) u = 0.9 - u, v = 0.9 - v, u = std::max(u, 0.05), v = std::max(v, 0.05);
        const Index f = Index(3 * k % c.level().face_count());
        worst = std::max(worst, limit_test::central_difference_error(s, f, u, v, c.positions));
      }
      CHECK(worst < 1e-6);
    }
  }
}

TEST_CASE("sqrt3: refined vertices approach their limit at the rate of a second difference") {
  // The point of base face f is a vertex from level 1 on (child vertices keep their numbers:
  // the parent's first, then one per face), at (u, v) = (1/3, 1/3). In a regular region its
  // distance to its limit is a second difference of the level, h^2 for triangles of size
  // h = 3^-k after 2k steps: it falls by 9 per double step.
  const int n = 8;
  test::Mesh m = test::torus(n, n, true);
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[size_t(3 * v + 2)] += 0.2 * std::sin(1.3 * v);
  const auto scheme = load_scheme("sqrt3");
  const LimitSurface s(scheme, m.level());
  const Index f = 37;
  const LimitSample limit = s.evaluate(f, 1.0 / 3, 1.0 / 3, m.positions, 3, 0);
  RefineOptions ro;
  ro.levels = 6;
  const Hierarchy h = refine(*scheme, m.level(), ro);
  std::vector<double> p = m.positions;
  std::vector<double> d;
  for (int l = 0; l < 6; ++l) {
    p = h.stencils[size_t(l)].apply(p, 3);
    if (l % 2 == 1) d.push_back(distance(std::span(p).subspan(size_t(3 * (m.vertex_count + f)), 3), limit.position));
  }
  REQUIRE(d.size() == 3);
  MESSAGE("distances at levels 2, 4, 6: " << d[0] << " " << d[1] << " " << d[2]);
  CHECK(d[0] / d[1] == doctest::Approx(9).epsilon(0.05));
  CHECK(d[1] / d[2] == doctest::Approx(9).epsilon(0.02));
}

TEST_CASE("sqrt3: points next to vertices keep their digits") {
  const test::Mesh m = bumped(test::octahedron());
  const LimitSurface s(load_scheme("sqrt3"), m.level());
  const LimitSample corner = s.evaluate(0, 0, 0, m.positions, 3);
  // 1e-300 from the valence-4 vertex: its limit, with derivatives (the descent goes on past
  // the last triangle touching the vertex, 34 double steps, about 628 + 34 in all).
  const LimitSample near = s.evaluate(0, 1e-300, 0.7e-300, m.positions, 3);
  CHECK(distance(near.position, corner.position) < 1e-15);
  CHECK(near.has_derivatives);
  CHECK(near.steps > 600);
  // Its normal is the vertex's limit normal (the tangent masks' cross product). The
  // derivatives there are about (3 lambda)^628 = 0.67^628 (lambda = 2/9 at valence 4): scaled
  // to unit length before the cross product, which would underflow.
  const LimitResult masks = limit_positions(*load_scheme("sqrt3"), m.level(), m.positions);
  auto unit = [](std::vector<double> x) {
    const double l = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    for (double& c : x) c /= l;
    return x;
  };
  const std::vector<double> du = unit(near.du), dv = unit(near.dv);
  std::array<double, 3> normal{du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
  const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  for (double& x : normal) x /= length;
  CHECK(distance(normal, std::span(masks.normals).subspan(0, 3)) < 1e-6);
  // Farther out, the distance to the corner's limit grows with the parameter.
  const LimitSample mid = s.evaluate(0, 1e-8, 0.7e-8, m.positions, 3, 0);
  const LimitSample far = s.evaluate(0, 1e-4, 0.7e-4, m.positions, 3, 0);
  CHECK(distance(mid.position, corner.position) > 0);
  CHECK(distance(mid.position, corner.position) < distance(far.position, corner.position));
  // A point on a base edge stays on it exactly: both faces agree at 1e-12 from a vertex too.
  const Level L = m.level();
  const Index a = 0, b = 2;  // the edge of faces 0 (0, 2, 4) and 4 (2, 0, 5)
  const auto x = on_edge(L, 0, a, b, 1e-12), y = on_edge(L, 4, a, b, 1e-12);
  CHECK(distance(s.evaluate(0, x[0], x[1], m.positions, 3, 0).position, s.evaluate(4, y[0], y[1], m.positions, 3, 0).position) <
        1e-15);
}

TEST_CASE("sqrt3: the numbers do not depend on the order of evaluation") {
  // Each neighbourhood is worked out once, on its cut renumbered by its labels: a second
  // surface that meets the faces in the other order gives the same bits.
  const test::Mesh m = bumped(test::bipyramid(5));
  const LimitSurface a(load_scheme("sqrt3"), m.level()), b(load_scheme("sqrt3"), m.level());
  std::vector<LimitSample> first, second;
  const Index faces = m.level().face_count();
  for (Index f = 0; f < faces; ++f) first.push_back(a.evaluate(f, 0.21, 0.37, m.positions, 3));
  for (Index f = faces; f-- > 0;) second.push_back(b.evaluate(f, 0.21, 0.37, m.positions, 3));
  for (Index f = 0; f < faces; ++f) {
    CHECK(first[size_t(f)].position == second[size_t(faces - 1 - f)].position);
    CHECK(first[size_t(f)].du == second[size_t(faces - 1 - f)].du);
  }
}

TEST_CASE("sqrt3: the tessellation is closed") {
  const test::Mesh m = bumped(test::octahedron());
  const LimitSurface s(load_scheme("sqrt3"), m.level());
  const Tessellation t = tessellate(s, m.positions, 2);
  CHECK(t.face_count() == 8 * 4);
  CHECK(t.point_count() == 6 + 12);  // N = 2: corners and edge middles, each once (no cracks), no interior points
}
