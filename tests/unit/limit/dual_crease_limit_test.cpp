// Exact limit evaluation of dual schemes next to boundaries, sharp creases and corners, against
// mathematics: along a boundary or crease the limit is the crease polygon's Chaikin curve
// (Chaikin 1974), the uniform quadratic B-spline, or between two corners the clamped one
// (evaluated here by Cox & de Boor's recurrence), at the parameter docs/limit.md gives; corners
// are interpolated; both sides of every edge give the same point; affine invariance; at the
// parameters of level-1 points the limit is the V-face centroid limit of the refined mesh
// (interpolation/dual_limits.h, computed from one step of the scheme independently of this
// evaluator); fractional sharpness is the smooth limit of the mesh one step down.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <tuple>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/features/dual_features.h"
#include "framework/interpolation/limit_selection.h"
#include "framework/limit/dual_limit.h"
#include "framework/limit/face_domain.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

using P3 = std::array<double, 3>;

using limit_test::distance;

test::Mesh bumped(test::Mesh m) { return limit_test::bumped(std::move(m), 0.3); }

P3 point(const test::Mesh& m, Index v) {
  return {m.positions[size_t(3 * v)], m.positions[size_t(3 * v + 1)], m.positions[size_t(3 * v + 2)]};
}

// Cox & de Boor: the degree-2 B-spline with knots t over control points at parameter x.
P3 quadratic_bspline(const std::vector<double>& t, const std::vector<P3>& ctrl, double x) {
  size_t k = 2;
  while (k + 1 < t.size() && !(t[k] <= x && x < t[k + 1])) ++k;
  if (k + 1 >= t.size() || k >= ctrl.size()) k = ctrl.size() - 1;  // x at the last knot
  std::vector<P3> d(ctrl.begin() + ptrdiff_t(k) - 2, ctrl.begin() + ptrdiff_t(k) + 1);
  for (int r = 1; r <= 2; ++r)
    for (int j = 2; j >= r; --j) {
      const size_t i = k - 2 + size_t(j);
      const double den = t[i + 3 - size_t(r)] - t[i];
      const double a = den == 0 ? 0 : (x - t[i]) / den;
      for (size_t c = 0; c < 3; ++c) d[size_t(j)][c] = (1 - a) * d[size_t(j) - 1][c] + a * d[size_t(j)][c];
    }
  return d[2];
}

// The uniform quadratic B-spline of a closed polygon, control point k at parameter k (its
// Greville abscissa; knots at the half-integers).
P3 closed_quadratic(const std::vector<P3>& loop, double x) {
  const int n = int(loop.size());
  // ctrl[q] is loop point q - 3, at Greville q - 3 between its knots t[q + 1], t[q + 2] =
  // (q - 3) -+ 1/2: t[i] = i - 4.5.
  std::vector<P3> ctrl;
  for (int k = -3; k <= n + 3; ++k) ctrl.push_back(loop[size_t(((k % n) + n) % n)]);
  std::vector<double> t(ctrl.size() + 3);
  for (size_t i = 0; i < t.size(); ++i) t[i] = double(i) - 4.5;
  return quadratic_bspline(t, ctrl, x);
}

std::shared_ptr<const Scheme> scheme(const char* name) { return load_scheme(name); }

P3 at(const LimitSurface& s, const test::Mesh& m, Index face, double u, double v) {
  const LimitSample p = s.evaluate(face, u, v, m.positions, 3, 0);
  return {p.position[0], p.position[1], p.position[2]};
}

// Faces of test::grid(nx, ny): face (i, j) is j nx + i, corners (i, j), (i+1, j), (i+1, j+1), (i, j+1).
Index grid_face(int nx, int i, int j) { return Index(j * nx + i); }

// A 6 x 6 grid without its top right 3 x 3 block: an L whose reflex corner, vertex (3, 3) =
// 24, is a boundary vertex of three faces. Face (i, j) as in the grid, numbered row by row
// over the faces kept (l_shape_face).
test::Mesh l_shape() {
  test::Mesh m;
  for (int j = 0; j <= 6; ++j)
    for (int i = 0; i <= 6; ++i) m.add_vertex(i, j, 0);
  auto id = [](int i, int j) { return Index(j * 7 + i); };
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i)
      if (i < 3 || j < 3) m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return bumped(m);
}
Index l_shape_face(int i, int j) { return j < 3 ? Index(6 * j + i) : Index(18 + 3 * (j - 3) + i); }

// A half disc of quads around vertex 0 on its boundary: four quads at 0 (a boundary vertex of
// four faces), then a ring of eight; the ends of the outer ring are corners of one face.
// Faces 0 ... 3 have a corner at vertex 0, faces 4 ... 11 do not.
test::Mesh half_disc() {
  test::Mesh m;
  const double pi = std::acos(-1.0);
  m.add_vertex(0, 0, 0);
  for (int r = 1; r <= 2; ++r)
    for (int k = 0; k <= 8; ++k) m.add_vertex(r * std::cos(k * pi / 8), r * std::sin(k * pi / 8), 0);
  auto ring = [](int r, int k) { return Index(1 + 9 * (r - 1) + k); };
  for (int k = 0; k < 4; ++k) m.add_face({0, ring(1, 2 * k), ring(1, 2 * k + 1), ring(1, 2 * k + 2)});
  for (int k = 0; k < 8; ++k) m.add_face({ring(1, k), ring(2, k), ring(2, k + 1), ring(1, k + 1)});
  return bumped(m);
}

// A disc of quads around vertex 0: eight quads at 0, then a ring of sixteen (faces 8 + k, k =
// 0 ... 15: ring-1 vertex k, ring-2 vertex k, k + 1, ring-1 vertex k + 1), with the diameter
// through ring vertices 0 and 8 infinitely sharp: vertex 0 is a crease vertex of four faces
// on each side; the crease ends at the boundary in corners.
test::Mesh disc(Level* creased) {
  test::Mesh m;
  const double pi = std::acos(-1.0);
  m.add_vertex(0, 0, 0);
  for (int r = 1; r <= 2; ++r)
    for (int k = 0; k < 16; ++k) m.add_vertex(r * std::cos(k * pi / 8), r * std::sin(k * pi / 8), 0);
  auto ring = [](int r, int k) { return Index(1 + 16 * (r - 1) + k % 16); };
  for (int k = 0; k < 8; ++k) m.add_face({0, ring(1, 2 * k), ring(1, 2 * k + 1), ring(1, 2 * k + 2)});
  for (int k = 0; k < 16; ++k) m.add_face({ring(1, k), ring(2, k), ring(2, k + 1), ring(1, k + 1)});
  m = bumped(m);
  *creased = m.level();
  creased->edge_sharpness.assign(size_t(creased->edge_count()), 0.f);
  for (const auto& [a, b] : {std::pair{Index(0), ring(1, 0)}, {Index(0), ring(1, 8)}, {ring(1, 0), ring(2, 0)},
                             {ring(1, 8), ring(2, 8)}})
    creased->edge_sharpness[size_t(find_edge(*creased, a, b))] = 10.f;
  return m;
}

// A torus with its loop of vertices j = 0 (the edges from (i, 0) to (i + 1, 0)) infinitely sharp.
Level creased_torus_level(const test::Mesh& m, int nu) {
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (int i = 0; i < nu; ++i) L.edge_sharpness[size_t(find_edge(L, Index(i), Index((i + 1) % nu)))] = 10.f;
  return L;
}

// For each edge of two faces, the two faces' (u, v) at parameter t along it (quads only).
// Faces for which `skip` holds are left out.
// The mesh under the affine map x -> A x + b (its limit must move the same way).
const std::array<std::array<double, 3>, 3> kA{{{0.8, -0.3, 0.1}, {0.2, 1.1, -0.4}, {0.05, 0.3, 0.9}}};
const P3 kB{0.3, -1.2, 2.0};
test::Mesh affinely_moved(const test::Mesh& m) {
  test::Mesh moved = m;
  for (Index v = 0; v < m.vertex_count; ++v)
    for (size_t r = 0; r < 3; ++r) {
      double x = kB[r];
      for (size_t c = 0; c < 3; ++c) x += kA[r][c] * m.positions[size_t(3 * v) + c];
      moved.positions[size_t(3 * v) + r] = x;
    }
  return moved;
}

// At four points of each face (the last one the caller's, on an edge): the largest distance
// between the limit of the moved mesh and the moved limit (affine invariance), and between
// the limit and its stencil applied to the control points. A stencil with `derivatives` 2
// must have its second derivatives.
struct AffineStencilErrors {
  double affine = 0, stencil = 0;
};
AffineStencilErrors affine_and_stencil_errors(const LimitSurface& s, const test::Mesh& m, const std::vector<Index>& faces,
                                              std::array<double, 2> on_edge, int derivatives) {
  const test::Mesh moved = affinely_moved(m);
  AffineStencilErrors worst;
  for (const Index f : faces)
    for (const auto& uv : {std::array<double, 2>{0.1, 0.05}, {0.6, 0.3}, {0.999, 0.5}, on_edge}) {
      const P3 p = at(s, m, f, uv[0], uv[1]), q = at(s, moved, f, uv[0], uv[1]);
      P3 e = kB;
      for (size_t r = 0; r < 3; ++r)
        for (size_t c = 0; c < 3; ++c) e[r] += kA[r][c] * p[c];
      worst.affine = std::max(worst.affine, distance(q, e));
      const LimitStencil w = s.stencil(f, uv[0], uv[1], derivatives);
      P3 y{0, 0, 0};
      for (size_t k = 0; k < w.vertices.size(); ++k)
        for (size_t c = 0; c < 3; ++c) y[c] += w.position[k] * m.positions[size_t(3 * w.vertices[k]) + c];
      worst.stencil = std::max(worst.stencil, distance(p, y));
      if (derivatives == 2) CHECK(w.has_second_derivatives);
    }
  return worst;
}

void check_edges_continuous(const LimitSurface& s, const test::Mesh& m, const Level& L, double tolerance,
                            const std::function<bool(Index)>& skip = {}) {
  constexpr std::array<std::array<double, 2>, 4> kCorner{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  auto edge_uv = [&](Index f, Index a, Index b, double t) {
    const auto g = L.face(f);
    for (int k = 0; k < 4; ++k)
      if (g[size_t(k)] == a && g[size_t((k + 1) % 4)] == b) {
        const auto& p = kCorner[size_t(k)];
        const auto& q = kCorner[size_t((k + 1) % 4)];
        return std::array<double, 2>{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])};
      }
    FAIL("edge not in face");
    return std::array<double, 2>{};
  };
  double worst = 0;
  for (Index e = 0; e < L.edge_count(); ++e) {
    if (L.edge_on_boundary(e)) continue;
    const Index f0 = L.edge_faces[size_t(2 * e)], f1 = L.edge_faces[size_t(2 * e + 1)];
    if (skip && (skip(f0) || skip(f1))) continue;
    const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
    for (double t : {0.0, 0.3, 0.5, 0.8125}) {
      // Each face runs the edge in its own direction.
      const bool f0_ab = [&] {
        const auto g = L.face(f0);
        for (int k = 0; k < 4; ++k)
          if (g[size_t(k)] == a && g[size_t((k + 1) % 4)] == b) return true;
        return false;
      }();
      const auto p0 = f0_ab ? edge_uv(f0, a, b, t) : edge_uv(f0, b, a, 1 - t);
      const auto p1 = f0_ab ? edge_uv(f1, b, a, 1 - t) : edge_uv(f1, a, b, t);
      const P3 x = at(s, m, f0, p0[0], p0[1]), y = at(s, m, f1, p1[0], p1[1]);
      worst = std::max(worst, distance(x, y));
    }
  }
  CHECK(worst < tolerance);
}

}  // namespace

