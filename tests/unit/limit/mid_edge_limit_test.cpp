// Limit evaluation of the mid-edge scheme (Peters & Reif 1997) at (face, u, v), in the dual
// quadrants of the halved grid (docs/limit.md), against closed forms: a mid-edge step keeps
// the centroid of every face (the middles of a polygon's edges have its vertices' centroid),
// so the limit at a face's centre is its centroid, at a base vertex w the centroid of its
// V-face, (w + mean of its neighbours) / 2, and at an edge's middle the centroid of that
// edge's V-face one step later; the vertices two steps make against their limit masks (the
// route of `subdiv refine --limit`); linear precision; continuity across every edge; affine
// invariance; stencils; the refusals.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>

#include "framework/analysis/surface/limit_evaluation.h"
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

using Point = std::array<double, 3>;

using limit_test::distance;

using limit_test::bumped;

// A tetrahedron: triangles only, every vertex of valence 3.
test::Mesh tetrahedron() {
  test::Mesh m;
  m.add_vertex(1, 1, 1), m.add_vertex(1, -1, -1), m.add_vertex(-1, 1, -1), m.add_vertex(-1, -1, 1);
  m.add_face({0, 1, 2}), m.add_face({0, 2, 3}), m.add_face({0, 3, 1}), m.add_face({1, 3, 2});
  return m;
}

// Closed meshes with quads, triangles (sub-faces) and vertices of valence 3, 4 and 5.
std::vector<test::Mesh> meshes() {
  return {bumped(test::cube()), bumped(test::pyramid()), bumped(test::bipyramid(5)), bumped(tetrahedron())};
}

Point at(const test::Mesh& m, Index v) {
  return {m.positions[size_t(3 * v)], m.positions[size_t(3 * v + 1)], m.positions[size_t(3 * v + 2)]};
}
Point mean(const std::vector<Point>& ps) {
  Point s{0, 0, 0};
  for (const Point& p : ps)
    for (size_t i = 0; i < 3; ++i) s[i] += p[i] / double(ps.size());
  return s;
}
Point middle(const test::Mesh& m, Index a, Index b) { return mean({at(m, a), at(m, b)}); }

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
// (u, v) of the centre of quadrant j of a face of size n at (a, b).
std::array<double, 2> quadrant_uv(int n, int j, double a, double b) {
  if (n != 4) return sub_face_uv(n, j, a, b);
  constexpr double c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto& o = c[j];
  const auto& e = c[(j + 1) % 4];
  const auto& f = c[(j + 3) % 4];
  return {o[0] + 0.5 * (a * (e[0] - o[0]) + b * (f[0] - o[0])), o[1] + 0.5 * (a * (e[1] - o[1]) + b * (f[1] - o[1]))};
}

}  // namespace

