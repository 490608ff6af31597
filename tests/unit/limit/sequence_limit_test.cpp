// The limit of a scheme sequence ("A:k,B"): the limit of its last scheme over the mesh its
// head makes, in the base faces' (u, v). Properties: k levels of B before B change nothing
// (the limit is B's, and its splits nest, so the parameters agree), continuity across the
// base edges, stencils equal evaluation, derivatives equal central differences (also
// across the head's child faces), and heads whose splits do not nest are refused.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <random>
#include <vector>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/limit/limit_surface.h"
#include "framework/topology/level.h"
#include "framework/limit/tessellation.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

test::Mesh bumped(test::Mesh m) {
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[size_t(3 * v + 2)] += 0.1 * std::sin(1.7 * v + 0.3);
  return m;
}

// The tetrahedron: every face's three neighbours share their third corner.
test::Mesh tetrahedron() {
  test::Mesh m;
  m.add_vertex(1, 1, 1), m.add_vertex(-1, -1, 1), m.add_vertex(-1, 1, -1), m.add_vertex(1, -1, -1);
  m.add_face({0, 1, 2}), m.add_face({0, 3, 1}), m.add_face({0, 2, 3}), m.add_face({1, 3, 2});
  return m;
}

double distance(std::span<const double> a, std::span<const double> b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

// Two routes to one limit at (f, u, v): the largest position and first-derivative gaps seen,
// and how many points had derivatives (both must agree on that).
struct Agreement {
  double position = 0, first = 0;
  int with_derivatives = 0;
  void take(const LimitSurface& one, const LimitSurface& other, const test::Mesh& m, Index f, double u, double v) {
    const LimitSample a = one.evaluate(f, u, v, m.positions, 3, 1);
    const LimitSample b = other.evaluate(f, u, v, m.positions, 3, 1);
    position = std::max(position, distance(a.position, b.position));
    REQUIRE(a.has_derivatives == b.has_derivatives);
    if (!a.has_derivatives) return;
    ++with_derivatives;
    first = std::max(first, distance(a.du, b.du) + distance(a.dv, b.dv));
  }
};

// At (f, u, v): the first derivatives against central differences of evaluated points
// (h = 1e-6), and the stencil's position and du against evaluation.
struct PointChecks {
  double differences = 0, stencil = 0;
  void take(const PointChecks& o) {
    differences = std::max(differences, o.differences);
    stencil = std::max(stencil, o.stencil);
  }
};

PointChecks check_point(const LimitSurface& s, const test::Mesh& m, Index f, double u, double v) {
  PointChecks out;
  const LimitSample p = s.evaluate(f, u, v, m.positions, 3);
  REQUIRE(p.has_derivatives);
  const double h = 1e-6;
  const auto P = [&](double a, double b) { return s.evaluate(f, a, b, m.positions, 3, 0).position; };
  const auto pu = P(u + h, v), mu = P(u - h, v), pv = P(u, v + h), mv = P(u, v - h);
  for (size_t i = 0; i < 3; ++i) {
    out.differences = std::max(out.differences, std::fabs((pu[i] - mu[i]) / (2 * h) - p.du[i]));
    out.differences = std::max(out.differences, std::fabs((pv[i] - mv[i]) / (2 * h) - p.dv[i]));
  }
  const LimitStencil w = s.stencil(f, u, v);
  std::vector<double> x(3, 0.0), xu(3, 0.0);
  for (size_t e = 0; e < w.vertices.size(); ++e)
    for (size_t i = 0; i < 3; ++i) {
      x[i] += w.position[e] * m.positions[size_t(3 * w.vertices[e]) + i];
      xu[i] += w.du[e] * m.positions[size_t(3 * w.vertices[e]) + i];
    }
  out.stencil = distance(x, p.position) + distance(xu, p.du);
  return out;
}

}  // namespace