TEST_CASE("dual limit at a boundary: the boundary between two corners is the clamped quadratic B-spline, corners "
          "interpolated") {
  // 6 x 4, and 2 x 2 where each side has one vertex between two corners (knots 0, 0, 0, 1, 1, 1:
  // a quadratic Bezier curve).
  for (const auto& size : {std::array<int, 2>{6, 4}, std::array<int, 2>{2, 2}}) {
    const int nx = size[0], ny = size[1];
    CAPTURE(nx);
    const test::Mesh m = bumped(test::grid(nx, ny));
    // The bottom row (i, 0): corners (0, 0) and (nx, 0) end it. Clamped knots 0, 0, 0, 1, ...,
    // nx - 1 (three times): P_0 at Greville 0, P_i at i - 1/2, P_nx at nx - 1.
    std::vector<P3> row;
    for (int i = 0; i <= nx; ++i) row.push_back(point(m, Index(i)));
    std::vector<double> knots{0, 0, 0};
    for (int k = 1; k < nx - 1; ++k) knots.push_back(k);
    for (int r = 0; r < 3; ++r) knots.push_back(nx - 1);
    auto greville = [&](int i) { return i == 0 ? 0.0 : (i == nx ? nx - 1.0 : i - 0.5); };
    for (const char* name : {"doo-sabin", "doo-sabin-centroid", "quad-bspline"}) {
      CAPTURE(name);
      ParameterOverrides d2;
      d2["d"] = "2";
      const LimitSurface s(std::string(name) == "quad-bspline" ? load_scheme(name, d2) : scheme(name), m.level());
      double worst = 0;
      for (int i = 0; i < nx; ++i)
        for (double u : {0.0, 0.125, 0.3, 0.5, 0.71, 0.9375, 1.0}) {
          const double x = greville(i) + u * (greville(i + 1) - greville(i));
          const P3 e = quadratic_bspline(knots, row, std::min(x, nx - 1 - 1e-15));
          worst = std::max(worst, distance(at(s, m, grid_face(nx, i, 0), u, 0), e));
        }
      CHECK(worst < 1e-12);
      // The grid's four corners stay.
      CHECK(distance(at(s, m, grid_face(nx, 0, 0), 0, 0), point(m, 0)) < 1e-14);
      CHECK(distance(at(s, m, grid_face(nx, nx - 1, ny - 1), 1, 1), point(m, Index((nx + 1) * (ny + 1) - 1))) < 1e-14);
    }
  }
}

