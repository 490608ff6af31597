// Exact limit evaluation of dual schemes (Doo-Sabin, its centroid variant, even-degree quad
// B-splines) at (face, u, v), against mathematics: the uniform B-spline's closed form on a
// regular grid (de Boor's cardinal B-splines, written here independently of the library's
// quadrant basis), linear precision, the limit at a face centre (Doo & Sabin 1978: the
// centroid, which their symmetric face rule preserves), convergence of level-L corner points
// to the limit at their parameters at the rate of the subdominant eigenvalue, continuity
// across every shared edge, finite differences, stencils and affine invariance.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <functional>
#include <random>

#include "framework/engine/refiner.h"
#include "framework/limit/face_domain.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

const double kPi = std::acos(-1.0);

double distance(std::span<const double> a, std::span<const double> b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

// The cardinal B-spline of degree d centred at 0 (support [-(d+1)/2, (d+1)/2]), by the
// Cox-de Boor recurrence N_d(x) = (x N_{d-1}(x) + (d + 1 - x) N_{d-1}(x - 1)) / d on [0, d + 1].
double cardinal(int d, double x) {
  std::function<double(int, double)> N = [&](int k, double y) -> double {
    if (k == 0) return y >= 0 && y < 1 ? 1.0 : 0.0;
    return (y * N(k - 1, y) + (k + 1 - y) * N(k - 1, y - 1)) / k;
  };
  return N(d, x + 0.5 * (d + 1));
}
double cardinal_d(int d, double x) { return cardinal(d - 1, x + 0.5) - cardinal(d - 1, x - 0.5); }

test::Mesh bumped(test::Mesh m) {
  for (Index v = 0; v < m.vertex_count; ++v) {
    m.positions[size_t(3 * v)] += 0.07 * std::sin(2.3 * v + 0.1);
    m.positions[size_t(3 * v + 2)] += 0.1 * std::sin(1.7 * v + 0.3);
  }
  return m;
}

// The n x n torus of test::torus: vertex (i, j) is j n + i; face (i, j) has corners (i, j),
// (i+1, j), (i+1, j+1), (i, j+1), so its (u, v) are the grid's (x - i, y - j).
struct TorusPoint {
  Index face;
  double u, v;
};

// The tensor-product B-spline of degree d over the torus' control points, at grid point (x, y).
std::array<double, 9> bspline_on_torus(const test::Mesh& m, int n, int d, double x, double y) {
  std::array<double, 9> out{};  // position, d/dx, d/dy
  const int lo = int(std::floor(x)) - d - 1, hi = int(std::floor(x)) + d + 2;
  const int loy = int(std::floor(y)) - d - 1, hiy = int(std::floor(y)) + d + 2;
  for (int j = loy; j <= hiy; ++j)
    for (int i = lo; i <= hi; ++i) {
      const double bx = cardinal(d, x - i), by = cardinal(d, y - j);
      const double dx = cardinal_d(d, x - i), dy = cardinal_d(d, y - j);
      const Index v = Index(((j % n + n) % n) * n + (i % n + n) % n);
      for (int c = 0; c < 3; ++c) {
        const double p = m.positions[size_t(3 * v + c)];
        out[size_t(c)] += bx * by * p;
        out[size_t(3 + c)] += dx * by * p;
        out[size_t(6 + c)] += bx * dy * p;
      }
    }
  return out;
}

// (u, v) of a point of an n-gon's quadrant (sub-face) j at (a, b), in Bfr's QUAD_SUBFACES layout.
std::array<double, 2> sub_face_uv(int n, int j, double a, double b) {
  const int columns = sub_face_columns(n);
  return {j % columns + 0.5 * a, j / columns + 0.5 * b};
}
// (u, v) of the point at t along edge k (from corner k to k + 1) of a face of size n.
std::array<double, 2> edge_uv(int n, int k, double t) {
  if (n == 4) {
    constexpr double c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const int l = (k + 1) % 4;
    return {c[k][0] + t * (c[l][0] - c[k][0]), c[k][1] + t * (c[l][1] - c[k][1])};
  }
  return t <= 0.5 ? sub_face_uv(n, k, 2 * t, 0) : sub_face_uv(n, (k + 1) % n, 0, 2 * (1 - t));
}

std::shared_ptr<const Scheme> quad_bspline(int d) { return load_scheme("quad-bspline", {{"d", std::to_string(d)}}); }

}  // namespace