TEST_CASE("A scheme's own levels before it leave its limit unchanged, derivatives included") {
  struct Case {
    const char* scheme;
    test::Mesh mesh;
    bool triangles;
  };
  for (const Case& c : {Case{"catmull-clark", bumped(test::pyramid()), false},
                        Case{"loop", bumped(test::octahedron()), true}}) {
    CAPTURE(std::string(c.scheme));
    const auto scheme = load_scheme(c.scheme);
    const LimitSurface plain(scheme, c.mesh.level());
    const LimitSurface sequence({{scheme, 2}}, scheme, c.mesh.level());
    CHECK(sequence.triangles() == plain.triangles());
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(0, 1);
    double worst = 0, worst_d = 0, worst_dd = 0;
    for (int k = 0; k < 30; ++k) {
      const Index f = Index(k % c.mesh.level().face_count());
      double u = U(rng), v = U(rng);
      if (c.triangles && u + v > 1) u = 1 - u, v = 1 - v;
      if (!c.triangles && c.mesh.level().face_size(f) != 4) u *= 0.5, v *= 0.5;  // sub-face 0
      const LimitSample a = plain.evaluate(f, u, v, c.mesh.positions, 3, 2);
      const LimitSample b = sequence.evaluate(f, u, v, c.mesh.positions, 3, 2);
      worst = std::max(worst, distance(a.position, b.position));
      REQUIRE(a.has_derivatives == b.has_derivatives);
      if (a.has_derivatives) worst_d = std::max(worst_d, distance(a.du, b.du) + distance(a.dv, b.dv));
      REQUIRE(a.has_second_derivatives == b.has_second_derivatives);
      if (a.has_second_derivatives)
        worst_dd = std::max(worst_dd, distance(a.duu, b.duu) + distance(a.duv, b.duv) + distance(a.dvv, b.dvv));
    }
    CHECK(worst < 1e-13);
    CHECK(worst_d < 1e-11);
    CHECK(worst_dd < 1e-9);
  }
}