TEST_CASE("mid-edge: the limit at face centres, base vertices and edge middles is the centroid the steps keep") {
  const auto scheme = load_scheme("mid-edge");
  for (const test::Mesh& m : meshes()) {
    const Level L = m.level();
    const LimitSurface s(scheme, L);
    CHECK(!s.triangles());
    double worst = 0;
    for (Index f = 0; f < L.face_count(); ++f) {
      const auto fv = L.face(f);
      const int n = int(fv.size());
      std::vector<Point> corners;
      for (Index v : fv) corners.push_back(at(m, v));
      const auto centre = n == 4 ? std::array<double, 2>{0.5, 0.5} : sub_face_uv(n, 0, 1, 1);
      const LimitSample c = s.evaluate(f, centre[0], centre[1], m.positions, 3);
      CHECK(c.has_derivatives == (n == 4));  // the centre of an n-gon is an extraordinary point
      worst = std::max(worst, distance(c.position, mean(corners)));
      for (int k = 0; k < n; ++k) {
        // The corner: w and the middles of its edges (V-face of the first step).
        const Index w = fv[size_t(k)];
        std::vector<Point> ring;
        for (Index e : L.ring_edges(w)) ring.push_back(middle(m, w, L.other_end(e, w)));
        const auto uv = edge_uv(n, k, 0);
        worst = std::max(worst, distance(s.evaluate(f, uv[0], uv[1], m.positions, 3).position, mean(ring)));
        // The middle of edge k (a to b): the first step's point there has four neighbours, the
        // middles of the edges before and after it in its two faces; its V-face one step later
        // has the centroid (m_e + mean of those four) / 2.
        const Index a = fv[size_t(k)], b = fv[size_t((k + 1) % n)];
        const Index other = [&] {
          const Index e = find_edge(L, a, b);
          return L.edge_faces[size_t(2 * e)] == f ? L.edge_faces[size_t(2 * e + 1)] : L.edge_faces[size_t(2 * e)];
        }();
        std::vector<Point> around;
        for (Index g : {f, other}) {
          const auto gv = L.face(g);
          const int gn = int(gv.size());
          for (int i = 0; i < gn; ++i) {
            const Index x = gv[size_t(i)], y = gv[size_t((i + 1) % gn)];
            const bool is_e = (x == a && y == b) || (x == b && y == a);
            if (!is_e) continue;
            around.push_back(middle(m, gv[size_t((i + gn - 1) % gn)], x));
            around.push_back(middle(m, y, gv[size_t((i + 2) % gn)]));
          }
        }
        REQUIRE(around.size() == 4);
        const Point me = middle(m, a, b), ma = mean(around);
        const Point expected{(me[0] + ma[0]) / 2, (me[1] + ma[1]) / 2, (me[2] + ma[2]) / 2};
        const auto mid = edge_uv(n, k, 0.5);
        worst = std::max(worst, distance(s.evaluate(f, mid[0], mid[1], m.positions, 3).position, expected));
      }
    }
    CHECK(worst < 1e-14);
  }
}

TEST_CASE("mid-edge: the limit at the vertices two steps make equals their limit masks (refine --limit)") {
  // The point of corner (g, j) after two steps is the middle of the first step's edge between
  // the middles of g's edges j - 1 and j, at the centre (1/2, 1/2) of quadrant (g, j).
  const auto scheme = load_scheme("mid-edge");
  for (const test::Mesh& m : meshes()) {
    const Level L = m.level();
    const LimitSurface s(scheme, L);
    RefineOptions ro;
    ro.levels = 2;
    const Hierarchy h = refine(*scheme, L, ro);
    const std::vector<double> p2 = h.stencils[1].apply(h.stencils[0].apply(m.positions, 3), 3);
    LimitOptions lo;
    lo.first_step = 2;
    const LimitResult masks = limit_positions(*scheme, h.levels[2], p2, lo);
    // The level-2 vertex of corner (g, j): the level-2 point whose level-2 position is the
    // middle of the middles of edges j - 1 and j (positions, not numbering, find it).
    double worst = 0;
    int found = 0;
    for (Index g = 0; g < L.face_count(); ++g) {
      const auto gv = L.face(g);
      const int n = int(gv.size());
      for (int j = 0; j < n; ++j) {
        const Point a = middle(m, gv[size_t((j + n - 1) % n)], gv[size_t(j)]), b = middle(m, gv[size_t(j)], gv[size_t((j + 1) % n)]);
        const Point c = mean({a, b});
        Index v = kNone;
        for (Index x = 0; x < h.levels[2].vertex_count; ++x)
          if (distance(std::span(p2).subspan(size_t(3 * x), 3), c) < 1e-14) v = x;
        REQUIRE(v != kNone);
        ++found;
        const auto uv = quadrant_uv(n, j, 0.5, 0.5);
        const LimitSample q = s.evaluate(g, uv[0], uv[1], m.positions, 3);
        worst = std::max(worst, distance(q.position, std::span(masks.positions).subspan(size_t(3 * v), 3)));
      }
    }
    CHECK(found == int(L.face_vertices.size()));
    CHECK(worst < 1e-13);
  }
}