TEST_CASE("Dual schemes on a regular grid are the biquadratic B-spline, with its derivatives") {
  const int n = 10;
  const test::Mesh m = bumped(test::torus(n, n));
  for (const auto& scheme : {load_scheme("doo-sabin"), load_scheme("doo-sabin-centroid"), quad_bspline(2)}) {
    CAPTURE(scheme->name);
    const LimitSurface s(scheme, m.level());
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(0, 1);
    double worst = 0, worst_d = 0;
    for (int k = 0; k < 40; ++k) {
      const int i = int(U(rng) * n) % n, j = int(U(rng) * n) % n;
      const double u = U(rng), v = U(rng);
      const LimitSample p = s.evaluate(Index(j * n + i), u, v, m.positions, 3);
      const auto e = bspline_on_torus(m, n, 2, i + u, j + v);
      REQUIRE(p.has_derivatives);
      worst = std::max(worst, distance(p.position, std::span(e).subspan(0, 3)));
      worst_d = std::max(worst_d, distance(p.du, std::span(e).subspan(3, 3)) + distance(p.dv, std::span(e).subspan(6, 3)));
    }
    CHECK(worst < 1e-13);
    CHECK(worst_d < 1e-12);
  }
}

TEST_CASE("Dual schemes have linear precision in the quadrant parameterisation") {
  // Control points at their own grid coordinates (a 16 x 16 torus unrolled away from the
  // seam, which the faces evaluated here do not read): the limit is the plane (i + u, j + v).
  const int n = 16;
  const test::Mesh m = limit_test::unrolled_torus(n);
  const LimitSurface s(load_scheme("doo-sabin"), m.level());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  for (int k = 0; k < 30; ++k) {
    const int i = 7 + k % 2, j = 7 + (k / 2) % 2;
    const double u = U(rng), v = U(rng);
    const LimitSample p = s.evaluate(Index(j * n + i), u, v, m.positions, 3);
    CHECK(std::fabs(p.position[0] - (i + u)) < 1e-12);
    CHECK(std::fabs(p.position[1] - (j + v)) < 1e-12);
    CHECK(std::fabs(p.du[0] - 1) < 1e-12);
    CHECK(std::fabs(p.dv[1] - 1) < 1e-12);
    CHECK(std::fabs(p.du[1]) + std::fabs(p.dv[0]) < 1e-12);
  }
}

TEST_CASE("The limit at a face centre is the centroid of the face, and points towards it converge to it") {
  // Doo & Sabin 1978: the new points of a face are a symmetric circulant combination of its
  // corners (weights summing to one by rows and by columns), so every F-face has the same
  // centroid, and the F-faces shrink to it: the limit at the face's centre.
  const test::Mesh m = bumped(test::bipyramid(5));
  for (const char* name : {"doo-sabin", "doo-sabin-centroid"}) {
    CAPTURE(std::string(name));
    const LimitSurface s(load_scheme(name), m.level());
    const Level& L = s.base();
    for (Index f : {Index(0), Index(3)}) {
      std::array<double, 3> centroid{};
      for (Index v : L.face(f))
        for (int c = 0; c < 3; ++c) centroid[size_t(c)] += m.positions[size_t(3 * v + c)] / 3;
      const auto uv = sub_face_uv(3, 1, 1, 1);
      const LimitSample p = s.evaluate(f, uv[0], uv[1], m.positions, 3);
      CHECK(distance(p.position, centroid) < 1e-14);
      CHECK_FALSE(p.has_derivatives);  // an extraordinary point: the parameterisation is singular
      double last = 1;
      for (double e : {1e-2, 1e-4, 1e-8, 1e-12}) {
        const auto q = sub_face_uv(3, 2, 1 - e, 1 - 0.5 * e);
        const double d = distance(s.evaluate(f, q[0], q[1], m.positions, 3).position, centroid);
        CHECK(d < last);
        last = d;
      }
      CHECK(last < 1e-5);
    }
  }
}