TEST_CASE("A bilinear head then Catmull-Clark, and Catmull-Clark then Doo-Sabin: continuous, stencils, finite differences") {
  const test::Mesh m = bumped(test::pyramid());
  for (const auto& run : {std::pair{"bilinear", "catmull-clark"}, std::pair{"catmull-clark", "doo-sabin"}}) {
    const char* head = run.first;
    const char* tail = run.second;
    CAPTURE(std::string(head));
    const LimitSurface s({{load_scheme(head), 1}}, load_scheme(tail), m.level());
    const Level& L = s.base();
    // Continuity across every base edge: the pyramid's quad and triangles (sub-faces).
    double worst_edge = 0;
    for (Index e = 0; e < L.edge_count(); ++e) {
      std::vector<std::vector<double>> seen;
      for (int side = 0; side < 2; ++side) {
        const Index f = L.edge_faces[size_t(2 * e + side)];
        const auto c = L.face(f);
        const int n = int(c.size());
        int k = 0;
        while (L.face_edge_list(f)[size_t(k)] != e) ++k;
        const bool forward = c[size_t(k)] == L.edge_vertices[size_t(2 * e)];
        const double t = forward ? 0.3 : 0.7;
        double u = 0, v = 0;
        if (n == 4) {
          constexpr double q[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
          u = q[k][0] + t * (q[(k + 1) % 4][0] - q[k][0]), v = q[k][1] + t * (q[(k + 1) % 4][1] - q[k][1]);
        } else if (t <= 0.5) {
          u = k % 2 + t, v = k / 2;  // sub-face k, along its u to the edge's middle (2 columns)
        } else {
          u = (k + 1) % n % 2, v = (k + 1) % n / 2 + (1 - t);
        }
        seen.push_back(s.evaluate(f, u, v, m.positions, 3).position);
      }
      worst_edge = std::max(worst_edge, distance(seen[0], seen[1]));
    }
    CHECK(worst_edge < 1e-13);
    // Inside the quad base face, across its children's edges (u = 1/2): stencils and differences.
    PointChecks worst;
    for (const auto& [u, v] : {std::pair{0.5, 0.3}, std::pair{0.21, 0.5}, std::pair{0.77, 0.64}})
      worst.take(check_point(s, m, 0, u, v));
    CHECK(worst.differences < 1e-7);
    CHECK(worst.stencil < 1e-13);
    // The tessellation is closed.
    const Tessellation t = tessellate(s, m.positions, 2);
    CHECK(t.face_count() == 1 * 4 + 4 * 3 * 1);
  }
}

TEST_CASE("sqrt3's own levels in a sequence's head, one or two, change nothing") {
  // Two routes to the same limit through different cuts: sqrt3 alone, and sqrt3 after one or
  // two of its own levels (the head carries the point into the new triangle that holds it,
  // which reaches across the old edge), on closed meshes (the tetrahedron's neighbours share
  // their third corner) and on an open one (Kobbelt's boundary trisection).
  const auto sqrt3 = load_scheme("sqrt3");
  for (const test::Mesh& m : {bumped(test::octahedron()), bumped(tetrahedron()), bumped(test::grid(3, 3, true))}) {
    for (const int head_levels : {1, 2}) {
      CAPTURE(m.vertex_count);
      CAPTURE(head_levels);
      const LimitSurface plain(sqrt3, m.level());
      const LimitSurface sequence({{sqrt3, head_levels}}, sqrt3, m.level());
      std::mt19937 rng(9);
      std::uniform_real_distribution<double> U(0, 1);
      Agreement worst;
      for (int k = 0; k < 40; ++k) {
        double u = U(rng), v = U(rng);
        if (u + v > 1) u = 1 - u, v = 1 - v;
        worst.take(plain, sequence, m, Index(k % m.level().face_count()), u, v);
      }
      CHECK(worst.position < 1e-13);
      CHECK(worst.first < 1e-10);
      CHECK(worst.with_derivatives > 20);
    }
  }
}

TEST_CASE("sqrt3 then Loop: continuous across every edge, stencils equal evaluation, derivatives differences") {
  const test::Mesh m = bumped(test::grid(3, 3, true));
  constexpr double corner_uv[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (const int head_levels : {1, 2}) {
    CAPTURE(head_levels);
    const LimitSurface s({{load_scheme("sqrt3"), head_levels}}, load_scheme("loop"), m.level());
    const Level& L = s.base();
    double worst_edge = 0;
    for (Index e = 0; e < L.edge_count(); ++e) {
      if (L.edge_on_boundary(e)) continue;
      for (const double t : {0.2, 0.5, 0.9}) {
        std::vector<std::vector<double>> seen;
        for (int side = 0; side < 2; ++side) {
          const Index f = L.edge_faces[size_t(2 * e + side)];
          int k = 0;
          while (L.face_edge_list(f)[size_t(k)] != e) ++k;
          const double a = L.face(f)[size_t(k)] == L.edge_vertices[size_t(2 * e)] ? t : 1 - t;
          const auto& p = corner_uv[k];
          const auto& q = corner_uv[(k + 1) % 3];
          seen.push_back(s.evaluate(f, p[0] + a * (q[0] - p[0]), p[1] + a * (q[1] - p[1]), m.positions, 3, 0).position);
        }
        worst_edge = std::max(worst_edge, distance(seen[0], seen[1]));
      }
    }
    CHECK(worst_edge < 1e-13);
    // Off the lines from the corners to the centre, where one step's pieces meet (the tail's
    // derivatives change there), and off the triadic grid's lines, where a pair's meet.
    PointChecks worst;
    for (const auto& [u, v] : {std::pair{0.2, 0.1}, std::pair{0.6, 0.15}, std::pair{0.15, 0.5}})
      for (Index f : {Index(0), Index(8)}) worst.take(check_point(s, m, f, u, v));
    CHECK(worst.differences < 1e-7);
    CHECK(worst.stencil < 1e-13);
  }
}

TEST_CASE("mid-edge's own levels in a sequence's head, two or four, change nothing; mid-edge then Catmull-Clark is "
          "continuous with stencils and derivatives") {
  // Two mid-edge steps nest as one dual step (mid_edge_pair.h), the layout mid-edge's own
  // evaluator follows: the same limit in the same (u, v), through different cuts. The cube
  // (quads), the pyramid (a quad and triangles: sub-faces) and the octahedron (triangles).
  const auto mid_edge = load_scheme("mid-edge");
  for (const test::Mesh& m : {bumped(test::cube()), bumped(test::pyramid()), bumped(test::octahedron())}) {
    for (const int head_levels : {2, 4}) {
      CAPTURE(m.vertex_count);
      CAPTURE(head_levels);
      const LimitSurface plain(mid_edge, m.level());
      const LimitSurface sequence({{mid_edge, head_levels}}, mid_edge, m.level());
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> U(0, 1);
      Agreement worst;
      for (int k = 0; k < 30; ++k) {
        const Index f = Index(k % m.level().face_count());
        double u = U(rng), v = U(rng);
        if (m.level().face_size(f) != 4) u *= 0.5, v *= 0.5;  // sub-face 0
        worst.take(plain, sequence, m, f, u, v);
      }
      CHECK(worst.position < 1e-13);
      CHECK(worst.first < 1e-10);
    }
  }
  // Mid-edge twice, then Catmull-Clark on the pyramid: the same point from both faces of
  // every base edge, and off the quadrants' lines stencils and central differences.
  const test::Mesh m = bumped(test::pyramid());
  const LimitSurface s({{mid_edge, 2}}, load_scheme("catmull-clark"), m.level());
  double worst_edge = 0;
  const Level& L = s.base();
  for (Index e = 0; e < L.edge_count(); ++e)
    for (const double t : {0.2, 0.45}) {
      std::vector<std::vector<double>> seen;
      for (int side = 0; side < 2; ++side) {
        const Index f = L.edge_faces[size_t(2 * e + side)];
        int k = 0;
        while (L.face_edge_list(f)[size_t(k)] != e) ++k;
        const bool forward = L.face(f)[size_t(k)] == L.edge_vertices[size_t(2 * e)];
        const int n = L.face_size(f);
        // From the edge's first end: sub-face k's u (or k + 1's v) in a sub-faced face, the
        // quad's side otherwise.
        double u = 0, v = 0;
        if (n == 4) {
          constexpr double q[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
          const double a = forward ? t : 1 - t;
          u = q[k][0] + a * (q[(k + 1) % 4][0] - q[k][0]), v = q[k][1] + a * (q[(k + 1) % 4][1] - q[k][1]);
        } else if (forward) {
          u = k % 2 + t, v = k / 2;
        } else {
          u = (k + 1) % n % 2, v = (k + 1) % n / 2 + t;
        }
        seen.push_back(s.evaluate(f, u, v, m.positions, 3, 0).position);
      }
      worst_edge = std::max(worst_edge, distance(seen[0], seen[1]));
    }
  CHECK(worst_edge < 1e-13);
  PointChecks worst;
  for (const auto& [u, v] : {std::pair{0.3, 0.2}, std::pair{0.7, 0.85}, std::pair{0.15, 0.6}})
    worst.take(check_point(s, m, 0, u, v));
  CHECK(worst.differences < 1e-7);
  CHECK(worst.stencil < 1e-13);
}

TEST_CASE("A sequence whose head does not nest, or whose tail is refused, is refused with the reason") {
  const auto mid_edge = load_scheme("mid-edge");
  CHECK_THROWS_WITH_AS(LimitSurface({{mid_edge, 1}}, load_scheme("doo-sabin"), test::cube().level()),
                       doctest::Contains("an odd number: one mid-edge step turns the faces"), Error);
  CHECK_THROWS_WITH_AS(LimitSurface({{mid_edge, 2}}, load_scheme("catmull-clark"), test::grid(2, 2).level()),
                       doctest::Contains("has a mid-edge split and at level 0 the mesh has a boundary"), Error);
  CHECK_THROWS_WITH_AS(LimitSurface({{load_scheme("loop"), 1}, {mid_edge, 2}}, mid_edge, test::octahedron().level()),
                       doctest::Contains("a dual or mid-edge split after a triangle split"), Error);
  CHECK_THROWS_WITH_AS(LimitSurface({{load_scheme("catmull-clark"), 1}}, load_scheme("mid-edge"), test::grid(2, 2).level()),
                       doctest::Contains("mid-edge split and the mesh has a boundary"), Error);
}

TEST_CASE("A sqrt3 tail counts its steps from the base mesh, as refinement does: its limit at a vertex is the "
          "limit mask's of the head's mesh with that step count") {
  // The sqrt3 split trisects boundaries in odd steps counted from the base mesh, across a
  // sequence too (docs/scheme-format.md), so after one Loop level the tail's first step
  // trisects and after two it keeps. The limit masks (analysis/surface/limit_evaluation.h,
  // the route of `subdiv refine --limit`) are told the step count; the evaluator follows the
  // point. The interior vertex (1, 1) of the grid is next to the boundary, where the order of
  // the two kinds of step changes the limit (by about 0.04 on the bundled tube).
  const test::Mesh grid = bumped(test::grid(4, 4, true));
  const Index vertex = 1 * 5 + 1;
  const auto loop = load_scheme("loop"), sqrt3 = load_scheme("sqrt3");
  const Level base = grid.level();
  const Index f = base.ring_faces(vertex)[0];
  const auto corners = base.face(f);
  const int k = int(std::find(corners.begin(), corners.end(), vertex) - corners.begin());
  constexpr double corner_uv[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (const int head_levels : {1, 2}) {
    CAPTURE(head_levels);
    const test::Refined head = test::refine_mesh(grid, "loop", head_levels);
    LimitOptions o;
    o.first_step = head_levels;
    const LimitResult masks = limit_positions(*sqrt3, head.hierarchy.levels.back(), head.positions, o);
    REQUIRE(masks.exact[size_t(vertex)]);  // vertex children keep their index
    const LimitSurface sequence({{loop, head_levels}}, sqrt3, base);
    const LimitSample a = sequence.evaluate(f, corner_uv[k][0], corner_uv[k][1], grid.positions, 3, 0);
    CHECK(distance(a.position, std::span(masks.positions).subspan(size_t(3 * vertex), 3)) < 1e-13);
  }
}

TEST_CASE("A dual head: Doo-Sabin's own level before it changes nothing, and Doo-Sabin then Catmull-Clark is continuous") {
  // Doo-Sabin's quadrants nest, so doo-sabin:1,doo-sabin is Doo-Sabin's limit in the same (u, v).
  for (const test::Mesh& m : {bumped(test::cube()), bumped(test::pyramid())}) {
    const auto ds = load_scheme("doo-sabin");
    const LimitSurface plain(ds, m.level());
    const LimitSurface sequence({{ds, 1}}, ds, m.level());
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> U(0.02, 0.48);
    double worst = 0, worst_d = 0;
    for (int k = 0; k < 24; ++k) {
      const Index f = Index(k % m.level().face_count());
      const int n = m.level().face_size(f);
      double u = U(rng), v = U(rng);
      if (n == 4) u += 0.5 * (k % 2), v += 0.5 * (k / 2 % 2);
      const LimitSample a = plain.evaluate(f, u, v, m.positions, 3);
      const LimitSample b = sequence.evaluate(f, u, v, m.positions, 3);
      worst = std::max(worst, distance(a.position, b.position));
      REQUIRE(a.has_derivatives == b.has_derivatives);
      if (a.has_derivatives) worst_d = std::max(worst_d, distance(a.du, b.du) + distance(a.dv, b.dv));
    }
    CHECK(worst < 1e-13);
    CHECK(worst_d < 1e-11);
  }
  const test::Mesh m = bumped(test::cube());
  const LimitSurface s({{load_scheme("doo-sabin"), 1}}, load_scheme("catmull-clark"), m.level());
  const Tessellation t = tessellate(s, m.positions, 4);
  CHECK(t.face_count() == 6 * 16);
  Level semi = test::torus(8, 6).level();
  semi.edge_sharpness.assign(size_t(semi.edge_count()), 0.f);
  for (Index i = 0; i < 8; ++i) semi.edge_sharpness[size_t(find_edge(semi, i, (i + 1) % 8))] = 2.f;
  CHECK_THROWS_WITH_AS(LimitSurface({{load_scheme("doo-sabin"), 1}}, load_scheme("catmull-clark"), semi),
                       doctest::Contains("not semi-sharp ones"), Error);
}

TEST_CASE("A dual head next to a boundary and a sharp crease: Doo-Sabin's own levels before it change nothing") {
  // The head hands each point to the tail in its child face's (u, v), through the layout of
  // faces next to the crease (docs/limit.md): doo-sabin:k,doo-sabin must be Doo-Sabin's limit
  // in the same (u, v), on and off the crease.
  test::Mesh torus = bumped(test::torus(8, 6));
  Level creased = torus.level();
  creased.edge_sharpness.assign(size_t(creased.edge_count()), 0.f);
  for (Index i = 0; i < 8; ++i) creased.edge_sharpness[size_t(find_edge(creased, i, (i + 1) % 8))] = 10.f;
  const test::Mesh grid = bumped(test::grid(5, 4));
  const auto ds = load_scheme("doo-sabin");
  for (int mesh = 0; mesh < 2; ++mesh) {
    const test::Mesh& m = mesh == 0 ? grid : torus;
    const Level L = mesh == 0 ? grid.level() : creased;
    const LimitSurface plain(ds, L);
    for (int k : {1, 2}) {
      CAPTURE(mesh);
      CAPTURE(k);
      const LimitSurface sequence({{ds, k}}, ds, L);
      std::mt19937 rng(17);
      std::uniform_real_distribution<double> U(0.0, 1.0);
      double worst = 0, worst_d = 0;
      for (int n = 0; n < 30; ++n) {
        const Index f = Index(n % L.face_count());
        const double u = U(rng), v = n % 3 == 0 ? 0.0 : U(rng);
        const LimitSample a = plain.evaluate(f, u, v, m.positions, 3);
        const LimitSample b = sequence.evaluate(f, u, v, m.positions, 3);
        worst = std::max(worst, distance(a.position, b.position));
        REQUIRE(a.has_derivatives == b.has_derivatives);
        if (a.has_derivatives) {
          const std::vector<double> zero(3, 0.0);
          const double size = 1 + distance(a.du, zero) + distance(a.dv, zero);
          worst_d = std::max(worst_d, (distance(a.du, b.du) + distance(a.dv, b.dv)) / size);
        }
      }
      CHECK(worst < 1e-12);
      CHECK(worst_d < 1e-9);
    }
  }
}