TEST_CASE("dual limit at a sharp crease: both sides give the crease polygon's uniform quadratic B-spline") {
  const int nu = 8, nv = 6;
  const test::Mesh m = bumped(test::torus(nu, nv));
  const Level L = creased_torus_level(m, nu);
  std::vector<P3> loop;
  for (int i = 0; i < nu; ++i) loop.push_back(point(m, Index(i)));
  for (const char* name : {"doo-sabin", "doo-sabin-centroid"}) {
    CAPTURE(name);
    const LimitSurface s(scheme(name), L);
    double worst = 0;
    for (int i = 0; i < nu; ++i)
      for (double u : {0.0, 0.2, 0.5, 0.625, 0.99}) {
        const P3 e = closed_quadratic(loop, i + u);
        // Face (i, 0) has the crease as its edge v = 0; face (i, nv - 1) as its edge v = 1.
        worst = std::max(worst, distance(at(s, m, Index(i), u, 0), e));
        worst = std::max(worst, distance(at(s, m, Index((nv - 1) * nu + i), u, 1), e));
      }
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("dual limit at boundaries and creases: continuous across every edge, affine invariant, stencils") {
  const test::Mesh grid = bumped(test::grid(5, 4));
  const test::Mesh torus = bumped(test::torus(8, 6));
  const Level torus_level = creased_torus_level(torus, 8);
  const LimitSurface on_grid(scheme("doo-sabin"), grid.level());
  check_edges_continuous(on_grid, grid, grid.level(), 1e-12);
  const LimitSurface on_torus(scheme("doo-sabin"), torus_level);
  check_edges_continuous(on_torus, torus, torus_level, 1e-12);
  // Affine invariance: the limit of A x + b is A (limit) + b.
  std::vector<Index> faces(size_t(grid.level().face_count()));
  std::iota(faces.begin(), faces.end(), Index(0));
  const AffineStencilErrors errors = affine_and_stencil_errors(on_grid, grid, faces, {0.25, 0}, 0);
  CHECK(errors.affine < 1e-12);
  CHECK(errors.stencil < 1e-13);
}

namespace {

// The limits of the level-1 points of corners off the crease, against their limits on the
// refined mesh. A level-1 point of a corner off the crease lies at (1/2, 1/2) of its quadrant:
// half way between the corner and the quadrant's (1, 1) — the face centre, or for a face with
// corners on the crease the middle of its crease run (docs/limit.md). On the refined mesh its
// limit is taken by the V-face centroid limit (interpolation/dual_limits.h, from the refined
// mesh's own next step) when `by_centroids`, else by evaluating the refined mesh at the point
// as a corner of one of its faces.
void check_level_one_points(const test::Mesh& m, const Level& L, bool by_centroids,
                            const std::function<bool(Index)>& skip = {}, int at_least = 20) {
  constexpr std::array<std::array<double, 2>, 4> kCorner{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const LimitSurface s(scheme("doo-sabin"), L);
  RefineOptions ro;
  ro.levels = 1;
  const Hierarchy h = refine(*scheme("doo-sabin"), L, ro);
  std::vector<double> p1(size_t(3 * h.levels[1].vertex_count));
  h.stencils[0].apply(m.positions, p1, 3);
  std::vector<double> limits(p1.size());
  const Level& L1 = h.levels[1];
  if (by_centroids) {
    const LimitChoice c = select_limit(load_scheme_sequence("doo-sabin", 1, {}), L1);
    c.evaluator->limit_points(L1, p1, limits);
  } else {
    const LimitSurface s1(scheme("doo-sabin"), L1);
    for (Index v = 0; v < L1.vertex_count; ++v) {
      const Index f = L1.ring_faces(v)[0];
      const auto g = L1.face(f);
      REQUIRE(g.size() == 4);
      size_t k = 0;
      while (g[k] != v) ++k;
      const LimitSample x = s1.evaluate(f, kCorner[k][0], kCorner[k][1], p1, 3, 0);
      for (size_t c = 0; c < 3; ++c) limits[size_t(3 * v) + c] = x.position[c];
    }
  }
  const ChildOrigins& o = h.origins[0];
  int checked = 0;
  double worst = 0;
  for (size_t v = 0; v < o.kind.size(); ++v) {
    if (o.kind[v] != OriginKind::Corner) continue;
    const Index f = o.parent[v];
    if (skip && skip(f)) continue;
    const int j = int(o.local[v]);
    const auto g = L.face(f);
    // Which corners of f are on a sharp edge or a boundary, or are corners of the mesh.
    auto sharp = [&](int k) {
      const Index e = L.face_edges[size_t(L.face_offsets[f] + ((k % 4) + 4) % 4)];
      return L.edge_on_boundary(e) || L.edge_sharp(e) >= 1;
    };
    auto crease_corner = [&](int k) {
      const Index w = g[size_t(k % 4)];
      return sharp(k) || sharp(k + 3) || (L.on_boundary(w) && L.incident_face_count(w) == 1);
    };
    if (crease_corner(j)) continue;
    std::array<double, 2> centre{0.5, 0.5};
    std::vector<int> run;
    for (int k = 0; k < 4; ++k)
      if (crease_corner(k)) run.push_back(k);
    if (run.size() == 2)  // one crease edge: its middle
      centre = {(kCorner[size_t(run[0])][0] + kCorner[size_t(run[1])][0]) / 2,
                (kCorner[size_t(run[0])][1] + kCorner[size_t(run[1])][1]) / 2};
    if (run.size() == 3)  // turning at a corner of the mesh
      for (int k = 0; k < 4; ++k)
        if (crease_corner(k) && crease_corner(k + 1) && crease_corner(k + 3)) centre = kCorner[size_t(k)];
    const double u = (kCorner[size_t(j)][0] + centre[0]) / 2, w = (kCorner[size_t(j)][1] + centre[1]) / 2;
    const P3 e{limits[3 * v], limits[3 * v + 1], limits[3 * v + 2]};
    worst = std::max(worst, distance(at(s, m, f, u, w), e));
    ++checked;
  }
  CHECK(checked > at_least);
  CHECK(worst < 1e-12);
}

Level sharpened(const test::Mesh& m, int nu, float s) {
  Level L = creased_torus_level(m, nu);
  for (float& x : L.edge_sharpness)
    if (x > 0) x = s;
  return L;
}

}  // namespace

TEST_CASE("dual limit at boundaries and creases: at level-1 points, the limit points of the refined mesh") {
  const test::Mesh grid = bumped(test::grid(5, 4));
  check_level_one_points(grid, grid.level(), true);
  const test::Mesh torus = bumped(test::torus(8, 6));
  check_level_one_points(torus, creased_torus_level(torus, 8), true);
}

TEST_CASE("dual limit at semi-sharp creases: the limit of the mesh after the sharpness has decayed") {
  // Sharpness 1 takes the crease rules once and is smooth after: the level-1 mesh is untagged,
  // and its V-face centroid limits are the reference. Sharpness 2 and 1.5 take them once and
  // leave 1 and 0.5: the reference is the level-1 mesh evaluated at its vertices (sharpness
  // 1 there checked just before), each level one step of the decay.
  const test::Mesh torus = bumped(test::torus(8, 6));
  check_level_one_points(torus, sharpened(torus, 8, 1.f), true);
  check_level_one_points(torus, sharpened(torus, 8, 2.f), false);
  check_level_one_points(torus, sharpened(torus, 8, 1.5f), false);
  // The surface lies between the smooth one and the infinitely sharp crease's.
  const LimitSurface smooth(scheme("doo-sabin"), torus.level()), sharp(scheme("doo-sabin"), creased_torus_level(torus, 8)),
      semi(scheme("doo-sabin"), sharpened(torus, 8, 2.f));
  for (double u : {0.3, 0.5}) {
    const P3 a = at(smooth, torus, 2, u, 0), b = at(sharp, torus, 2, u, 0), c = at(semi, torus, 2, u, 0);
    CHECK(distance(c, a) > 1e-3);
    CHECK(distance(c, b) > 1e-3);
    CHECK(distance(c, b) < distance(a, b));
  }
  // Continuous across every edge.
  const Level L = sharpened(torus, 8, 2.5f);
  check_edges_continuous(LimitSurface(scheme("doo-sabin"), L), torus, L, 1e-12);
}

TEST_CASE("dual limit: fractional sharpness below 1 is the smooth limit of the mesh one step down") {
  // An edge of sharpness s < 1 keeps the smooth topology, blends its corners' rules once and
  // decays to 0: the limit is the untagged limit of the first level, at the point's
  // parameter there (dual_child_point: the quadrant the point is in after one step).
  const test::Mesh m = bumped(test::torus(8, 6));
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (int i = 0; i < 8; ++i) L.edge_sharpness[size_t(find_edge(L, Index(8 + i), Index(8 + (i + 1) % 8)))] = 0.6f;
  const LimitSurface s(scheme("doo-sabin"), L);
  RefineOptions ro;
  ro.levels = 1;
  const Hierarchy h = refine(*scheme("doo-sabin"), L, ro);
  std::vector<double> p1(size_t(3 * h.levels[1].vertex_count));
  h.stencils[0].apply(m.positions, p1, 3);
  Level L1 = h.levels[1];
  for (float x : L1.edge_sharpness) REQUIRE(x == 0.f);
  L1.edge_sharpness.clear();
  const LimitSurface s1(scheme("doo-sabin"), L1);
  double worst = 0, moved = 0;
  const LimitSurface smooth(scheme("doo-sabin"), m.level());
  for (Index f : {Index(0), Index(3), Index(8), Index(11), Index(17)})
    for (const auto& uv : {std::array<double, 2>{0.2, 0.1}, {0.5, 0.5}, {0.9, 0.35}, {0.4, 0.0}}) {
      const auto bp = base_face_point(L, f, uv[0], uv[1], false, nullptr);
      REQUIRE(bp);
      const auto cp = dual_child_point(L, h.levels[1], h.origins[0], *bp);
      REQUIRE(cp);
      REQUIRE(cp->sub_face < 0);
      const double cu = cp->st[0], cv = cp->st[1];
      const LimitSample a = s.evaluate(f, uv[0], uv[1], m.positions, 3, 0);
      const LimitSample b = s1.evaluate(cp->face, cu, cv, p1, 3, 0);
      worst = std::max(worst, distance(a.position, b.position));
      moved = std::max(moved, distance(a.position, smooth.evaluate(f, uv[0], uv[1], m.positions, 3, 0).position));
    }
  CHECK(worst < 1e-12);
  CHECK(moved > 1e-3);  // the sharpness does change the surface
}

TEST_CASE("dual limit: boundaries and creases not covered yet are refused with the place") {
  // A boundary vertex of three faces: the faces around it (the others are evaluated, below).
  const test::Mesh ell = l_shape();
  const LimitSurface on_ell(scheme("doo-sabin"), ell.level());
  CHECK_THROWS_WITH_AS(on_ell.evaluate(l_shape_face(2, 2), 0.5, 0.5, ell.positions, 3),
                       doctest::Contains("face 14 has a corner at boundary vertex 24, which has 3 faces: with three or more faces"), Error);
  // A dart: one sharp edge ending inside the torus.
  const test::Mesh t = test::torus(8, 6);
  Level dart = t.level();
  dart.edge_sharpness.assign(size_t(dart.edge_count()), 0.f);
  dart.edge_sharpness[size_t(find_edge(dart, 0, 1))] = 10.f;
  CHECK_THROWS_WITH_AS(LimitSurface(scheme("doo-sabin"), dart), doctest::Contains("dart"), Error);
  // A semi-sharp corner.
  Level semi = t.level();
  semi.vertex_sharpness.assign(size_t(semi.vertex_count), 0.f);
  semi.vertex_sharpness[9] = 2.f;
  CHECK_THROWS_WITH_AS(LimitSurface(scheme("doo-sabin"), semi), doctest::Contains("semi-sharp corner"), Error);
  // A pentagon at a boundary: a 3 x 2 grid whose bottom middle face has an extra corner
  // (vertex 12) on its boundary edge.
  test::Mesh house;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) house.add_vertex(i, j, 0);
  house.add_vertex(1.5, -0.2, 0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const Index a = Index(j * 4 + i);
      if (i == 1 && j == 0)
        house.add_face({1, 12, 2, 6, 5});
      else
        house.add_face({a, a + 1, a + 5, a + 4});
    }
  CHECK_THROWS_WITH_AS(LimitSurface(scheme("doo-sabin"), house.level()),
                       doctest::Contains("face 1 has 5 sides"), Error);
  // A face between two semi-sharp creases with a corner of the mesh (the corner face of a 3 x 3
  // grid whose rows of edges y = 1 and 2 have sharpness 3).
  const test::Mesh g3 = test::grid(3, 3);
  Level rows = g3.level();
  rows.edge_sharpness.assign(size_t(rows.edge_count()), 0.f);
  for (int j : {1, 2})
    for (int i = 0; i < 3; ++i) rows.edge_sharpness[size_t(find_edge(rows, Index(4 * j + i), Index(4 * j + i + 1)))] = 3.f;
  CHECK_THROWS_WITH_AS(LimitSurface(scheme("doo-sabin"), rows),
                       doctest::Contains("face 0 lies between two creases (its crease corners are not one run), "
                                         "and only quads between creases on opposite sides"),
                       Error);
}

TEST_CASE("dual limit at semi-sharp creases: Chaikin's decay; sharpness varying along a crease is refused") {
  const test::Mesh torus = bumped(test::torus(8, 6));
  for (CreaseMethod method : {CreaseMethod::Uniform, CreaseMethod::Chaikin}) {
    CAPTURE(int(method));
    LimitSurfaceOptions o;
    o.features.crease_method = method;
    const Level L = sharpened(torus, 8, 2.5f);
    check_edges_continuous(LimitSurface(scheme("doo-sabin"), L, o), torus, L, 1e-12);
  }
  Level L = creased_torus_level(torus, 8);
  L.edge_sharpness[size_t(find_edge(L, 2, 3))] = 3.f;
  CHECK_THROWS_WITH_AS(LimitSurface(scheme("doo-sabin"), L), doctest::Contains("crease vertex 2 joins sharp edges"),
                       Error);
}

TEST_CASE("dual limit next to holes: holes change no rule, so the faces around them keep their limit") {
  // OpenSubdiv's holes (and --boundary none's) remove faces, not rules: the surface of every
  // face that is kept is the one the mesh without the hole tags has.
  const test::Mesh torus = bumped(test::torus(8, 6));
  Level holed = torus.level();
  holed.face_hole.assign(size_t(holed.face_count()), 0);
  holed.face_hole[19] = holed.face_hole[20] = 1;
  const LimitSurface with(scheme("doo-sabin"), holed), without(scheme("doo-sabin"), torus.level());
  double worst = 0;
  for (Index f : {Index(11), Index(12), Index(18), Index(21), Index(27), Index(28)})
    for (const auto& uv : {std::array<double, 2>{0.1, 0.9}, {0.5, 0.5}, {0.97, 0.03}, {0.3, 0.0}})
      worst = std::max(worst, distance(at(with, torus, f, uv[0], uv[1]), at(without, torus, f, uv[0], uv[1])));
  CHECK(worst < 1e-12);
  CHECK_THROWS_WITH_AS(with.evaluate(19, 0.5, 0.5, torus.positions, 3), doctest::Contains("hole"), Error);
  // --boundary none: the faces touching the boundary are holes; the others keep the surface of
  // the mesh with its boundary (a dual scheme's boundary rules do not depend on the mode).
  const test::Mesh grid = bumped(test::grid(6, 5));
  LimitSurfaceOptions none;
  none.features.boundary = BoundaryInterpolation::None;
  const LimitSurface inner(scheme("doo-sabin"), grid.level(), none), all(scheme("doo-sabin"), grid.level());
  worst = 0;
  for (int j = 1; j < 4; ++j)
    for (int i = 1; i < 5; ++i)
      for (const auto& uv : {std::array<double, 2>{0.2, 0.7}, {0.0, 0.5}})
        worst = std::max(worst, distance(at(inner, grid, grid_face(6, i, j), uv[0], uv[1]),
                                         at(all, grid, grid_face(6, i, j), uv[0], uv[1])));
  CHECK(worst < 1e-12);
  CHECK_THROWS_WITH_AS(inner.evaluate(0, 0.5, 0.5, grid.positions, 3), doctest::Contains("hole"), Error);
}

TEST_CASE("dual limit next to boundaries and creases: derivatives against central differences") {
  // The quadrants of faces next to the crease are affine images of rectangles of the face's
  // (u, v) (and, after a semi-sharp crease has decayed, of the closed face's quadrants), so
  // the derivatives carry that Jacobian: checked against central differences of positions.
  const test::Mesh grid = bumped(test::grid(5, 4));
  const test::Mesh torus = bumped(test::torus(8, 6));
  const Level semi = sharpened(torus, 8, 2.f);
  struct Case {
    const test::Mesh* mesh;
    Level level;
  };
  const Case cases[] = {{&grid, grid.level()}, {&torus, creased_torus_level(torus, 8)}, {&torus, semi}};
  const double h = 1e-6;
  for (const Case& c : cases) {
    const LimitSurface s(scheme("doo-sabin"), c.level);
    double worst = 0;
    int with_derivatives = 0;
    for (Index f : {Index(0), Index(1), Index(2), Index(6), Index(9)})
      for (const auto& uv : {std::array<double, 2>{0.5, 0.5}, {0.3, 0.7}, {0.8, 0.4}, {0.45, 0.2}, {0.6, 0.85}}) {
        const LimitSample p = s.evaluate(f, uv[0], uv[1], c.mesh->positions, 3, 1);
        if (!p.has_derivatives) continue;
        ++with_derivatives;
        const P3 up = at(s, *c.mesh, f, uv[0] + h, uv[1]), um = at(s, *c.mesh, f, uv[0] - h, uv[1]);
        const P3 vp = at(s, *c.mesh, f, uv[0], uv[1] + h), vm = at(s, *c.mesh, f, uv[0], uv[1] - h);
        for (size_t k = 0; k < 3; ++k) {
          const double scale = 1 + std::abs(p.du[k]) + std::abs(p.dv[k]);
          worst = std::max(worst, std::abs(p.du[k] - (up[k] - um[k]) / (2 * h)) / scale);
          worst = std::max(worst, std::abs(p.dv[k] - (vp[k] - vm[k]) / (2 * h)) / scale);
        }
      }
    CHECK(with_derivatives == 25);
    CHECK(worst < 1e-6);
  }
}

TEST_CASE("dual limit at a crease that keeps its middles but is not Chaikin's: exact by descent") {
  // A scheme stating its crease corner rule as cuts at 3/8 (5/8 v + 3/8 next): symmetric about
  // each edge's middle, so the middles stay, but not Chaikin's curve (de Rham's corner cutting,
  // not a quadratic B-spline). On the crease the limit is reached by descending, not by
  // Chaikin's closed form: at the parameter of a level-1 crease point X1 = 5/8 P + 3/8 Q,
  // (u, v) = (1/4, 0) of the face on P - Q, the limit is the middle of X1's two points one step
  // down, 5/8 X1 + 3/16 (X0 + X2) with its level-1 neighbours X0 = 5/8 P + 3/8 P_prev and
  // X2 = 3/8 P + 5/8 Q; at (1/2, 0) the middle of P - Q.
  const std::string text = R"json({
    "name": "doo-sabin-three-eighths", "split": "dual", "faces": "any",
    "rules": {"corner": {
      "smooth": [{"sum": "vertices", "w": "j == 0 ? (k + 5)/(4*k) : (3 + 2*cos(2*pi*j/k))/(4*k)"}],
      "crease": [{"sum": "vertices", "w": "j == 0 ? 5/8 : (j == 1 ? 3/8 : 0)"}],
      "corner": [{"at": "self", "w": "1"}]}}})json";
  const auto s = load_scheme_text(text, "three-eighths.json");
  const test::Mesh torus = bumped(test::torus(8, 6));
  const Level L = creased_torus_level(torus, 8);
  const LimitSurface surface(s, L);
  double worst = 0;
  for (int i = 0; i < 8; ++i) {
    const P3 P = point(torus, Index(i)), Q = point(torus, Index((i + 1) % 8)), prev = point(torus, Index((i + 7) % 8));
    P3 expected{}, middle{};
    for (size_t c = 0; c < 3; ++c) {
      const double X1 = 0.625 * P[c] + 0.375 * Q[c], X0 = 0.625 * P[c] + 0.375 * prev[c];
      const double X2 = 0.375 * P[c] + 0.625 * Q[c];
      expected[c] = 0.625 * X1 + 0.1875 * (X0 + X2);
      middle[c] = 0.5 * (P[c] + Q[c]);
    }
    worst = std::max(worst, distance(at(surface, torus, Index(i), 0.25, 0), expected));
    worst = std::max(worst, distance(at(surface, torus, Index(i), 0.5, 0), middle));
  }
  CHECK(worst < 1e-12);
  check_edges_continuous(surface, torus, L, 1e-12);
}

