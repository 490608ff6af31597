// Limit evaluation of √3 schemes (Kobbelt 2000, section 5's boundary rules; Labsik & Greiner
// 2000's interpolating variant) on meshes with boundaries and holes: two steps are the
// triadic split also along a boundary (its edges trisected in the second step), so the
// parameterisation of closed meshes carries over, the trisection points at (2a + b)/3. Against
// the limit masks of the surface analysis (boundary configurations; the route of
// `subdiv refine --limit`) at base vertices and at every vertex two steps make, continuity
// across every interior edge, affine invariance and stencils, linear precision, derivatives
// against central differences, the rate refined vertices approach their limit, holes.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/engine/refiner.h"
#include "framework/limit/limit_surface.h"
#include "framework/limit/sqrt3_limit.h"
#include "framework/limit/tessellation.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/sanitizers.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"
#include "unit/limit/sqrt3_points.h"

using namespace subdiv;

namespace {

using limit_test::bumped;
using limit_test::distance;
using namespace limit_test::sqrt3;

// An open fan of `sectors` triangles around a boundary vertex (vertex 0), `rings` rings deep,
// spread over a half plane: the centre has `sectors` faces on the boundary, the ends of each
// ring 2 or 3, the inner ring's vertices valence 5 inside.
test::Mesh boundary_fan(int sectors, int rings) {
  test::Mesh m;
  m.add_vertex(0, 0, 0);
  auto id = [&](int r, int j) { return Index(1 + (r - 1) * (sectors + 1) + j); };
  for (int r = 1; r <= rings; ++r)
    for (int j = 0; j <= sectors; ++j) {
      const double a = std::acos(-1.0) * j / sectors;
      m.add_vertex(r * std::cos(a), r * std::sin(a), 0);
    }
  for (int j = 0; j < sectors; ++j) m.add_face({0, id(1, j), id(1, j + 1)});
  for (int r = 1; r < rings; ++r)
    for (int j = 0; j < sectors; ++j) {
      m.add_face({id(r, j), id(r + 1, j), id(r + 1, j + 1)});
      m.add_face({id(r, j), id(r + 1, j + 1), id(r, j + 1)});
    }
  return m;
}

// Open bumped patches: a triangulated 4 x 4 grid (boundary vertices with 1, 2 and 3 faces)
// and fans whose centre has 2, 3 and 4 faces on the boundary.
std::vector<test::Mesh> meshes() {
  return {bumped(test::grid(4, 4, true), 0.3), bumped(boundary_fan(2, 3), 0.3), bumped(boundary_fan(3, 3), 0.3),
          bumped(boundary_fan(4, 3), 0.3)};
}

}  // namespace

TEST_CASE("sqrt3 at boundaries: the limit at the vertices two steps make equals their limit masks") {
  // The limit masks (analysis/surface/limit_evaluation.h: the left eigenvector of 1 of each
  // vertex's local subdivision matrix, boundary configurations included) at base vertices and
  // at level 2, the route of `subdiv refine --limit`, against the evaluation's descent.
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    int which = 0;
    for (const test::Mesh& m : meshes()) {
      const int mesh = which++;
      CAPTURE(mesh);
      const Level L = m.level();
      const auto scheme = load_scheme(name);
      const LimitSurface s(scheme, L);
      const LimitResult base = limit_positions(*scheme, L, m.positions);
      double worst_base = 0, worst_interpolation = 0;
      for (Index f = 0; f < L.face_count(); ++f)
        for (int k = 0; k < 3; ++k) {
          const std::array<double, 2> c[3] = {{0, 0}, {1, 0}, {0, 1}};
          const Index w = L.face(f)[size_t(k)];
          const LimitSample p = s.evaluate(f, c[k][0], c[k][1], m.positions, 3, 0);
          worst_base = std::max(worst_base, distance(p.position, std::span(base.positions).subspan(size_t(3 * w), 3)));
          worst_interpolation =
              std::max(worst_interpolation, distance(p.position, std::span(m.positions).subspan(size_t(3 * w), 3)));
        }
      CHECK(worst_base < 1e-13);
      if (std::string(name) == "interpolating-sqrt3") CHECK(worst_interpolation < 1e-13);
      RefineOptions ro;
      ro.levels = 2;
      const Hierarchy h = refine(*scheme, L, ro);
      const std::vector<double> p1 = h.stencils[0].apply(m.positions, 3);
      const std::vector<double> p2 = h.stencils[1].apply(p1, 3);
      LimitOptions lo;
      lo.first_step = 2;
      const LimitResult masks = limit_positions(*scheme, h.levels[2], p2, lo);
      double worst = 0;
      int trisection = 0;
      for (Index v = 0; v < h.levels[2].vertex_count; ++v) {
        const Where x = where_two_steps_put(L, h, v);
        trisection += h.origins[1].kind[size_t(v)] == OriginKind::Edge;
        if (subdiv_test::thinned_out(v)) continue;
        const LimitSample p = s.evaluate(x.face, x.uv[0], x.uv[1], m.positions, 3, 0);
        worst = std::max(worst, distance(p.position, std::span(masks.positions).subspan(size_t(3 * v), 3)));
      }
      Index boundary_edges = 0;
      for (Index e = 0; e < L.edge_count(); ++e) boundary_edges += L.edge_on_boundary(e);
      CHECK(trisection == 2 * boundary_edges);
      MESSAGE(std::string(name) << " mesh " << mesh << ": base vertices " << worst_base << ", level 2 " << worst);
      CHECK(worst < 1e-13);
    }
  }
}

