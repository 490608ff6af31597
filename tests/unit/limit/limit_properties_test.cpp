// Properties of limit evaluation that hold for every supported scheme, with or without a
// reference library: stencils equal evaluation, continuity across shared edges, affine
// invariance, derivatives against finite differences, corners against the limit masks,
// convergence of level-L vertices to the limit at the rate of the subdominant eigenvalue,
// and clear refusals.
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

using namespace subdiv;

namespace {

using limit_test::octahedron;

test::Mesh bumped(test::Mesh m) {
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[size_t(3 * v + 2)] += 0.1 * std::sin(1.7 * v + 0.3);
  return m;
}

double distance(std::span<const double> a, std::span<const double> b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

struct Case {
  const char* scheme;
  test::Mesh mesh;
  bool triangles;
};

std::vector<Case> cases() {
  return {{"catmull-clark", bumped(test::cube()), false},
          {"loop", bumped(octahedron()), true},
          {"butterfly", bumped(octahedron()), true},
          {"loop-composite", bumped(octahedron()), true},
          {"modified-butterfly", bumped(test::grid(4, 4, true)), true}};
}

}  // namespace

TEST_CASE("A limit stencil applied to the control points is the evaluated point") {
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.scheme));
    const LimitSurface s(load_scheme(c.scheme), c.mesh.level());
    const LimitSample p = s.evaluate(1, 0.3, 0.2, c.mesh.positions, 3);
    const LimitStencil w = s.stencil(1, 0.3, 0.2);
    std::vector<double> q(3, 0.0), du(3, 0.0);
    double sum = 0;
    for (size_t k = 0; k < w.vertices.size(); ++k) {
      sum += w.position[k];
      for (int a = 0; a < 3; ++a) {
        q[size_t(a)] += w.position[k] * c.mesh.positions[size_t(3 * w.vertices[k] + a)];
        if (w.has_derivatives) du[size_t(a)] += w.du[k] * c.mesh.positions[size_t(3 * w.vertices[k] + a)];
      }
    }
    CHECK(sum == doctest::Approx(1.0).epsilon(1e-13));
    CHECK(distance(q, p.position) < 1e-13);
    REQUIRE(w.has_derivatives == p.has_derivatives);
    if (p.has_derivatives) CHECK(distance(du, p.du) < 1e-12);
  }
}

TEST_CASE("Limit evaluation is affine invariant and continuous across shared edges") {
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.scheme));
    const Level base = c.mesh.level();
    const LimitSurface s(load_scheme(c.scheme), base);
    // An affine map: rotation-shear plus a shift.
    std::vector<double> moved(c.mesh.positions.size());
    const double A[3][3] = {{0.8, -0.6, 0.1}, {0.6, 0.8, 0.2}, {0.0, 0.3, 1.1}}, b[3] = {2, -1, 0.5};
    for (Index v = 0; v < base.vertex_count; ++v)
      for (int i = 0; i < 3; ++i) {
        double x = b[i];
        for (int j = 0; j < 3; ++j) x += A[i][j] * c.mesh.positions[size_t(3 * v + j)];
        moved[size_t(3 * v + i)] = x;
      }
    const LimitSample p = s.evaluate(0, 0.15, 0.35, c.mesh.positions, 3);
    const LimitSample q = s.evaluate(0, 0.15, 0.35, moved, 3);
    std::vector<double> expect(3);
    for (int i = 0; i < 3; ++i) {
      expect[size_t(i)] = b[i];
      for (int j = 0; j < 3; ++j) expect[size_t(i)] += A[i][j] * p.position[size_t(j)];
    }
    CHECK(distance(expect, q.position) < 1e-13);
    // Every shared edge of the mesh: the points at t = 0.375 and at an irrational-looking
    // t along it, from both faces. The two faces reach each point through different
    // neighbourhoods and steps, so only the limit can make them agree.
    auto along = [&](int corner, double x) -> std::array<double, 2> {
      if (c.triangles) {
        const double cu[3] = {0, 1, 0}, cv[3] = {0, 0, 1};
        const int c1 = (corner + 1) % 3;
        return {cu[corner] + x * (cu[c1] - cu[corner]), cv[corner] + x * (cv[c1] - cv[corner])};
      }
      const double cu[4] = {0, 1, 1, 0}, cv[4] = {0, 0, 1, 1};
      const int c1 = (corner + 1) % 4;
      return {cu[corner] + x * (cu[c1] - cu[corner]), cv[corner] + x * (cv[c1] - cv[corner])};
    };
    for (Index f = 0; f < base.face_count(); ++f) {
      const auto corners = base.face(f);
      const int n = int(corners.size());
      for (int k = 0; k < n; ++k) {
        const Index a = corners[size_t(k)], bb = corners[size_t((k + 1) % n)];
        const Index e = find_edge(base, a, bb);
        const Index g = base.edge_faces[size_t(2 * e)] == f ? base.edge_faces[size_t(2 * e + 1)] : base.edge_faces[size_t(2 * e)];
        if (g == kNone || g < f) continue;
        const auto gc = base.face(g);
        int kb = 0;
        while (gc[size_t(kb)] != bb) ++kb;
        for (double t : {0.375, 0.6180339887}) {
          const auto in0 = along(k, t), ing = along(kb, 1 - t);
          const LimitSample x = s.evaluate(f, in0[0], in0[1], c.mesh.positions, 3);
          const LimitSample y = s.evaluate(g, ing[0], ing[1], c.mesh.positions, 3);
          CHECK(distance(x.position, y.position) < 1e-13);
        }
      }
    }
  }
}