TEST_CASE("dual limit next to a boundary: second derivatives against central differences of the first") {
  const test::Mesh grid = bumped(test::grid(5, 4));
  const LimitSurface s(scheme("doo-sabin"), grid.level());
  const double h = 1e-5;
  double worst = 0;
  int with_second = 0;
  for (Index f : {Index(0), Index(1), Index(2), Index(6)})
    for (const auto& uv : {std::array<double, 2>{0.3, 0.7}, {0.8, 0.4}, {0.6, 0.85}}) {
      const LimitSample p = s.evaluate(f, uv[0], uv[1], grid.positions, 3, 2);
      if (!p.has_second_derivatives) continue;
      ++with_second;
      const LimitSample up = s.evaluate(f, uv[0] + h, uv[1], grid.positions, 3, 1);
      const LimitSample um = s.evaluate(f, uv[0] - h, uv[1], grid.positions, 3, 1);
      const LimitSample vp = s.evaluate(f, uv[0], uv[1] + h, grid.positions, 3, 1);
      const LimitSample vm = s.evaluate(f, uv[0], uv[1] - h, grid.positions, 3, 1);
      for (size_t k = 0; k < 3; ++k) {
        const double scale = 1 + std::abs(p.duu[k]) + std::abs(p.duv[k]) + std::abs(p.dvv[k]);
        worst = std::max(worst, std::abs(p.duu[k] - (up.du[k] - um.du[k]) / (2 * h)) / scale);
        worst = std::max(worst, std::abs(p.duv[k] - (vp.du[k] - vm.du[k]) / (2 * h)) / scale);
        worst = std::max(worst, std::abs(p.dvv[k] - (vp.dv[k] - vm.dv[k]) / (2 * h)) / scale);
      }
    }
  CHECK(with_second == 12);
  CHECK(worst < 1e-5);
}

namespace {

// The cardinal B-spline of degree d centred at 0, by the Cox-de Boor recurrence
// N_d(x) = (x N_{d-1}(x) + (d + 1 - x) N_{d-1}(x - 1)) / d on [0, d + 1].
double cardinal(int d, double x) {
  std::function<double(int, double)> N = [&](int k, double y) -> double {
    if (k == 0) return y >= 0 && y < 1 ? 1.0 : 0.0;
    return (y * N(k - 1, y) + (k + 1 - y) * N(k - 1, y - 1)) / k;
  };
  return N(d, x + 0.5 * (d + 1));
}

}  // namespace

TEST_CASE("dual limit at a sharp crease of quad-bspline d = 4 and 6: the uniform degree-d B-spline of the loop") {
  // Chaikin's split then Lane & Riesenfeld's averaging passes along the crease: the crease is
  // the loop's uniform B-spline of degree d (control point k at parameter k); its crease points
  // move after the split, so the limit at the middle of a crease edge comes from the crease
  // curve's local subdivision matrix (dual_crease_curve.h). Evaluated at dyadic parameters and,
  // for d = 4, at 0.3 (a descent of the whole double), from both sides of the crease.
  const int nu = 8, nv = 6;
  const test::Mesh m = bumped(test::torus(nu, nv));
  const Level L = creased_torus_level(m, nu);
  for (int d : {4, 6}) {
    CAPTURE(d);
    ParameterOverrides o;
    o["d"] = std::to_string(d);
    const LimitSurface s(load_scheme("quad-bspline", o), L);
    double worst = 0;
    for (int i = 0; i < nu; i += 3)
      for (double u : {0.0, 0.5, 0.25, d == 4 ? 0.3 : 0.375}) {
        P3 e{0, 0, 0};
        for (int k = i - d; k <= i + d + 1; ++k) {
          const double w = cardinal(d, i + u - k);
          const P3 x = point(m, Index(((k % nu) + nu) % nu));
          for (size_t c = 0; c < 3; ++c) e[c] += w * x[c];
        }
        worst = std::max(worst, distance(at(s, m, Index(i), u, 0), e));
        worst = std::max(worst, distance(at(s, m, Index((nv - 1) * nu + i), u, 1), e));
      }
    CHECK(worst < 1e-12);
  }
  // Next to a corner the degree-d crease is the clamped spline (docs/features.md), and it
  // is evaluated: the boundary of a grid, continuous across every edge.
  ParameterOverrides o4;
  o4["d"] = "4";
  const test::Mesh grid = bumped(test::grid(3, 3));
  check_edges_continuous(LimitSurface(load_scheme("quad-bspline", o4), grid.level()), grid, grid.level(), 1e-12);
}

TEST_CASE("dual limit of quad-bspline d = 4 next to corners: boundary points on the refined boundary curve") {
  // The crease rules change within a few crease edges of a corner (the clamped ends,
  // "crease-ends" in the scheme), so a crease edge's middle takes the crease curve's own
  // limit mask only where its window is clear of them; nearer, the evaluation descends. Every
  // point evaluated on the boundary of a bumped 6 x 6 grid lies on the boundary polygon of
  // uniform level 6 (which is within about 1e-5 of the limit curve); a uniform mask used next
  // to a corner missed it by up to 5e-3.
  ParameterOverrides o;
  o["d"] = "4";
  const auto s4 = load_scheme("quad-bspline", o);
  const int n = 6;
  const test::Mesh grid = bumped(test::grid(n, n));
  RefineOptions ro;
  ro.levels = 6;
  const Hierarchy h = refine(*s4, grid.level(), ro);
  const std::vector<double> fine = interpolate(h, ro.levels, grid.positions, 3);
  const Level& F = h.levels.back();
  auto off_boundary = [&](const P3& x) {
    double best = 1e300;
    for (Index e = 0; e < F.edge_count(); ++e) {
      if (F.edge_face_count(e) != 1) continue;
      const Index a = F.edge_vertices[size_t(2 * e)], b = F.edge_vertices[size_t(2 * e + 1)];
      P3 d{}, ax{};
      double dd = 0, t = 0;
      for (size_t c = 0; c < 3; ++c) {
        d[c] = fine[size_t(3 * b) + c] - fine[size_t(3 * a) + c];
        ax[c] = x[c] - fine[size_t(3 * a) + c];
        dd += d[c] * d[c], t += ax[c] * d[c];
      }
      t = std::clamp(t / dd, 0.0, 1.0);
      double e2 = 0;
      for (size_t c = 0; c < 3; ++c) e2 += std::pow(ax[c] - t * d[c], 2);
      best = std::min(best, std::sqrt(e2));
    }
    return best;
  };
  const LimitSurface s(s4, grid.level());
  double worst = 0;
  for (int i = 0; i < n; ++i)
    for (double u : {0.5, 0.25, 0.75}) worst = std::max(worst, off_boundary(at(s, grid, grid_face(n, i, 0), u, 0)));
  CHECK(worst < 3e-5);
}