TEST_CASE("sqrt3 at boundaries: continuous across every edge, affine invariant, stencils equal evaluation") {
  const double A[3][3] = {{0.8, -0.3, 0.2}, {0.1, 1.1, -0.4}, {0.5, 0.2, 0.9}}, shift[3] = {1.5, -2, 0.25};
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    for (const test::Mesh& m : meshes()) {
      const Level L = m.level();
      const LimitSurface s(load_scheme(name), L);
      double worst_edge = 0;
      for (Index e = 0; e < L.edge_count(); ++e) {
        if (L.edge_on_boundary(e) || subdiv_test::thinned_out(e)) continue;
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
      std::vector<double> moved(m.positions.size());
      for (size_t v = 0; v < moved.size() / 3; ++v)
        for (int r = 0; r < 3; ++r)
          moved[3 * v + size_t(r)] = shift[r] + A[r][0] * m.positions[3 * v] + A[r][1] * m.positions[3 * v + 1] +
                                     A[r][2] * m.positions[3 * v + 2];
      std::mt19937 rng(5);
      std::uniform_real_distribution<double> U(0, 1);
      double worst_affine = 0, worst_derivative = 0, worst_stencil = 0;
      for (Index f = 0; f < L.face_count(); ++f) {
        double u = U(rng), v = U(rng);
        if (subdiv_test::thinned_out(f / 3)) continue;  // whole runs of three: f % 3 picks the edge case
        if (u + v > 1) u = 1 - u, v = 1 - v;
        if (f % 3 == 0) v = 0;  // on the face's edge 0, a boundary edge for some faces
        const LimitSample p = s.evaluate(f, u, v, m.positions, 3);
        const LimitSample q = s.evaluate(f, u, v, moved, 3);
        // On the boundary itself there are no derivatives (docs/limit.md).
        const bool on_boundary = v == 0 && L.edge_on_boundary(L.face_edge_list(f)[0]);
        CHECK(p.has_derivatives == !on_boundary);
        if (on_boundary) {
          for (int r = 0; r < 3; ++r) {
            double x = shift[r];
            for (int c = 0; c < 3; ++c) x += A[r][c] * p.position[size_t(c)];
            worst_affine = std::max(worst_affine, std::fabs(q.position[size_t(r)] - x));
          }
          continue;
        }
        for (int r = 0; r < 3; ++r) {
          double x = shift[r], du = 0, dv = 0;
          for (int c = 0; c < 3; ++c)
            x += A[r][c] * p.position[size_t(c)], du += A[r][c] * p.du[size_t(c)], dv += A[r][c] * p.dv[size_t(c)];
          worst_affine = std::max(worst_affine, std::fabs(q.position[size_t(r)] - x));
          worst_derivative = std::max({worst_derivative, std::fabs(q.du[size_t(r)] - du), std::fabs(q.dv[size_t(r)] - dv)});
        }
        const LimitStencil w = s.stencil(f, u, v);
        REQUIRE(w.has_derivatives);
        std::array<double, 3> x{}, du{}, dv{};
        for (size_t i = 0; i < w.vertices.size(); ++i)
          for (size_t c = 0; c < 3; ++c) {
            const double pc = m.positions[size_t(3 * w.vertices[i]) + c];
            x[c] += w.position[i] * pc, du[c] += w.du[i] * pc, dv[c] += w.dv[i] * pc;
          }
        worst_stencil = std::max({worst_stencil, distance(x, p.position), distance(du, p.du) / 10, distance(dv, p.dv) / 10});
      }
      CHECK(worst_affine < 1e-13);
      CHECK(worst_derivative < 1e-12);
      CHECK(worst_stencil < 1e-13);
    }
  }
}