TEST_CASE("Level-L corner points approach the limit at their parameters at the subdominant eigenvalue's rate") {
  // The new point of corner (g, j) sits at the centre of quadrant (g, j); following corner j
  // of a face's F-faces, the level-L point has parameter (1 - 2^-L, 1 - 2^-L) in the base
  // quadrant j. Near an extraordinary face centre both the point and the limit there move
  // by lambda^L (lambda the subdominant eigenvalue), and so does their distance. The face
  // rule's circulant has eigenvalues sum_i w_i cos(2 pi i k / n): for Doo-Sabin 1/2 at k = 1
  // for every n and 1/4 beyond (Doo & Sabin 1978), for the centroid variant
  // 1/2 + cos(2 pi k / n)/4. The next eigenvalue mu is removed (below): with it the rate is
  // within 1% by level 8, where the plain ratio d_(L+1) / d_L still converges (0.59 at level 9
  // for the centroid variant's pentagon).
  struct Case {
    const char* scheme;
    test::Mesh mesh;
    Index face;
    int n;
    double lambda, mu;
  };
  const std::vector<Case> cases{
      {"doo-sabin", bumped(test::bipyramid(5)), 0, 3, 0.5, 0.25},
      {"doo-sabin-centroid", [] {
         // A pentagonal prism: two pentagons among quads.
         test::Mesh p;
         for (int k = 0; k < 2; ++k)
           for (int i = 0; i < 5; ++i)
             p.add_vertex(std::cos(2 * kPi * i / 5), std::sin(2 * kPi * i / 5), double(k));
         p.add_face({4, 3, 2, 1, 0});
         p.add_face({5, 6, 7, 8, 9});
         for (int i = 0; i < 5; ++i)
           p.add_face({Index(i), Index((i + 1) % 5), Index(5 + (i + 1) % 5), Index(5 + i)});
         return bumped(p);
       }(), 1, 5, 0.5 + std::cos(2 * kPi / 5) / 4, 0.5 + std::cos(4 * kPi / 5) / 4}};
  for (const Case& c : cases) {
    CAPTURE(std::string(c.scheme));
    const auto scheme = load_scheme(c.scheme);
    const LimitSurface s(scheme, c.mesh.level());
    RefineOptions ro;
    ro.levels = 9;
    const Hierarchy h = refine(*scheme, c.mesh.level(), ro);
    std::vector<double> P = c.mesh.positions;
    Index g = c.face;
    int j = 1;
    std::vector<double> ratios;
    double previous = 0, before = 0;
    for (int l = 1; l <= 9; ++l) {
      P = h.stencils[size_t(l - 1)].apply(P, 3);
      const ChildOrigins& o = h.origins[size_t(l - 1)];
      Index corner = kNone, F = kNone;
      for (size_t x = 0; x < o.kind.size(); ++x)
        if (o.kind[x] == OriginKind::Corner && o.parent[x] == g && int(o.local[x]) == j) corner = Index(x);
      const Level& child = h.levels[size_t(l)];
      for (Index f = 0; f < child.face_count(); ++f)
        if (o.parent_face[size_t(f)] == g) F = f;
      REQUIRE(corner != kNone);
      REQUIRE(F != kNone);
      const double t = 1 - std::ldexp(1.0, -l);
      const auto uv = sub_face_uv(c.n, 1, t, t);
      const LimitSample p = s.evaluate(c.face, uv[0], uv[1], c.mesh.positions, 3);
      const double d = distance(p.position, std::span(P).subspan(size_t(3 * corner), 3));
      // With the next eigenvalue mu known, d_L = A lambda^L + B mu^L + ... gives
      // (d_L - mu d_(L-1)) / (d_(L-1) - mu d_(L-2)) = lambda up to the third eigenvalue.
      if (l >= 8) ratios.push_back((d - c.mu * previous) / (previous - c.mu * before));
      before = previous;
      previous = d;
      const auto cs = child.face(F);
      j = int(std::find(cs.begin(), cs.end(), corner) - cs.begin());
      g = F;
    }
    REQUIRE(ratios.size() == 2);
    for (double r : ratios) CHECK(r == doctest::Approx(c.lambda).epsilon(0.015));
  }
}