TEST_CASE("dual limit next to boundary vertices of other than two faces: the faces without a corner there") {
  // A boundary vertex of three or more faces leaves, after every step, two more beside it
  // (the face between its end faces touches the boundary at the vertex only): counted on the
  // engine's levels of the L. The faces with a corner there are refused with the reason; the
  // others never reach that structure and are evaluated exactly.
  const test::Mesh ell = l_shape();
  {
    RefineOptions ro;
    ro.levels = 3;
    const Hierarchy h = refine(*scheme("doo-sabin"), ell.level(), ro);
    for (int l = 1; l <= 3; ++l) {
      const Level& L = h.levels[size_t(l)];
      int three = 0;
      for (Index v = 0; v < L.vertex_count; ++v) three += L.on_boundary(v) && L.incident_face_count(v) == 3;
      CHECK(three == (1 << l));
    }
  }
  const test::Mesh disc = half_disc();
  const auto at_reflex = [](Index f) { return f == l_shape_face(2, 2) || f == l_shape_face(3, 2) || f == l_shape_face(2, 3); };
  const auto at_centre = [](Index f) { return f < 4; };
  for (const char* name : {"doo-sabin", "doo-sabin-centroid", "quad-bspline"}) {
    CAPTURE(name);
    ParameterOverrides d2;
    d2["d"] = "2";
    const auto sch = std::string(name) == "quad-bspline" ? load_scheme(name, d2) : scheme(name);
    const LimitSurface on_ell(sch, ell.level()), on_disc(sch, disc.level());
    for (Index f = 0; f < ell.level().face_count(); ++f)
      if (at_reflex(f))
        CHECK_THROWS_WITH_AS(on_ell.evaluate(f, 0.3, 0.6, ell.positions, 3), doctest::Contains("boundary vertex 24, which has 3 faces"),
                             Error);
    for (Index f = 0; f < 4; ++f)
      CHECK_THROWS_WITH_AS(on_disc.stencil(f, 0.3, 0.6, 0), doctest::Contains("boundary vertex 0, which has 4 faces"), Error);
    // Along the L's boundary from corner (6, 3) over the reflex corner to corner (3, 6): the
    // clamped quadratic B-spline of that polygon (knots 0, 0, 0, 1, ..., 5, 5, 5; Greville 0,
    // 1/2, 3/2, ..., 5), on the edges of the faces kept.
    std::vector<P3> polygon;
    for (Index v : {Index(27), Index(26), Index(25), Index(24), Index(31), Index(38), Index(45)})
      polygon.push_back(point(ell, v));
    const std::vector<double> knots{0, 0, 0, 1, 2, 3, 4, 5, 5, 5};
    const double greville[] = {0, 0.5, 1.5, 2.5, 3.5, 4.5, 5};
    double worst = 0;
    for (double u : {0.0, 0.125, 0.3, 0.5, 0.71, 1.0}) {
      // Face (5, 2) has polygon edge 0-1 as its top edge (u from 1 to 0), face (4, 2) edge 1-2;
      // face (2, 4) has edge 4-5 as its right edge (v from 0 to 1), face (2, 5) edge 5-6.
      auto curve = [&](int k, double t) {
        return quadratic_bspline(knots, polygon, std::min(greville[k] + t * (greville[k + 1] - greville[k]), 5 - 1e-15));
      };
      worst = std::max(worst, distance(at(on_ell, ell, l_shape_face(5, 2), 1 - u, 1), curve(0, u)));
      worst = std::max(worst, distance(at(on_ell, ell, l_shape_face(4, 2), 1 - u, 1), curve(1, u)));
      worst = std::max(worst, distance(at(on_ell, ell, l_shape_face(2, 4), 1, u), curve(4, u)));
      worst = std::max(worst, distance(at(on_ell, ell, l_shape_face(2, 5), 1, u), curve(5, u)));
    }
    CHECK(worst < 1e-12);
    // Both faces of every edge between faces kept give the same point.
    check_edges_continuous(on_ell, ell, ell.level(), 1e-12, at_reflex);
    check_edges_continuous(on_disc, disc, disc.level(), 1e-12, at_centre);
  }
  // The level-1 points of corners off the boundary: the V-face centroid limits of the refined mesh.
  check_level_one_points(ell, ell.level(), true, at_reflex, 50);
  check_level_one_points(disc, disc.level(), true, at_centre, 10);
}

TEST_CASE("dual limit next to boundary vertices of other than two faces: derivatives, affine invariance, stencils") {
  const test::Mesh ell = l_shape(), disc = half_disc();
  const LimitSurface on_ell(scheme("doo-sabin"), ell.level()), on_disc(scheme("doo-sabin"), disc.level());
  const std::array<std::array<double, 3>, 3> A{{{0.8, -0.3, 0.1}, {0.2, 1.1, -0.4}, {0.05, 0.3, 0.9}}};
  const P3 b{0.3, -1.2, 2.0};
  struct Case {
    const LimitSurface* s;
    const test::Mesh* m;
    std::vector<Index> faces;  // next to the vertex of three or four faces, without a corner there
  };
  const Case cases[] = {{&on_ell, &ell, {l_shape_face(1, 2), l_shape_face(4, 2), l_shape_face(4, 1), l_shape_face(2, 4), l_shape_face(1, 1)}},
                        {&on_disc, &disc, {4, 5, 7, 8, 11}}};
  for (const Case& c : cases) {
    test::Mesh moved = *c.m;
    for (Index v = 0; v < c.m->vertex_count; ++v)
      for (size_t r = 0; r < 3; ++r) {
        double x = b[r];
        for (size_t k = 0; k < 3; ++k) x += A[r][k] * c.m->positions[size_t(3 * v) + k];
        moved.positions[size_t(3 * v) + r] = x;
      }
    double derivative = 0, affine = 0, stencil = 0;
    int with_derivatives = 0;
    for (Index f : c.faces)
      for (const auto& uv : {std::array<double, 2>{0.5, 0.5}, {0.3, 0.7}, {0.8, 0.4}, {0.45, 0.2}, {0.6, 0.85}}) {
        CAPTURE(f);
        const LimitSample p = c.s->evaluate(f, uv[0], uv[1], c.m->positions, 3, 1);
        if (p.has_derivatives) {
          ++with_derivatives;
          derivative = std::max(derivative, limit_test::central_difference_error(*c.s, f, uv[0], uv[1], c.m->positions, 1e-6));
        }
        const P3 x{p.position[0], p.position[1], p.position[2]}, y = at(*c.s, moved, f, uv[0], uv[1]);
        P3 e = b;
        for (size_t r = 0; r < 3; ++r)
          for (size_t k = 0; k < 3; ++k) e[r] += A[r][k] * x[k];
        affine = std::max(affine, distance(y, e));
        const LimitStencil w = c.s->stencil(f, uv[0], uv[1], 0);
        P3 z{0, 0, 0};
        for (size_t k = 0; k < w.vertices.size(); ++k)
          for (size_t r = 0; r < 3; ++r) z[r] += w.position[k] * c.m->positions[size_t(3 * w.vertices[k]) + r];
        stencil = std::max(stencil, distance(x, z));
      }
    CHECK(with_derivatives == 25);
    CHECK(derivative < 1e-6);
    CHECK(affine < 1e-12);
    CHECK(stencil < 1e-13);
  }
}

namespace {

struct LevelPointCase {
  Index face;
  int corner;
  Uv far;  // the quadrant's (1, 1) in the face's (u, v)
  double rate;
  // From level `decay` on (a semi-sharp crease has decayed), the (1, 1) of the quadrant of the
  // chain's F-face in its own layout, in the face's (u, v).
  int decay = 1 << 20;
  Uv far_after{};
};

// For l = 1 ... levels: the distance between the point of corner c.corner of c.face after l
// doo-sabin steps (the corner of the l-th F-face of the face) and the limit evaluated at its
// parameter, (1 - 2^-l) of the way from the corner to the quadrant's (1, 1).
std::vector<double> level_point_errors(const test::Mesh& m, const Level& base, const LevelPointCase& c, int levels) {
  const LimitSurface s(scheme("doo-sabin"), base);
  RefineOptions ro;
  ro.levels = levels;
  const Hierarchy h = refine(*scheme("doo-sabin"), base, ro);
  std::vector<double> positions = m.positions;
  Index face = c.face;
  int corner = c.corner;
  constexpr Uv kCorner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Uv start = kCorner[c.corner];
  std::vector<double> error;
  for (int l = 1; l <= levels; ++l) {
    std::vector<double> next(size_t(3 * h.levels[size_t(l)].vertex_count));
    h.stencils[size_t(l - 1)].apply(positions, next, 3);
    positions.swap(next);
    // The point of `corner` of `face`, and the F-face of `face` (the child face inside it).
    const ChildOrigins& o = h.origins[size_t(l - 1)];
    const Level& child = h.levels[size_t(l)];
    Index point = kNone, f_face = kNone;
    for (size_t v = 0; v < o.kind.size(); ++v)
      if (o.kind[v] == OriginKind::Corner && o.parent[v] == face && int(o.local[v]) == corner) point = Index(v);
    for (Index g = 0; g < child.face_count(); ++g)
      if (o.parent_face[size_t(g)] == face) f_face = g;
    REQUIRE(point != kNone);
    REQUIRE(f_face != kNone);
    const bool after = l > c.decay;
    const Uv from = after ? Uv{start[0] + (1 - std::ldexp(1.0, -c.decay)) * (c.far[0] - start[0]),
                               start[1] + (1 - std::ldexp(1.0, -c.decay)) * (c.far[1] - start[1])}
                          : start;
    const Uv to = after ? c.far_after : c.far;
    const double t = 1 - std::ldexp(1.0, after ? c.decay - l : -l);
    const P3 e = at(s, m, c.face, from[0] + t * (to[0] - from[0]), from[1] + t * (to[1] - from[1]));
    error.push_back(distance(e, P3{positions[size_t(3 * point)], positions[size_t(3 * point + 1)],
                                   positions[size_t(3 * point + 2)]}));
    const auto g = child.face(f_face);
    corner = int(std::find(g.begin(), g.end(), point) - g.begin());
    face = f_face;
  }
  return error;
}

}  // namespace

TEST_CASE("dual limit next to boundary vertices of other than two faces: level-L points converge at the eigenvalue's rate") {
  // The point of corner j of face g after L steps (the corner of the L-th F-face of g) lies at
  // (1 - 2^-L, 1 - 2^-L) of the quadrant of (g, j) (docs/limit.md), which tends to the
  // quadrant's (1, 1). The evaluated limit there and the level-L point agree in the components
  // of eigenvalue 1 and those the parameterisation follows exactly; their distance shrinks by
  // the next eigenvalue of the local subdivision matrix at (1, 1) per step. At the centre of a
  // regular quad that is 1/4 (the tensor product of Chaikin's 1, 1/2, 1/4: the parameters are
  // linear, so 1 and 1/2 are exact). At the middle of a boundary edge it is 3/4, the subdominant
  // eigenvalue across the boundary (rows [[1, 0, 0], [1/4, 3/4, 0], [0, 3/4, 1/4]], Nasri 1987;
  // docs/analysis.md), which the parameters, halving per step, do not follow. Measured on a
  // quad of the L next to the reflex corner's faces, and on a boundary face beside them.
  const test::Mesh ell = l_shape();
  for (const auto& c : {LevelPointCase{l_shape_face(1, 1), 0, {0.5, 0.5}, 0.25},
                        LevelPointCase{l_shape_face(4, 2), 0, {0.5, 1.0}, 0.75}}) {
    CAPTURE(c.face);
    const std::vector<double> error = level_point_errors(ell, ell.level(), c, 7);
    CHECK(error[0] > 1e-4);
    for (size_t l : {size_t(5), size_t(6)}) CHECK(error[l] / error[l - 1] == doctest::Approx(c.rate).epsilon(5e-3));
  }
}

TEST_CASE("dual limit next to a crease vertex of four faces a side: the faces without a corner there") {
  Level L;
  const test::Mesh m = disc(&L);
  const LimitSurface s(scheme("doo-sabin"), L);
  for (Index f = 0; f < 8; ++f)
    CHECK_THROWS_WITH_AS(s.evaluate(f, 0.4, 0.3, m.positions, 3),
                         doctest::Contains("crease vertex 0, which has 4 and 4 faces on the sides of its crease"), Error);
  // The crease from corner to corner (ring-2 vertex 8, ring-1 vertex 8, the centre, ring-1
  // vertex 0, ring-2 vertex 0): the clamped quadratic B-spline (knots 0, 0, 0, 1, 2, 3, 3, 3;
  // Greville 0, 1/2, 3/2, 5/2, 3), on its two end edges from both sides.
  std::vector<P3> polygon;
  for (Index v : {Index(25), Index(9), Index(0), Index(1), Index(17)}) polygon.push_back(point(m, v));
  const std::vector<double> knots{0, 0, 0, 1, 2, 3, 3, 3};
  double worst = 0;
  for (double t : {0.0, 0.2, 0.5, 0.77, 1.0}) {
    const P3 near0 = quadratic_bspline(knots, polygon, std::min(2.5 + t / 2, 3 - 1e-15));
    const P3 near8 = quadratic_bspline(knots, polygon, 0.5 - t / 2);
    worst = std::max(worst, distance(at(s, m, 8, t, 0), near0));    // ring-1 0 to ring-2 0
    worst = std::max(worst, distance(at(s, m, 23, t, 1), near0));   // the same edge in face 8 + 15
    worst = std::max(worst, distance(at(s, m, 16, t, 0), near8));   // ring-1 8 to ring-2 8
    worst = std::max(worst, distance(at(s, m, 15, t, 1), near8));   // face 8 + 7
  }
  CHECK(worst < 1e-12);
  check_edges_continuous(s, m, L, 1e-12, [](Index f) { return f < 8; });
  check_level_one_points(m, L, true, [](Index f) { return f < 8; }, 20);
}