TEST_CASE("sqrt3 at boundaries: linear precision along the boundary and two rings inside it") {
  // A triangulated n x n grid with the control points at their grid coordinates: face
  // 2 (j n + i) is (i, j), (i+1, j), (i+1, j+1), its (u, v) the point (i + u + v, j + v);
  // face 2 (j n + i) + 1 is (i, j), (i+1, j+1), (i, j+1): (i + u, j + u + v).
  // - Faces two rings inside: both schemes reproduce linear functions on a regular grid.
  // - The boundary curve, two edges from a corner: the curve rule alone (the ternary cubic
  //   B-spline, cubic Lagrange weights), which reproduces lines with the trisection points at
  //   the thirds.
  // In between the surface is planar but not the identity map: the first step's face point of
  // a boundary triangle has 5 neighbours, and Kobbelt's vertex rule (or Labsik & Greiner's
  // stencil) moves it off the centroid in the second step (docs/limit.md).
  const int n = 8;
  const test::Mesh m = test::grid(n, n, true);
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    const LimitSurface s(load_scheme(name), m.level());
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0, 1);
    double worst = 0, worst_derivative = 0, worst_curve = 0;
    for (Index f = 0; f < m.level().face_count(); ++f) {
      const int half = int(f % 2), i = int(f / 2) % n, j = int(f / 2) / n;
      const bool inside = i >= 2 && j >= 2 && i < n - 2 && j < n - 2;
      const bool curve = j == 0 && half == 0 && i >= 2 && i < n - 2;
      if (!inside && !curve) continue;
      double u = U(rng), v = U(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      if (curve) v = 0;
      const LimitSample p = s.evaluate(f, u, v, m.positions, 3);
      const std::array<double, 3> x = half ? std::array<double, 3>{i + u, j + u + v, 0}
                                           : std::array<double, 3>{i + u + v, j + v, 0};
      const std::array<double, 3> du = half ? std::array<double, 3>{1, 1, 0} : std::array<double, 3>{1, 0, 0};
      const std::array<double, 3> dv = half ? std::array<double, 3>{0, 1, 0} : std::array<double, 3>{1, 1, 0};
      REQUIRE(p.has_derivatives == inside);  // none on the boundary (docs/limit.md)
      if (inside) {
        worst = std::max(worst, distance(p.position, x));
        worst_derivative = std::max({worst_derivative, distance(p.du, du), distance(p.dv, dv)});
      } else {
        worst_curve = std::max(worst_curve, distance(p.position, x));
      }
    }
    MESSAGE(std::string(name) << ": plane " << worst << ", axes " << worst_derivative << "; boundary curve " << worst_curve);
    CHECK(worst < 1e-12);
    CHECK(worst_derivative < 1e-11);
    CHECK(worst_curve < 1e-12);
  }
}

TEST_CASE("sqrt3 at boundaries: derivatives next to the boundary against central differences, none on it") {
  // Points 1e-2 to 1e-6 off a boundary edge (their descent steps on until the boundary is
  // a few rings from their vertex) against central differences with h = 1e-3 of that: the
  // derivatives change on the scale of the distance to the boundary.
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    const test::Mesh m = bumped(test::grid(4, 4, true), 0.3);
    const Level L = m.level();
    const LimitSurface s(load_scheme(name), L);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(0.05, 0.9);
    double worst = 0;
    for (int i = 0; i < 4; ++i) {
      const Index f = Index(2 * i);  // (i, 0), (i + 1, 0), (i + 1, 1): edge 0 on the boundary
      const double u = U(rng);
      CHECK(!s.evaluate(f, u, 0, m.positions, 3).has_derivatives);
      for (double t : {1e-2, 1e-4, 1e-6}) {
        const double h = t / 1000;
        const LimitSample p = s.evaluate(f, u, t, m.positions, 3);
        REQUIRE(p.has_derivatives);
        const LimitSample a = s.evaluate(f, u + h, t, m.positions, 3, 0), b = s.evaluate(f, u - h, t, m.positions, 3, 0);
        const LimitSample c = s.evaluate(f, u, t + h, m.positions, 3, 0), d = s.evaluate(f, u, t - h, m.positions, 3, 0);
        double e = 0;
        for (size_t r = 0; r < 3; ++r) {
          e = std::max(e, std::fabs((a.position[r] - b.position[r]) / (2 * h) - p.du[r]));
          e = std::max(e, std::fabs((c.position[r] - d.position[r]) / (2 * h) - p.dv[r]));
        }
        worst = std::max(worst, e);
      }
    }
    // The interpolating scheme is rougher (its central differences converge more slowly).
    MESSAGE(std::string(name) << ": worst " << worst);
    CHECK(worst < (std::string(name) == "sqrt3" ? 1e-5 : 1e-4));
  }
}