TEST_CASE("Derivatives agree with finite differences of evaluated points") {
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.scheme));
    const LimitSurface s(load_scheme(c.scheme), c.mesh.level());
    const double u = 0.3, v = 0.2, h = 1e-5;
    const LimitSample p = s.evaluate(2, u, v, c.mesh.positions, 3);
    REQUIRE(p.has_derivatives);
    const LimitSample pu = s.evaluate(2, u + h, v, c.mesh.positions, 3), mu = s.evaluate(2, u - h, v, c.mesh.positions, 3);
    const LimitSample pv = s.evaluate(2, u, v + h, c.mesh.positions, 3), mv = s.evaluate(2, u, v - h, c.mesh.positions, 3);
    std::vector<double> fu(3), fv(3);
    for (int i = 0; i < 3; ++i) {
      fu[size_t(i)] = (pu.position[size_t(i)] - mu.position[size_t(i)]) / (2 * h);
      fv[size_t(i)] = (pv.position[size_t(i)] - mv.position[size_t(i)]) / (2 * h);
    }
    // Central differences: error h^2 times the third derivative where the surface is C3
    // (the approximating schemes' regular patches), more for the butterflies, which are C1
    // with Hoelder-continuous derivatives only; plus rounding 1e-16 / h.
    CHECK(distance(fu, p.du) < 1e-6);
    CHECK(distance(fv, p.dv) < 1e-6);
  }
}

TEST_CASE("At a base vertex the evaluation is the vertex's limit mask, which level-L vertices approach geometrically") {
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.scheme));
    const auto scheme = load_scheme(c.scheme);
    const Level base = c.mesh.level();
    const LimitSurface s(scheme, base);
    const LimitResult masks = limit_positions(*scheme, base, c.mesh.positions);
    const Index v0 = base.face(0)[0];
    const LimitSample p = s.evaluate(0, 0, 0, c.mesh.positions, 3);
    CHECK(distance(p.position, std::span<const double>(masks.positions).subspan(size_t(3 * v0), 3)) < 1e-13);
    // The vertex v0 at level L converges to the evaluated limit geometrically, like
    // lambda^L for an eigenvalue lambda < 1 of its local subdivision matrix (the largest
    // whose eigenvector does not vanish at the centre): successive distances keep one ratio.
    RefineOptions o;
    o.levels = 6;
    const Hierarchy h = refine(*scheme, base, o);
    std::vector<double> d;
    for (int L = 3; L <= 6; ++L) {
      const auto P = interpolate(h, L, c.mesh.positions, 3);
      d.push_back(distance(std::span<const double>(P).subspan(size_t(3 * v0), 3), p.position));
    }
    if (d.back() < 1e-13) continue;  // interpolatory: the vertex is its limit at every level
    const double ratio = d[3] / d[2], previous = d[2] / d[1];
    MESSAGE(std::string(c.scheme), ": distance ratios ", previous, ", ", ratio);
    CHECK(std::fabs(ratio - previous) < 0.05 * ratio);
    CHECK(ratio < 0.5);
  }
}

TEST_CASE("Points arbitrarily close to an extraordinary vertex cost no more than others and tend to its limit") {
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.scheme));
    const LimitSurface s(load_scheme(c.scheme), c.mesh.level());
    const LimitSample corner = s.evaluate(0, 0, 0, c.mesh.positions, 3);
    const LimitSample near = s.evaluate(0, 1e-300, 0.7e-300, c.mesh.positions, 3);
    const LimitSample far = s.evaluate(0, 0.3, 0.2, c.mesh.positions, 3);
    CHECK(near.steps <= far.steps + 16);
    CHECK(distance(near.position, corner.position) < 1e-14);
    CHECK(near.has_derivatives);
    // Approaching a vertex of a finer level along an edge: more than 1023 levels in all,
    // whose Jacobian 2^level is carried scaled (it would overflow).
    const LimitSample edge = s.evaluate(0, 1e-300, 0.5, c.mesh.positions, 3);
    const LimitSample edge_before = s.evaluate(0, 1e-250, 0.5, c.mesh.positions, 3);
    REQUIRE(edge.has_derivatives);
    CHECK(distance(edge.du, edge_before.du) < 1e-12);
    CHECK(distance(edge.dv, edge_before.dv) < 1e-12);
    // Between: the distance to the corner's limit shrinks with the parameter.
    const LimitSample mid = s.evaluate(0, 1e-8, 0.7e-8, c.mesh.positions, 3);
    CHECK(distance(mid.position, corner.position) < 1e-5);
    CHECK(distance(mid.position, corner.position) > distance(near.position, corner.position));
  }
}

TEST_CASE("Schemes without a fixed limit operator, and unsupported splits, are refused with the reason") {
  CHECK_THROWS_WITH_AS(LimitSurface(load_scheme("mid-edge"), test::grid(2, 2).level()),
                       doctest::Contains("mid-edge split and the mesh has a boundary"), Error);
  const LimitSurface s(load_scheme("catmull-clark"), test::cube().level());
  CHECK(s.check(7, 0.5, 0.5).find("does not exist") != std::string::npos);
  CHECK(s.check(0, 1.5, 0.5).find("outside the unit square") != std::string::npos);
  CHECK(s.check(0, std::nan(""), 0.5).find("finite") != std::string::npos);
}

TEST_CASE("Non-manifold meshes are refused with the reason under splits other than the binary ones") {
  // Three quads on one edge (the binary splits evaluate it: non_manifold_limit_test.cpp).
  test::Mesh m;
  m.vertex_count = 8;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, -1, 0.5, 1, -1, 0.5, 0, 0, 1, 1, 0, 1};
  m.corners = {0, 1, 3, 2, 1, 0, 4, 5, 0, 1, 7, 6};
  m.offsets = {0, 4, 8, 12};
  CHECK_THROWS_WITH_AS(LimitSurface(load_scheme("doo-sabin"), m.level()), doctest::Contains("non-manifold"), Error);
}