namespace {

// A 4 x 4 grid whose line of edges x = 2, from boundary vertex 2 to boundary vertex 22, has
// sharpness 2: at both ends a semi-sharp edge meets the boundary, three sharp edges, so those
// vertices are corners of the dual split while the edge is sharp (levels 0 and 1).
Level semi_sharp_line(const test::Mesh& m) {
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (int j = 0; j < 4; ++j) L.edge_sharpness[size_t(find_edge(L, Index(5 * j + 2), Index(5 * j + 7)))] = 2.f;
  return L;
}

// The unit cube with each face split into 2 x 2 quads (vertex 0 still at the origin, a cube
// corner of three faces), bumped; its edges along the cube's edges are tagged: those on the
// three cube edges at vertex 0 with sharpness s0 (along x), s1 (y), s2 (z), the others with
// s_rest. Every cube corner is then a corner of three sharp edges, every other vertex on a cube
// edge a crease vertex of two faces a side.
test::Mesh split_cube() { return bumped(limit_test::quad_split(test::cube())); }
Level semi_sharp_cube(float s0, float s1, float s2, float s_rest) {
  const test::Mesh flat = limit_test::quad_split(test::cube());
  Level L = flat.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (Index e = 0; e < L.edge_count(); ++e) {
    const P3 a = point(flat, L.edge_vertices[size_t(2 * e)]), b = point(flat, L.edge_vertices[size_t(2 * e + 1)]);
    int on_faces = 0, axis = 0;
    for (int k = 0; k < 3; ++k) {
      const double x = (a[size_t(k)] + b[size_t(k)]) / 2;
      if (x == 0 || x == 1) ++on_faces;
      else axis = k;
    }
    if (on_faces != 2) continue;  // not along a cube edge
    const bool at0 = a[size_t((axis + 1) % 3)] == 0 && a[size_t((axis + 2) % 3)] == 0;
    L.edge_sharpness[size_t(e)] = at0 ? (axis == 0 ? s0 : axis == 1 ? s1 : s2) : s_rest;
  }
  return L;
}

// One step of the crease rule on an open polygon (features.md, "Creases in dual schemes"):
// a corner stays, every other point makes two, Chaikin's 3/4 p + 1/4 q towards each
// neighbour q, or the edge's middle where q is a corner.
std::vector<P3> crease_step(const std::vector<P3>& p, const std::vector<bool>& corner, std::vector<bool>* child_corner) {
  std::vector<P3> out;
  child_corner->clear();
  auto cut = [](const P3& a, const P3& b, double w) {
    return P3{w * a[0] + (1 - w) * b[0], w * a[1] + (1 - w) * b[1], w * a[2] + (1 - w) * b[2]};
  };
  for (size_t i = 0; i < p.size(); ++i) {
    if (corner[i]) {
      out.push_back(p[i]);
      child_corner->push_back(true);
      continue;
    }
    out.push_back(cut(p[i], p[i - 1], corner[i - 1] ? 0.5 : 0.75));
    out.push_back(cut(p[i], p[i + 1], corner[i + 1] ? 0.5 : 0.75));
    child_corner->insert(child_corner->end(), 2, false);
  }
  return out;
}

// The distance from x to the clamped quadratic B-spline with control points `ctrl` (knots
// 0, 0, 0, 1, ..., K, K, K): sampled, then narrowed by golden sections around the best sample.
double distance_to_clamped_quadratic(const std::vector<P3>& ctrl, const P3& x) {
  const int K = int(ctrl.size()) - 2;
  std::vector<double> t{0, 0, 0};
  for (int k = 1; k < K; ++k) t.push_back(k);
  t.insert(t.end(), 3, double(K));
  auto d = [&](double s) { return distance(quadratic_bspline(t, ctrl, std::clamp(s, 0.0, K - 1e-15)), x); };
  double best = 0;
  for (int i = 0; i <= 200 * K; ++i)
    if (d(i / 200.0) < d(best)) best = i / 200.0;
  double a = best - 1 / 200.0, b = best + 1 / 200.0;
  for (int i = 0; i < 100; ++i) {
    const double m1 = a + (b - a) * 0.382, m2 = a + (b - a) * 0.618;
    (d(m1) < d(m2) ? b : a) = d(m1) < d(m2) ? m2 : m1;
  }
  return d((a + b) / 2);
}

}  // namespace

TEST_CASE("dual limit where a semi-sharp edge meets the boundary: the corner decays into a boundary vertex") {
  const test::Mesh m = bumped(test::grid(4, 4));
  const Level L = semi_sharp_line(m);
  // The vertex at boundary vertex 2 on the engine's levels: a corner (three sharp edges, two
  // quads) at levels 0 and 1, its point staying at vertex 2; at level 2 a boundary vertex of
  // the same two quads and no other sharp edge.
  {
    RefineOptions ro;
    ro.levels = 2;
    const Hierarchy h = refine(*scheme("doo-sabin"), L, ro);
    std::vector<double> p = m.positions;
    for (int l = 0; l <= 2; ++l) {
      if (l > 0) {
        std::vector<double> next(size_t(3 * h.levels[size_t(l)].vertex_count));
        h.stencils[size_t(l - 1)].apply(p, next, 3);
        p.swap(next);
      }
      const Level& Ll = h.levels[size_t(l)];
      Index at = kNone;
      for (Index v = 0; v < Ll.vertex_count; ++v)
        if (distance(P3{p[size_t(3 * v)], p[size_t(3 * v + 1)], p[size_t(3 * v + 2)]}, point(m, 2)) == 0) at = v;
      CAPTURE(l);
      REQUIRE(at != kNone);
      CHECK(Ll.incident_face_count(at) == 2);
      CHECK(Ll.on_boundary(at));
      CHECK(dual_sharp_edge_count(Ll, at) == (l < 2 ? 3 : 2));
    }
  }
  // The bottom boundary: the clamped quadratic B-spline of its polygon after two steps of the
  // crease rule with corners at both ends and at vertex 2 (Chaikin's cuts, the middle next to
  // a corner), after which vertex 2 is no corner and the polygon refines by Chaikin's cuts.
  std::vector<P3> polygon;
  for (Index v = 0; v <= 4; ++v) polygon.push_back(point(m, v));
  std::vector<bool> corner{true, false, true, false, true}, next;
  for (int l = 0; l < 2; ++l) {
    polygon = crease_step(polygon, corner, &next);
    corner = next;
  }
  // Vertex 2's limit: at level 2 its neighbours on the crease are (3 x2 + x1)/4 and
  // (3 x2 + x3)/4, and a boundary vertex's limit is (p + 6 v + q)/8: (x1 + 30 x2 + x3)/32.
  P3 at_corner{};
  for (size_t c = 0; c < 3; ++c) at_corner[c] = (point(m, 1)[c] + 30 * point(m, 2)[c] + point(m, 3)[c]) / 32;
  for (const char* name : {"doo-sabin", "doo-sabin-centroid", "quad-bspline"}) {
    CAPTURE(name);
    ParameterOverrides d2;
    d2["d"] = "2";
    const auto sch = std::string(name) == "quad-bspline" ? load_scheme(name, d2) : scheme(name);
    const LimitSurface s(sch, L);
    CHECK(distance(at(s, m, 1, 1, 0), at_corner) < 1e-12);
    CHECK(distance(at(s, m, 2, 0, 0), at_corner) < 1e-12);
    double off = 0;
    for (Index f = 0; f < 4; ++f)
      for (double u : {0.0, 0.1, 0.3, 0.5, 0.77, 0.95, 1.0})
        off = std::max(off, distance_to_clamped_quadratic(polygon, at(s, m, f, u, 0)));
    CHECK(off < 1e-9);
    check_edges_continuous(s, m, L, 1e-12);
  }
  // Chaikin's decay averages the sharpness of a crease vertex's edges; the corner's one
  // semi-sharp edge decays as under the uniform rule.
  LimitSurfaceOptions chaikin;
  chaikin.features.crease_method = CreaseMethod::Chaikin;
  check_edges_continuous(LimitSurface(scheme("doo-sabin"), L, chaikin), m, L, 1e-12);
  // Off the crease and the boundary the derivatives are those of the positions.
  const LimitSurface s(scheme("doo-sabin"), L);
  double worst = 0;
  for (Index f : {Index(1), Index(2), Index(5), Index(6), Index(13)})
    for (const auto& uv : {std::array<double, 2>{0.3, 0.6}, {0.7, 0.2}, {0.55, 0.9}})
      worst = std::max(worst, limit_test::central_difference_error(s, f, uv[0], uv[1], m.positions, 1e-6));
  CHECK(worst < 1e-6);
}

TEST_CASE("dual limit where a semi-sharp edge meets the boundary: level-L points converge at the eigenvalue's rate") {
  // Face 1 of the grid (corners 1, 2, 7, 6) has crease corners 1, 2 (the corner), 7: its one
  // quadrant, of corner 3, has its (1, 1) at vertex 2, (u, v) = (1, 0). Its second F-face, over
  // (u, v) in [3/4, 1] x [0, 1/4], has the corners (3/4, 1/4), (1, 1/4), (1, 0) (vertex 2's
  // point) and (3/4, 0); once the semi-sharp edge has decayed, vertex 2's point is a boundary
  // vertex and that face is laid out by its boundary edge: the quadrant of its corner
  // (3/4, 1/4) has (1, 1) at the edge's middle (7/8, 0), where the points converge at the rate
  // across a boundary, 3/4. Face 5 (corners 6, 7, 12, 11) beside the semi-sharp line: (1, 1) of
  // its corner 0 is the middle of edge 7-12, (1, 1/2); its second F-face, a half quad over
  // [3/4, 1] x [3/8, 5/8] (the quadrants of its corners off the crease, from corners 0 and 3 of
  // face 5), is a closed quad once the edge has decayed, with its centre (7/8, 1/2) the
  // quadrant's (1, 1), where the points converge at a regular quad's centre's rate, 1/4.
  const test::Mesh m = bumped(test::grid(4, 4));
  for (const auto& c : {LevelPointCase{1, 3, {1, 0}, 0.75, 2, {0.875, 0}},
                        LevelPointCase{5, 0, {1, 0.5}, 0.25, 2, {0.875, 0.5}}}) {
    CAPTURE(c.face);
    const std::vector<double> error = level_point_errors(m, semi_sharp_line(m), c, 8);
    CHECK(error[0] > 1e-4);
    for (size_t l : {size_t(6), size_t(7)}) CHECK(error[l] / error[l - 1] == doctest::Approx(c.rate).epsilon(5e-3));
  }
}