TEST_CASE("sqrt3 at boundaries: derivatives against central differences") {
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    for (const test::Mesh& c : meshes()) {
      const Level L = c.level();
      const LimitSurface s(load_scheme(name), L);
      std::mt19937 rng(2);
      std::uniform_real_distribution<double> U(0.1, 0.8);
      double worst = 0;
      for (Index f = 0; f < L.face_count(); f += 2) {
        double u = U(rng), v = U(rng);
        if (u + v > 0.9) u = 0.9 - u, v = 0.9 - v, u = std::max(u, 0.05), v = std::max(v, 0.05);
        worst = std::max(worst, limit_test::central_difference_error(s, f, u, v, c.positions));
      }
      CHECK(worst < 1e-6);
    }
  }
}

TEST_CASE("sqrt3 at boundaries: refined boundary points approach their limit as the subdominant eigenvalue says") {
  // The trisection point of a boundary edge in a regular stretch of the boundary (3 faces at
  // each end) is a vertex from level 2 on. Its distance to its limit is a second difference of
  // the level, lambda^2 per double step with lambda the subdominant eigenvalue of the regular
  // boundary's double step (the analysis: 1/3, the parameter scaled by 3).
  const auto scheme = load_scheme("sqrt3");
  LocalConfig config;
  config.valence = 4;
  config.boundary = true;
  const SurfaceAnalysis a = analyse_configuration(*scheme, config);
  REQUIRE(a.error.empty());
  CHECK(a.lambda1 == doctest::Approx(1.0 / 3));
  test::Mesh m = test::grid(6, 6, true);
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[size_t(3 * v + 2)] += 0.3 * std::sin(1.3 * v) + 0.1 * double(v % 3);
  const Level L = m.level();
  const LimitSurface s(scheme, L);
  RefineOptions ro;
  ro.levels = 6;
  const Hierarchy h = refine(*scheme, L, ro);
  // Vertices 2 and 3 of the bottom row: the edge of face 4, (2, 0), (3, 0), (3, 1).
  const Index e = find_edge(L, 2, 3);
  REQUIRE(L.edge_on_boundary(e));
  Index v2 = kNone;
  for (Index v = 0; v < h.levels[2].vertex_count; ++v)
    if (h.origins[1].kind[size_t(v)] == OriginKind::Edge) {
      const Where x = where_two_steps_put(L, h, v);
      if (x.face == 4 && std::fabs(x.uv[0] - 1.0 / 3) < 1e-15 && x.uv[1] == 0) v2 = v;
    }
  REQUIRE(v2 != kNone);
  const LimitSample limit = s.evaluate(4, 1.0 / 3, 0, m.positions, 3, 0);
  std::vector<double> p = m.positions;
  std::vector<double> d;
  for (int l = 0; l < 6; ++l) {
    p = h.stencils[size_t(l)].apply(p, 3);
    if (l % 2 == 1) d.push_back(distance(std::span(p).subspan(size_t(3 * v2), 3), limit.position));
  }
  MESSAGE("distances at levels 2, 4, 6: " << d[0] << " " << d[1] << " " << d[2]);
  const double rate = 1 / (a.lambda1 * a.lambda1);
  CHECK(d[0] / d[1] == doctest::Approx(rate).epsilon(0.05));
  CHECK(d[1] / d[2] == doctest::Approx(rate).epsilon(0.02));
}