namespace {

struct Shape {
  const char* name;
  test::Mesh mesh;
};
std::vector<Shape> extraordinary_shapes() {
  return {{"cube (valence-3 vertices)", bumped(test::cube())},
          {"bipyramid (triangles, valence-5 vertices)", bumped(test::bipyramid(5))},
          {"pyramid (a quad among triangles)", bumped(test::pyramid())}};
}

}  // namespace

TEST_CASE("Dual limits are continuous across every shared edge") {
  for (const char* scheme : {"doo-sabin", "doo-sabin-centroid"}) {
    for (const Shape& shape : extraordinary_shapes()) {
      CAPTURE(std::string(scheme));
      CAPTURE(std::string(shape.name));
      const LimitSurface s(load_scheme(scheme), shape.mesh.level());
      const Level& L = s.base();
      double worst = 0;
      for (Index e = 0; e < L.edge_count(); ++e) {
        const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
        for (double t : {0.3, 0.5, 0.71}) {
          std::vector<std::vector<double>> seen;
          for (int side = 0; side < 2; ++side) {
            const Index f = L.edge_faces[size_t(2 * e + side)];
            const auto c = L.face(f);
            const int n = int(c.size());
            int k = 0;
            while (!(c[size_t(k)] == a && c[size_t((k + 1) % n)] == b) && !(c[size_t(k)] == b && c[size_t((k + 1) % n)] == a)) ++k;
            const double along = c[size_t(k)] == a ? t : 1 - t;
            const auto uv = edge_uv(n, k, along);
            seen.push_back(s.evaluate(f, uv[0], uv[1], shape.mesh.positions, 3).position);
          }
          worst = std::max(worst, distance(seen[0], seen[1]));
        }
      }
      CHECK(worst < 1e-13);
    }
  }
}