TEST_CASE("dual limit at a corner of semi-sharp edges: a smooth vertex once they have decayed") {
  // The split cube with its cube edges of sharpness 2: vertex 0 is a corner at levels 0 and 1
  // (its point stays), a smooth vertex of valence 3 from level 2.
  const test::Mesh m = split_cube();
  const Level L = semi_sharp_cube(2, 2, 2, 2);
  RefineOptions ro;
  ro.levels = 2;
  const Hierarchy h = refine(*scheme("doo-sabin"), L, ro);
  std::vector<double> p1(size_t(3 * h.levels[1].vertex_count)), p2(size_t(3 * h.levels[2].vertex_count));
  h.stencils[0].apply(m.positions, p1, 3);
  h.stencils[1].apply(p1, p2, 3);
  Level L2 = h.levels[2];
  for (float x : L2.edge_sharpness) REQUIRE(x == 0.f);
  L2.edge_sharpness.clear();
  Index at0 = kNone;
  for (Index v = 0; v < L2.vertex_count; ++v)
    if (distance(P3{p2[size_t(3 * v)], p2[size_t(3 * v + 1)], p2[size_t(3 * v + 2)]}, point(m, 0)) == 0) at0 = v;
  REQUIRE(at0 != kNone);
  CHECK(L2.incident_face_count(at0) == 3);
  CHECK(!L2.on_boundary(at0));
  // Vertex 0's limit: the V-face centroid limit of the untagged level-2 mesh (dual_limits.h,
  // from its own next step, not this evaluator), from each of its three faces.
  const LimitChoice c = select_limit(load_scheme_sequence("doo-sabin", 1, {}), L2);
  std::vector<double> limits(p2.size());
  c.evaluator->limit_points(L2, p2, limits);
  const P3 expected{limits[size_t(3 * at0)], limits[size_t(3 * at0 + 1)], limits[size_t(3 * at0 + 2)]};
  CHECK(distance(expected, point(m, 0)) > 1e-2);  // the corner has decayed
  constexpr std::array<std::array<double, 2>, 4> kCorner{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const LimitSurface s(scheme("doo-sabin"), L);
  REQUIRE(L.ring_faces(0).size() == 3);
  double worst = 0;
  for (Index f : L.ring_faces(0)) {
    const auto g = L.face(f);
    const size_t k = size_t(std::find(g.begin(), g.end(), Index(0)) - g.begin());
    CHECK(distance(at(s, m, f, kCorner[k][0], kCorner[k][1]), expected) < 1e-12);
    for (const auto& uv : {std::array<double, 2>{0.3, 0.6}, {0.7, 0.2}, {0.05, 0.1}, {0.9, 0.97}})
      worst = std::max(worst, limit_test::central_difference_error(s, f, uv[0], uv[1], m.positions, 1e-6));
  }
  CHECK(worst < 1e-6);
  check_edges_continuous(s, m, L, 1e-12);
}

TEST_CASE("dual limit at corners whose ring of faces grows: the faces there are refused, the others evaluated") {
  // A tagged corner with smooth edges: the E-face of each edge loses a corner to the corner's
  // point, so the faces around it grow every level. And semi-sharp edges of sharpness 2 and
  // 3 at vertex 0 (and at the other end of the edge of 3), which leave a corner with a smooth
  // edge after two steps.
  const test::Mesh m = split_cube();
  Level tagged = m.level();
  tagged.vertex_sharpness.assign(size_t(tagged.vertex_count), 0.f);
  tagged.vertex_sharpness[0] = 10.f;
  const Level uneven = semi_sharp_cube(2, 2, 3, 2);
  struct Case {
    const Level* level;
    std::vector<Index> corners;
    const char* why;
  };
  for (const Case& c : {Case{&tagged, {0}, "not sharp"}, Case{&uneven, {0, 4}, "decay at different levels"}}) {
    CAPTURE(c.why);
    const LimitSurface s(scheme("doo-sabin"), *c.level);
    std::vector<Index> refused;
    for (Index v : c.corners)
      for (Index f : c.level->ring_faces(v)) {
        refused.push_back(f);
        CHECK_THROWS_WITH_AS(s.evaluate(f, 0.4, 0.7, m.positions, 3),
                             doctest::Contains(("face " + std::to_string(f) + " has a corner at corner vertex " + std::to_string(v)).c_str()),
                             Error);
        CHECK_THROWS_WITH_AS(s.evaluate(f, 0.4, 0.7, m.positions, 3), doctest::Contains(c.why), Error);
      }
    check_edges_continuous(s, m, *c.level, 1e-12,
                           [&](Index f) { return std::find(refused.begin(), refused.end(), f) != refused.end(); });
  }
}

namespace {

// A grid whose row of edges y = `row` is infinitely sharp: its top row of faces lies between
// that crease and the top boundary (faces between two creases; the crease ends at the side
// boundaries in corners, vertices of three sharp edges).
Level crease_row(const test::Mesh& m, int nx, int row) {
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  auto id = [&](int i, int j) { return Index(j * (nx + 1) + i); };
  for (int i = 0; i < nx; ++i) L.edge_sharpness[size_t(find_edge(L, id(i, row), id(i + 1, row)))] = 10.f;
  return L;
}

// The clamped quadratic B-spline of row j of test::grid(nx, ...) (corners at both ends: knots
// 0, 0, 0, 1, ..., nx - 1 three times; P_0 at Greville 0, P_i at i - 1/2, P_nx at nx - 1) at
// u along the edge from (i, j) to (i + 1, j).
P3 clamped_row(const test::Mesh& m, int nx, int j, int i, double u) {
  std::vector<P3> row;
  for (int k = 0; k <= nx; ++k) row.push_back(point(m, Index(j * (nx + 1) + k)));
  std::vector<double> knots{0, 0, 0};
  for (int k = 1; k < nx - 1; ++k) knots.push_back(k);
  for (int r = 0; r < 3; ++r) knots.push_back(nx - 1);
  auto greville = [&](int k) { return k == 0 ? 0.0 : (k == nx ? nx - 1.0 : k - 0.5); };
  const double x = greville(i) + u * (greville(i + 1) - greville(i));
  return quadratic_bspline(knots, row, std::min(x, nx - 1 - 1e-15));
}

P3 mix(const P3& a, const P3& b, double t) {
  return {(1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1], (1 - t) * a[2] + t * b[2]};
}

}  // namespace

TEST_CASE("dual limit between two creases: the ruled surface between the two crease curves") {
  // A face between two infinitely sharp creases is refined along them only (its children are
  // its F-face and the E-faces of its smooth edges, again between the same creases), so the
  // level-L quads between the creases join the level-L crease polygons bilinearly, and the
  // limit is (1 - v) C_0(u) + v C_1(u) with C_i Chaikin's curves (docs/limit.md).
  ParameterOverrides d2;
  d2["d"] = "2";
  // One face wide: a strip of five quads, two (one vertex between two corners: a quadratic
  // Bezier curve each side), and of a crease row under the top boundary of a 5 x 3 grid.
  struct Case {
    int nx, ny, row;
  };
  for (const Case c : {Case{5, 1, 0}, Case{2, 1, 0}, Case{5, 3, 2}}) {
    CAPTURE(c.nx);
    CAPTURE(c.ny);
    const test::Mesh m = bumped(test::grid(c.nx, c.ny));
    const Level L = c.row == 0 ? m.level() : crease_row(m, c.nx, c.row);
    for (const char* name : {"doo-sabin", "doo-sabin-centroid", "quad-bspline"}) {
      CAPTURE(name);
      const LimitSurface s(std::string(name) == "quad-bspline" ? load_scheme(name, d2) : scheme(name), L);
      double worst = 0;
      for (int i = 0; i < c.nx; ++i)
        for (double u : {0.0, 0.125, 0.3, 0.5, 0.71, 1.0})
          for (double v : {0.0, 0.2, 0.5, 0.875, 1.0}) {
            const P3 e = mix(clamped_row(m, c.nx, c.row, i, u), clamped_row(m, c.nx, c.row + 1, i, u), v);
            worst = std::max(worst, distance(at(s, m, grid_face(c.nx, i, c.row), u, v), e));
          }
      CHECK(worst < 1e-12);
    }
  }
  // A single quad: every edge on the boundary, every corner a corner of the mesh; the face is
  // its own F-face at every step, so the limit is the bilinear quad.
  test::Mesh quad;
  for (int k = 0; k < 4; ++k) quad.add_vertex(k == 1 || k == 2, k >= 2, k == 2 ? 0.7 : 0.1 * k);
  quad.add_face({0, 1, 2, 3});
  const LimitSurface s(scheme("doo-sabin"), quad.level());
  for (double u : {0.0, 0.3, 0.8})
    for (double v : {0.1, 0.5, 1.0})
      CHECK(distance(at(s, quad, 0, u, v), mix(mix(point(quad, 0), point(quad, 1), u),
                                               mix(point(quad, 3), point(quad, 2), u), v)) < 1e-15);
}

TEST_CASE("dual limit between two creases: continuous across every edge, affine invariant, stencils, level points") {
  const int nx = 5;
  const test::Mesh m = bumped(test::grid(nx, 3));
  const Level L = crease_row(m, nx, 2);
  const LimitSurface s(scheme("doo-sabin"), L);
  // Across the crease the faces below (half faces, read in their quadrants) give the crease
  // curve as the faces between the creases do.
  check_edges_continuous(s, m, L, 1e-12);
  std::vector<Index> faces;
  for (int i = 0; i < nx; ++i) faces.push_back(grid_face(nx, i, 2));
  const AffineStencilErrors errors = affine_and_stencil_errors(s, m, faces, {0.25, 1}, 2);
  CHECK(errors.affine < 1e-12);
  CHECK(errors.stencil < 1e-13);
}

TEST_CASE("dual limit between two creases: linear across, as the refined quads are; level points converge as 4^-L") {
  // The L-th F-face of a face between the creases has its corners on the two level-L crease
  // polygons at u = 1/2 -+ 2^-(L+1); its point (1/2, w) is the polygons' edge middles mixed
  // by w, and an edge middle of Chaikin's polygon lies on its curve (the quadratic B-spline at
  // a knot is the mean of the two control points beside it). So at every level it is the
  // limit at (1/2, w) of the base face. Its corners 0 (on the crease) and 3 (on the boundary),
  // at u = (1 - 2^-L)/2, are vertices of Chaikin's polygons, which differ from their curves by
  // an eighth of the polygon's second difference there: 1/4 per step.
  const int nx = 5;
  const test::Mesh m = bumped(test::grid(nx, 3));
  const Level L = crease_row(m, nx, 2);
  const LimitSurface s(scheme("doo-sabin"), L);
  RefineOptions ro;
  ro.levels = 7;
  const Hierarchy h = refine(*scheme("doo-sabin"), L, ro);
  std::vector<double> positions = m.positions;
  const Index base_face = grid_face(nx, 2, 2);
  Index face = base_face;
  double worst = 0;
  std::vector<std::array<double, 2>> error;  // corners 0 and 3
  for (int l = 1; l <= 7; ++l) {
    std::vector<double> next(size_t(3 * h.levels[size_t(l)].vertex_count));
    h.stencils[size_t(l - 1)].apply(positions, next, 3);
    positions.swap(next);
    const Level& child = h.levels[size_t(l)];
    Index f_face = kNone;
    for (Index g = 0; g < child.face_count(); ++g)
      if (h.origins[size_t(l - 1)].parent_face[size_t(g)] == face) f_face = g;
    REQUIRE(f_face != kNone);
    face = f_face;
    const auto g = child.face(face);
    REQUIRE(g.size() == 4);
    auto p = [&](size_t k) {
      const size_t x = size_t(3 * g[k]);
      return P3{positions[x], positions[x + 1], positions[x + 2]};
    };
    for (double w : {0.0, 1.0 / 3, 1.0}) {
      // Corners 0, 1 on the crease, 3, 2 on the boundary (the F-face keeps the face's order).
      const P3 e = mix(mix(p(0), p(1), 0.5), mix(p(3), p(2), 0.5), w);
      worst = std::max(worst, distance(at(s, m, base_face, 0.5, w), e));
    }
    const double u = (1 - std::ldexp(1.0, -l)) / 2;
    error.push_back({distance(p(0), at(s, m, base_face, u, 0)), distance(p(3), at(s, m, base_face, u, 1))});
  }
  CHECK(worst < 1e-12);
  for (size_t k = 0; k < 2; ++k) {
    CAPTURE(k);
    CHECK(error[0][k] > 1e-4);
    for (size_t l : {size_t(5), size_t(6)}) CHECK(error[l][k] / error[l - 1][k] == doctest::Approx(0.25).epsilon(5e-3));
  }
}

TEST_CASE("dual limit between two creases: derivatives against central differences") {
  const int nx = 5;
  const test::Mesh m = bumped(test::grid(nx, 3));
  const Level L = crease_row(m, nx, 2);
  // The strip of one face: its faces run along v in a grid turned a quarter (k = 1 layout).
  const test::Mesh strip = bumped(test::grid(1, 4));
  // Named, not a structured binding: clang 14 (the sanitizer build) cannot capture those.
  for (const auto& setup : {std::tuple{&m, L, 2}, std::tuple{&strip, strip.level(), -1}}) {
    const test::Mesh* const mesh = std::get<0>(setup);
    const int row = std::get<2>(setup);
    const LimitSurface s(scheme("doo-sabin"), std::get<1>(setup));
    const double h = 1e-6;
    double worst = 0, worst2 = 0;
    const int faces = row < 0 ? 4 : nx;
    for (int i = 0; i < faces; ++i)
      for (const auto& uv : {std::array<double, 2>{0.45, 0.55}, {0.3, 0.7}, {0.8, 0.4}, {0.1, 0.2}, {0.6, 0.85}}) {
        const Index f = row < 0 ? Index(i) : grid_face(nx, i, row);
        const double u = uv[0], v = uv[1];
        const LimitSample p = s.evaluate(f, u, v, mesh->positions, 3, 2);
        REQUIRE(p.has_second_derivatives);
        auto d = [&](double du, double dv) { return s.evaluate(f, u + du, v + dv, mesh->positions, 3, 1); };
        const LimitSample up = d(h, 0), um = d(-h, 0), vp = d(0, h), vm = d(0, -h);
        for (size_t k = 0; k < 3; ++k) {
          worst = std::max(worst, std::abs(p.du[k] - (up.position[k] - um.position[k]) / (2 * h)));
          worst = std::max(worst, std::abs(p.dv[k] - (vp.position[k] - vm.position[k]) / (2 * h)));
          worst2 = std::max(worst2, std::abs(p.duu[k] - (up.du[k] - um.du[k]) / (2 * h)));
          worst2 = std::max(worst2, std::abs(p.duv[k] - (vp.du[k] - vm.du[k]) / (2 * h)));
          worst2 = std::max(worst2, std::abs(p.dvv[k] - (vp.dv[k] - vm.dv[k]) / (2 * h)));
        }
      }
    CHECK(worst < 1e-7);
    CHECK(worst2 < 1e-6);
  }
}

namespace {

// A torus whose loops of vertices j = 0 and j = 1 have edges of sharpness s: the faces (i, 0),
// numbered i, lie between two semi-sharp creases.
Level two_loops(const test::Mesh& m, int nu, float s) {
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (int j : {0, 1})
    for (int i = 0; i < nu; ++i)
      L.edge_sharpness[size_t(find_edge(L, Index(j * nu + i), Index(j * nu + (i + 1) % nu)))] = s;
  return L;
}

}  // namespace

TEST_CASE("dual limit between two semi-sharp creases: the limit of the mesh after they have decayed") {
  // Sharpness 1: one step with the crease rules, smooth after. The F-face of a face between
  // the creases holds along in [1/4, 3/4] as along' = 2 along - 1/2, across kept
  // (docs/limit.md); the level-1 mesh is untagged, and its limit there (the closed-face
  // evaluation) is the reference. Sharpness 2: the level-1 mesh has sharpness 1 on the loops.
  const int nu = 8;
  const test::Mesh torus = bumped(test::torus(nu, 6));
  for (float sharpness : {1.f, 2.f}) {
    CAPTURE(sharpness);
    const Level L = two_loops(torus, nu, sharpness);
    const LimitSurface s(scheme("doo-sabin"), L);
    RefineOptions ro;
    ro.levels = 1;
    const Hierarchy h = refine(*scheme("doo-sabin"), L, ro);
    test::Mesh m1;
    m1.positions.resize(size_t(3 * h.levels[1].vertex_count));
    h.stencils[0].apply(torus.positions, m1.positions, 3);
    const LimitSurface s1(scheme("doo-sabin"), h.levels[1]);
    double worst = 0;
    int checked = 0;
    for (Index f = 0; f < nu; ++f) {
      Index F = kNone;
      for (Index g = 0; g < h.levels[1].face_count(); ++g)
        if (h.origins[0].parent_face[size_t(g)] == f) F = g;
      REQUIRE(F != kNone);
      for (double u : {0.25, 0.3, 0.5, 0.71, 0.75})
        for (double v : {0.0, 0.2, 0.5, 0.875, 1.0}) {
          worst = std::max(worst, distance(at(s, torus, f, u, v), at(s1, m1, F, 2 * u - 0.5, v)));
          ++checked;
        }
    }
    CHECK(checked == 200);
    CHECK(worst < 1e-12);
  }
  // Continuous across every edge: the rungs between the faces between the creases, the creases
  // (half faces on the other side), after the decay to 0 or to a fractional sharpness.
  for (float sharpness : {1.f, 2.f, 2.5f}) {
    CAPTURE(sharpness);
    const Level L = two_loops(torus, nu, sharpness);
    check_edges_continuous(LimitSurface(scheme("doo-sabin"), L), torus, L, 1e-12);
  }
  // Not the lasting creases' ruled surface, nor the smooth surface (away from v = 1/2, where
  // both are the quadratic B-spline of the mean of the two rows: the biquadratic B-spline on a
  // knot line across is).
  const LimitSurface semi(scheme("doo-sabin"), two_loops(torus, nu, 2.f)),
      lasting(scheme("doo-sabin"), two_loops(torus, nu, 10.f)), smooth(scheme("doo-sabin"), torus.level());
  for (double v : {0.0, 0.25}) {
    const P3 a = at(smooth, torus, 2, 0.4, v), b = at(lasting, torus, 2, 0.4, v), c = at(semi, torus, 2, 0.4, v);
    CHECK(distance(c, a) > 1e-3);
    CHECK(distance(c, b) > 1e-3);
  }
}

TEST_CASE("dual limit between two semi-sharp creases: derivatives, affine invariance, stencils") {
  const int nu = 8;
  const test::Mesh torus = bumped(test::torus(nu, 6));
  const Level L = two_loops(torus, nu, 2.f);
  const LimitSurface s(scheme("doo-sabin"), L);
  const double h = 1e-6;
  double worst = 0, stencil_worst = 0;
  for (Index f : {Index(0), Index(3), Index(5)})
    for (const auto& uv : {std::array<double, 2>{0.45, 0.55}, {0.3, 0.7}, {0.8, 0.4}, {0.1, 0.2}, {0.6, 0.85}}) {
      const double u = uv[0], v = uv[1];
      const LimitSample p = s.evaluate(f, u, v, torus.positions, 3, 1);
      REQUIRE(p.has_derivatives);
      const P3 up = at(s, torus, f, u + h, v), um = at(s, torus, f, u - h, v);
      const P3 vp = at(s, torus, f, u, v + h), vm = at(s, torus, f, u, v - h);
      for (size_t k = 0; k < 3; ++k) {
        worst = std::max(worst, std::abs(p.du[k] - (up[k] - um[k]) / (2 * h)));
        worst = std::max(worst, std::abs(p.dv[k] - (vp[k] - vm[k]) / (2 * h)));
      }
      const LimitStencil w = s.stencil(f, u, v, 1);
      P3 y{0, 0, 0}, du{0, 0, 0};
      for (size_t k = 0; k < w.vertices.size(); ++k)
        for (size_t c = 0; c < 3; ++c) {
          y[c] += w.position[k] * torus.positions[size_t(3 * w.vertices[k]) + c];
          du[c] += w.du[k] * torus.positions[size_t(3 * w.vertices[k]) + c];
        }
      stencil_worst = std::max(stencil_worst, distance(P3{p.position[0], p.position[1], p.position[2]}, y));
      stencil_worst = std::max(stencil_worst, distance(P3{p.du[0], p.du[1], p.du[2]}, du));
    }
  CHECK(worst < 1e-6);
  CHECK(stencil_worst < 1e-12);
  // Affine invariance.
  const std::array<std::array<double, 3>, 3> A{{{0.8, -0.3, 0.1}, {0.2, 1.1, -0.4}, {0.05, 0.3, 0.9}}};
  const P3 b{0.3, -1.2, 2.0};
  test::Mesh moved = torus;
  for (Index x = 0; x < torus.vertex_count; ++x)
    for (size_t r = 0; r < 3; ++r) {
      double y = b[r];
      for (size_t c = 0; c < 3; ++c) y += A[r][c] * torus.positions[size_t(3 * x) + c];
      moved.positions[size_t(3 * x) + r] = y;
    }
  double affine = 0;
  for (double u : {0.05, 0.5, 0.9}) {
    const P3 p = at(s, torus, 1, u, 0.3), q = at(s, moved, 1, u, 0.3);
    P3 e = b;
    for (size_t r = 0; r < 3; ++r)
      for (size_t c = 0; c < 3; ++c) e[r] += A[r][c] * p[c];
    affine = std::max(affine, distance(q, e));
  }
  CHECK(affine < 1e-12);
}