TEST_CASE("mid-edge: continuous across every edge, affine invariant, stencils equal evaluation") {
  const auto scheme = load_scheme("mid-edge");
  for (const test::Mesh& m : {bumped(test::cube()), bumped(test::pyramid())}) {
    const Level L = m.level();
    const LimitSurface s(scheme, L);
    double worst = 0;
    for (Index e = 0; e < L.edge_count(); ++e) {
      const Index a = L.edge_vertices[size_t(2 * e)];
      for (double t : {0.3, 0.61}) {
        std::vector<std::vector<double>> sides;
        for (int side = 0; side < 2; ++side) {
          const Index f = L.edge_faces[size_t(2 * e + side)];
          const auto fv = L.face(f);
          const int n = int(fv.size());
          for (int k = 0; k < n; ++k) {
            if (find_edge(L, fv[size_t(k)], fv[size_t((k + 1) % n)]) != e) continue;
            const auto uv = edge_uv(n, k, fv[size_t(k)] == a ? t : 1 - t);
            sides.push_back(s.evaluate(f, uv[0], uv[1], m.positions, 3).position);
          }
        }
        REQUIRE(sides.size() == 2);
        worst = std::max(worst, distance(sides[0], sides[1]));
      }
    }
    CHECK(worst < 1e-13);
    const double A[3][3] = {{0.8, -0.3, 0.2}, {0.1, 1.1, -0.4}, {0.5, 0.2, 0.9}}, t[3] = {1.5, -2, 0.25};
    std::vector<double> moved(m.positions.size());
    for (size_t v = 0; v < moved.size() / 3; ++v)
      for (int r = 0; r < 3; ++r)
        moved[3 * v + size_t(r)] = t[r] + A[r][0] * m.positions[3 * v] + A[r][1] * m.positions[3 * v + 1] +
                                   A[r][2] * m.positions[3 * v + 2];
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> U(0, 1);
    for (int k = 0; k < 4; ++k) {
      const Index f = Index(k % L.face_count());
      const int n = L.face_size(f);
      const auto uv = n == 4 ? std::array<double, 2>{U(rng), U(rng)} : sub_face_uv(n, k % n, U(rng), U(rng));
      const LimitSample p = s.evaluate(f, uv[0], uv[1], m.positions, 3);
      const LimitSample q = s.evaluate(f, uv[0], uv[1], moved, 3);
      for (int r = 0; r < 3; ++r) {
        double x = t[r];
        for (int c = 0; c < 3; ++c) x += A[r][c] * p.position[size_t(c)];
        CHECK(std::fabs(q.position[size_t(r)] - x) < 1e-13);
      }
      const LimitStencil w = s.stencil(f, uv[0], uv[1]);
      Point x{};
      for (size_t i = 0; i < w.vertices.size(); ++i)
        for (size_t c = 0; c < 3; ++c) x[c] += w.position[i] * m.positions[size_t(3 * w.vertices[i]) + c];
      CHECK(distance(x, p.position) < 1e-13);
    }
  }
}

TEST_CASE("mid-edge: linear precision in the quadrant parameterisation") {
  // Control points at their own grid coordinates (a 16 x 16 torus unrolled away from the seam,
  // which the faces evaluated here do not read): the limit is the plane (i + u, j + v). On a
  // regular grid every step keeps the plane: the middles of the middles of two edges at a
  // corner lie at (1/4, 1/4) of it, the centre of its quadrant.
  const int n = 16;
  const test::Mesh m = limit_test::unrolled_torus(n);
  const LimitSurface s(load_scheme("mid-edge"), m.level());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  for (int k = 0; k < 8; ++k) {
    const int i = 7 + k % 2, j = 7 + (k / 2) % 2;
    const double u = U(rng), v = U(rng);
    const LimitSample p = s.evaluate(Index(j * n + i), u, v, m.positions, 3);
    CHECK(std::fabs(p.position[0] - (i + u)) < 1e-12);
    CHECK(std::fabs(p.position[1] - (j + v)) < 1e-12);
    CHECK(std::fabs(p.position[2]) < 1e-12);
    // The derivatives are the grid's axes.
    REQUIRE(p.has_derivatives);
    CHECK(distance(p.du, Point{1, 0, 0}) < 1e-12);
    CHECK(distance(p.dv, Point{0, 1, 0}) < 1e-12);
  }
}