TEST_CASE("Dual derivatives agree with finite differences, stencils with evaluation, and evaluation is affine invariant") {
  for (const Shape& shape : extraordinary_shapes()) {
    CAPTURE(std::string(shape.name));
    const LimitSurface s(load_scheme("doo-sabin"), shape.mesh.level());
    const Level& L = s.base();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0.05, 0.45);
    // A rotation about (1, 1, 1) by 0.7 and a shift.
    const double c = std::cos(0.7), sn = std::sin(0.7), k = 1 / std::sqrt(3.0);
    const double R[3][3] = {{c + k * k * (1 - c), k * k * (1 - c) - k * sn, k * k * (1 - c) + k * sn},
                            {k * k * (1 - c) + k * sn, c + k * k * (1 - c), k * k * (1 - c) - k * sn},
                            {k * k * (1 - c) - k * sn, k * k * (1 - c) + k * sn, c + k * k * (1 - c)}};
    auto moved = [&](std::span<const double> p) {
      std::vector<double> q(p.size());
      for (size_t v = 0; v < p.size() / 3; ++v)
        for (int i = 0; i < 3; ++i)
          q[3 * v + size_t(i)] = 0.5 * i - 2 + R[i][0] * p[3 * v] + R[i][1] * p[3 * v + 1] + R[i][2] * p[3 * v + 2];
      return q;
    };
    const std::vector<double> Q = moved(shape.mesh.positions);
    double worst_fd = 0, worst_stencil = 0, worst_affine = 0;
    for (int trial = 0; trial < 24; ++trial) {
      const Index f = Index(trial % L.face_count());
      const int n = L.face_size(f);
      const int j = trial % n;
      const auto uv = n == 4 ? std::array<double, 2>{U(rng) + (j % 2) * 0.5, U(rng) + (j / 2) * 0.5}
                             : sub_face_uv(n, j, 2 * U(rng), 2 * U(rng));
      const LimitSample p = s.evaluate(f, uv[0], uv[1], shape.mesh.positions, 3);
      REQUIRE(p.has_derivatives);
      const double h = 1e-6;
      const auto at = [&](double du, double dv) { return s.evaluate(f, uv[0] + du, uv[1] + dv, shape.mesh.positions, 3, 0).position; };
      const auto pu = at(h, 0), mu = at(-h, 0), pv = at(0, h), mv = at(0, -h);
      for (int i = 0; i < 3; ++i) {
        worst_fd = std::max(worst_fd, std::fabs((pu[size_t(i)] - mu[size_t(i)]) / (2 * h) - p.du[size_t(i)]));
        worst_fd = std::max(worst_fd, std::fabs((pv[size_t(i)] - mv[size_t(i)]) / (2 * h) - p.dv[size_t(i)]));
      }
      const LimitStencil w = s.stencil(f, uv[0], uv[1]);
      std::array<double, 3> x{}, xu{};
      for (size_t e = 0; e < w.vertices.size(); ++e)
        for (int i = 0; i < 3; ++i) {
          x[size_t(i)] += w.position[e] * shape.mesh.positions[size_t(3 * w.vertices[e] + i)];
          xu[size_t(i)] += w.du[e] * shape.mesh.positions[size_t(3 * w.vertices[e] + i)];
        }
      worst_stencil = std::max(worst_stencil, distance(x, p.position) + distance(xu, p.du));
      const LimitSample q = s.evaluate(f, uv[0], uv[1], Q, 3);
      worst_affine = std::max(worst_affine, distance(q.position, moved(p.position)));
    }
    CHECK(worst_fd < 1e-7);
    CHECK(worst_stencil < 1e-13);
    CHECK(worst_affine < 1e-13);
  }
}

TEST_CASE("Even-degree quad B-splines beyond degree 2 are evaluated exactly at face centres") {
  // Degree 4 (a dual split and a smoothing pass): no closed form is taken, so a point descends
  // until it is a face centre, where the face's limit mask gives it. On a regular torus that
  // is the biquartic B-spline (de Boor) at the grid point.
  const int n = 10;
  const test::Mesh m = bumped(test::torus(n, n));
  const LimitSurface s(quad_bspline(4), m.level());
  for (const auto& [u, v] : std::vector<std::array<double, 2>>{{0.5, 0.5}, {0.25, 0.75}, {0.375, 0.125}, {0, 0}}) {
    const LimitSample p = s.evaluate(Index(4 * n + 3), u, v, m.positions, 3);
    const auto e = bspline_on_torus(m, n, 4, 3 + u, 4 + v);
    CHECK(distance(p.position, std::span(e).subspan(0, 3)) < 1e-13);
  }
}

TEST_CASE("Mid-edge schemes on meshes with boundaries are refused with the reason") {
  CHECK_THROWS_WITH_AS(LimitSurface(load_scheme("mid-edge"), test::grid(3, 3).level()),
                       doctest::Contains("mid-edge split and the mesh has a boundary"), Error);
}