TEST_CASE("sqrt3 at boundaries: points near and at boundary vertices") {
  for (int sectors : {2, 4}) {
    CAPTURE(sectors);
    const test::Mesh m = bumped(boundary_fan(sectors, 3), 0.3);
    const LimitSurface s(load_scheme("sqrt3"), m.level());
    const LimitSample corner = s.evaluate(0, 0, 0, m.positions, 3);
    // The centre has sectors faces on the boundary: not the regular 3, no derivatives in (u, v).
    CHECK(!corner.has_derivatives);
    const LimitSample near = s.evaluate(0, 1e-300, 0.7e-300, m.positions, 3);
    CHECK(distance(near.position, corner.position) < 1e-15);
    CHECK(near.has_derivatives);
    // On the boundary edge, next to the vertex, and farther along.
    const LimitSample edge = s.evaluate(0, 1e-200, 0, m.positions, 3);
    CHECK(distance(edge.position, corner.position) < 1e-15);
    const LimitSample mid = s.evaluate(0, 1e-8, 0, m.positions, 3, 0);
    const LimitSample far = s.evaluate(0, 1e-4, 0, m.positions, 3, 0);
    CHECK(distance(mid.position, corner.position) < distance(far.position, corner.position));
  }
  // Next to a boundary vertex of 3 faces, as next to one of 2 or 4, derivatives; at it none.
  const test::Mesh g = bumped(test::grid(4, 4, true), 0.3);
  const LimitSurface s(load_scheme("sqrt3"), g.level());
  CHECK(!s.evaluate(4, 0, 0, g.positions, 3).has_derivatives);  // vertex 2 of the bottom row
  CHECK(s.evaluate(4, 1e-12, 1e-12, g.positions, 3).has_derivatives);
}

TEST_CASE("sqrt3 with holes: a hole removes faces, not rules") {
  // Faces tagged as holes keep their rules (OpenSubdiv's convention): every other face has the
  // surface of the mesh without the tags; a point in a hole is refused with the face.
  const test::Mesh m = bumped(test::bipyramid(5));
  Level holed = m.level();
  holed.face_hole.assign(size_t(holed.face_count()), 0);
  holed.face_hole[3] = 1;
  const auto scheme = load_scheme("sqrt3");
  const LimitSurface plain(scheme, m.level()), with_hole(scheme, holed);
  for (Index f = 0; f < holed.face_count(); ++f) {
    if (f == 3) continue;
    const LimitSample p = plain.evaluate(f, 0.21, 0.37, m.positions, 3);
    const LimitSample q = with_hole.evaluate(f, 0.21, 0.37, m.positions, 3);
    CHECK(distance(p.position, q.position) < 1e-15);
    CHECK(distance(p.du, q.du) < 1e-13);
  }
  CHECK_THROWS_WITH_AS(with_hole.evaluate(3, 0.2, 0.2, m.positions, 3), doctest::Contains("hole"), Error);
  // --boundary none makes the faces along a boundary holes; the others are evaluated.
  LimitSurfaceOptions none;
  none.features.boundary = BoundaryInterpolation::None;
  const test::Mesh g = bumped(test::grid(4, 4, true), 0.3);
  const LimitSurface open(scheme, g.level(), none);
  CHECK_THROWS_WITH_AS(open.evaluate(0, 0.2, 0.2, g.positions, 3), doctest::Contains("hole"), Error);
  const LimitSample inside = open.evaluate(2 * (2 * 4 + 2), 0.2, 0.2, g.positions, 3);
  CHECK(inside.has_derivatives);
}

TEST_CASE("sqrt3 at boundaries: the tessellation is closed, with normals on the boundary") {
  const test::Mesh m = bumped(test::grid(4, 4, true), 0.3);
  const Level L = m.level();
  const LimitSurface s(load_scheme("sqrt3"), L);
  const Tessellation t = tessellate(s, m.positions, 2);
  CHECK(t.face_count() == 4 * L.face_count());
  CHECK(t.point_count() == L.vertex_count + L.edge_count());  // corners and edge middles, each once
  // On the boundary the normal is taken beside it (no derivatives there): unit length.
  for (size_t i = 0; i < t.normals.size() / 3; ++i) {
    const double l = std::sqrt(t.normals[3 * i] * t.normals[3 * i] + t.normals[3 * i + 1] * t.normals[3 * i + 1] +
                               t.normals[3 * i + 2] * t.normals[3 * i + 2]);
    CHECK(l == doctest::Approx(1).epsilon(1e-12));
  }
}