TEST_CASE("mid-edge: derivatives against central differences, none at an extraordinary point") {
  const auto scheme = load_scheme("mid-edge");
  for (const test::Mesh& m : meshes()) {
    const Level L = m.level();
    const LimitSurface s(scheme, L);
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> U(0.15, 0.85);
    double worst = 0, scale = 0;
    for (int k = 0; k < 4; ++k) {
      const Index f = Index((5 * k) % L.face_count());
      const int n = L.face_size(f);
      // A quad's point, or a point well inside a sub-face (derivatives along the face's u, v).
      const auto uv = n == 4 ? std::array<double, 2>{U(rng), U(rng)} : sub_face_uv(n, k % n, 0.3 + 0.4 * U(rng), 0.3 + 0.4 * U(rng));
      const LimitSample p = s.evaluate(f, uv[0], uv[1], m.positions, 3);
      REQUIRE(p.has_derivatives);
      const double h = 1e-5;
      const LimitSample a = s.evaluate(f, uv[0] + h, uv[1], m.positions, 3, 0), b = s.evaluate(f, uv[0] - h, uv[1], m.positions, 3, 0);
      const LimitSample c = s.evaluate(f, uv[0], uv[1] + h, m.positions, 3, 0), d = s.evaluate(f, uv[0], uv[1] - h, m.positions, 3, 0);
      for (size_t r = 0; r < 3; ++r) {
        worst = std::max(worst, std::fabs((a.position[r] - b.position[r]) / (2 * h) - p.du[r]));
        worst = std::max(worst, std::fabs((c.position[r] - d.position[r]) / (2 * h) - p.dv[r]));
        scale = std::max({scale, std::fabs(p.du[r]), std::fabs(p.dv[r])});
      }
      // The stencil's derivative weights applied to the control points.
      const LimitStencil w = s.stencil(f, uv[0], uv[1]);
      REQUIRE(w.has_derivatives);
      Point du{}, dv{};
      for (size_t i = 0; i < w.vertices.size(); ++i)
        for (size_t c3 = 0; c3 < 3; ++c3) {
          du[c3] += w.du[i] * m.positions[size_t(3 * w.vertices[i]) + c3];
          dv[c3] += w.dv[i] * m.positions[size_t(3 * w.vertices[i]) + c3];
        }
      CHECK(distance(du, p.du) < 1e-12);
      CHECK(distance(dv, p.dv) < 1e-12);
    }
    CHECK(worst < 1e-6 * std::max(1.0, scale));
    // A base vertex of valence other than 4 is an extraordinary point (its V-face is not a
    // quad): no derivatives there; a vertex of valence 4 has them.
    for (Index f = 0; f < L.face_count(); ++f)
      for (int k = 0; k < L.face_size(f); ++k) {
        const auto uv = edge_uv(L.face_size(f), k, 0);
        CHECK(s.evaluate(f, uv[0], uv[1], m.positions, 3).has_derivatives ==
              (L.incident_face_count(L.face(f)[size_t(k)]) == 4));
      }
  }
}

TEST_CASE("mid-edge: the numbers do not depend on the order of evaluation") {
  // Each neighbourhood is worked out once, on its cut renumbered by its labels: a second
  // surface that meets the faces in the other order gives the same bits.
  const test::Mesh m = bumped(test::pyramid());
  const LimitSurface a(load_scheme("mid-edge"), m.level()), b(load_scheme("mid-edge"), m.level());
  const Index faces = m.level().face_count();
  std::vector<LimitSample> first, second;
  for (Index f = 0; f < faces; ++f) first.push_back(a.evaluate(f, 0.2109375, 0.3671875, m.positions, 3));
  for (Index f = faces; f-- > 0;) second.push_back(b.evaluate(f, 0.2109375, 0.3671875, m.positions, 3));
  for (Index f = 0; f < faces; ++f) {
    CHECK(first[size_t(f)].position == second[size_t(faces - 1 - f)].position);
    CHECK(first[size_t(f)].du == second[size_t(faces - 1 - f)].du);
  }
}

TEST_CASE("mid-edge: boundaries and creases are refused with the reason") {
  CHECK_THROWS_WITH_AS(LimitSurface(load_scheme("mid-edge"), test::grid(3, 3).level()),
                       doctest::Contains("boundary"), Error);
  Level creased = test::cube().level();
  creased.edge_sharpness.assign(size_t(creased.edge_count()), 0.f);
  creased.edge_sharpness[0] = 1.f;
  CHECK_THROWS_WITH_AS(LimitSurface(load_scheme("mid-edge"), creased), doctest::Contains("creases"), Error);
}