TEST_CASE("Points very close to an extraordinary vertex keep their digits and their tangent plane") {
  // A cube corner (valence 3: a triangular V-face, an extraordinary point). The quadrant
  // coordinates are kept as distances from the nearer end, so a point at 1e-17 is not
  // rounded onto the corner (1 - 4e-17 would be 1): it has derivatives, its normal tends to the corner's tangent
  // plane, and its distance to the corner's limit shrinks with the parameter.
  const test::Mesh m = bumped(test::cube());
  const LimitSurface s(load_scheme("doo-sabin"), m.level());
  const LimitSample corner = s.evaluate(0, 0, 0, m.positions, 3);
  auto normal = [](const LimitSample& p) {
    std::array<double, 3> n{p.du[1] * p.dv[2] - p.du[2] * p.dv[1], p.du[2] * p.dv[0] - p.du[0] * p.dv[2],
                            p.du[0] * p.dv[1] - p.du[1] * p.dv[0]};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x /= l;
    return n;
  };
  double last = 1;
  std::array<double, 3> previous{};
  for (double e : {1e-6, 1e-9, 1e-12, 1e-15, 1e-17}) {
    const LimitSample p = s.evaluate(0, e, 0.7 * e, m.positions, 3);
    REQUIRE(p.has_derivatives);
    const double d = distance(p.position, corner.position);
    CHECK(d < last);
    last = d;
    const auto n = normal(p);
    if (e < 1e-6) CHECK(distance(n, previous) < 1e-3);
    previous = n;
  }
  CHECK(last < 1e-13);
}

TEST_CASE("Dual schemes refuse the faces at an interior vertex of valence 2, and evaluate the others") {
  // The cube's top face (4, 5, 7, 6) as two quads (4, 5, 7, 8) and (4, 8, 7, 6) around a
  // vertex 8 inside it: 8 has the two edges 4-8 and 8-7, so a dual split's face for it would
  // have two sides (OpenSubdiv's catmark_val2_* shapes have such vertices). Before, a point
  // of those faces stopped at an internal error; the faces elsewhere never reach the vertex.
  test::Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  m.add_vertex(0.6, 0.4, 1.1);
  m.add_face({0, 2, 3, 1}), m.add_face({4, 5, 7, 8}), m.add_face({4, 8, 7, 6});
  m.add_face({0, 1, 5, 4}), m.add_face({2, 6, 7, 3}), m.add_face({0, 4, 6, 2}), m.add_face({1, 3, 7, 5});
  const LimitSurface s(load_scheme("doo-sabin"), m.level());
  REQUIRE(s.base().valence(8) == 2);
  for (Index f : {1, 2})
    CHECK_THROWS_WITH_AS(s.evaluate(f, 0.3, 0.6, m.positions, 3),
                         doctest::Contains("has a corner at interior vertex 8 of valence 2"), Error);
  // The bottom face touches neither 8 nor its neighbours 4 and 7: its limit is continuous
  // with its neighbours' and affine invariant.
  const LimitSample bottom = s.evaluate(0, 0, 0.5, m.positions, 3);  // corners 3, 0 of face 0 are 1, 0
  const LimitSample side = s.evaluate(3, 0.5, 0, m.positions, 3);  // the shared edge 0-1, from face 3
  CHECK(distance(bottom.position, side.position) < 1e-13);
  test::Mesh shifted = m;
  for (size_t k = 0; k < shifted.positions.size(); k += 3) shifted.positions[k] += 2.5;
  const LimitSample moved = s.evaluate(0, 0.3, 0.3, shifted.positions, 3);
  CHECK(std::fabs(moved.position[0] - 2.5 - s.evaluate(0, 0.3, 0.3, m.positions, 3).position[0]) < 1e-13);
  // The mid-edge split makes the same two-sided face there: the mesh is refused (was an
  // internal error at the first point).
  CHECK_THROWS_WITH_AS(LimitSurface(load_scheme("mid-edge"), m.level()),
                       doctest::Contains("interior vertex 8 has valence 2"), Error);
}
