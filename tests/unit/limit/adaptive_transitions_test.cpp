// Transition faces as triangles and quads (limit/adaptive_transitions.h) against the polygon
// output of the same refinement: every face has 3 or 4 corners; the vertices are the same
// points (bit for bit, with and without limit positions); the mesh is as watertight as the
// polygons' (every edge in two faces, or on the polygons' own boundary: no T-junction) with
// the same Euler characteristic; and the new faces tile each polygon exactly. Tiling is
// checked in each base face's (u, v) domain, where every face is a planar convex polygon:
// every new face has a positive signed area there (none degenerate or flipped) and, base face
// by base face, the areas add up to the polygons' — with a manifold, consistently oriented
// mesh that is a cover of degree one. On planar meshes (a grid, with a crease) the same is
// checked in R^3: the output's area equals the polygons' to 1e-12. Face-varying values follow
// their corners: adaptive_face_varying_test.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "framework/limit/adaptive_refine.h"
#include "framework/limit/adaptive_transitions.h"
#include "framework/limit/limit_surface.h"
#include "framework/pipeline/adaptive_request.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

struct Pair {
  AdaptiveMesh polygons, triangles;
};

Pair adapt_both(const Scheme& scheme, const Level& base, std::span<const double> points, int levels,
                const LimitSurface* surface = nullptr, double tolerance = 0, bool limit = false) {
  AdaptiveOptions o;
  o.levels = levels;
  o.surface = surface;
  o.tolerance = tolerance;
  o.limit = limit;
  Pair p;
  p.polygons = refine_adaptive(scheme, base, points, o);
  o.transitions = AdaptiveTransitions::Triangles;
  p.triangles = refine_adaptive(scheme, base, points, o);
  return p;
}

Level level_of(const AdaptiveMesh& m) {
  return build_level(Index(m.positions.size() / 3), m.face_offsets, m.face_vertices);
}

size_t face_count(const AdaptiveMesh& m) { return m.face_offsets.size() - 1; }

// Signed area of face f in its base face's (u, v) domain (shoelace formula).
double uv_area(const AdaptiveMesh& m, size_t f) {
  double a = 0;
  const Index first = m.face_offsets[f], n = m.face_offsets[f + 1] - first;
  for (Index k = 0; k < n; ++k) {
    const auto& p = m.corner_uv[size_t(first + k)];
    const auto& q = m.corner_uv[size_t(first + (k + 1) % n)];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return a / 2;
}

// Area in R^3 of a planar polygon: half the length of its vector area.
double area(const AdaptiveMesh& m, size_t f) {
  double s[3] = {0, 0, 0};
  const Index first = m.face_offsets[f], n = m.face_offsets[f + 1] - first;
  for (Index k = 0; k < n; ++k) {
    const double* p = &m.positions[3 * size_t(m.face_vertices[size_t(first + k)])];
    const double* q = &m.positions[3 * size_t(m.face_vertices[size_t(first + (k + 1) % n)])];
    s[0] += p[1] * q[2] - p[2] * q[1], s[1] += p[2] * q[0] - p[0] * q[2], s[2] += p[0] * q[1] - p[1] * q[0];
  }
  return std::hypot(s[0], s[1], s[2]) / 2;
}

// The properties in the header.
void check_tiles_polygons(const Pair& p) {
  const AdaptiveMesh &P = p.polygons, &T = p.triangles;
  int bad_size = 0, transitions = 0;
  for (size_t f = 0; f < face_count(T); ++f) {
    const Index n = T.face_offsets[f + 1] - T.face_offsets[f];
    bad_size += n != 3 && n != 4;
  }
  for (size_t f = 0; f < face_count(P); ++f)
    for (Index k = P.face_offsets[f]; k < P.face_offsets[f + 1]; ++k)
      if (!P.corner_is_face_corner[size_t(k)]) {
        ++transitions;
        break;
      }
  CHECK(bad_size == 0);
  CHECK(transitions > 0);  // the case has transition polygons to tessellate
  CHECK(face_count(T) > face_count(P));
  // The same points: the tessellation adds and moves none.
  CHECK(T.positions == P.positions);
  CHECK(T.data == P.data);
  // Watertight as the polygons: edges in one face are the polygons' boundary edges.
  const Level LP = level_of(P), LT = level_of(T);
  CHECK(LT.manifold());
  std::set<std::pair<Index, Index>> boundary;
  for (Index e = 0; e < LP.edge_count(); ++e)
    if (LP.edge_face_count(e) == 1) boundary.insert(std::minmax(LP.edge_vertices[2 * size_t(e)], LP.edge_vertices[2 * size_t(e) + 1]));
  int wrong = 0;
  size_t boundary_edges = 0;
  for (Index e = 0; e < LT.edge_count(); ++e) {
    const int faces = LT.edge_face_count(e);
    if (faces == 1) {
      ++boundary_edges;
      wrong += !boundary.count(std::minmax(LT.edge_vertices[2 * size_t(e)], LT.edge_vertices[2 * size_t(e) + 1]));
    }
    wrong += faces < 1 || faces > 2;
  }
  CHECK(wrong == 0);
  CHECK(boundary_edges == boundary.size());
  CHECK(LT.vertex_count - LT.edge_count() + LT.face_count() == LP.vertex_count - LP.edge_count() + LP.face_count());
  // Exact tiling in each base face's domain; the cell arrays follow their polygon.
  std::map<Index, double> area_p, area_t;
  std::map<std::pair<Index, int>, int> level_p, level_t;  // faces per (base face, level), as corners
  double smallest = 1;
  for (size_t f = 0; f < face_count(P); ++f) area_p[P.base_face[f]] += uv_area(P, f);
  for (size_t f = 0; f < face_count(T); ++f) {
    const double a = uv_area(T, f);
    smallest = std::min(smallest, a);
    area_t[T.base_face[f]] += a;
  }
  CHECK(smallest > 0);
  REQUIRE(area_p.size() == area_t.size());
  double worst = 0;
  for (const auto& [b, a] : area_p) worst = std::max(worst, std::abs(area_t[b] - a));
  CHECK(worst < 1e-14);
  // A (base face, level, vertex) seen in a polygon is seen in its triangles, and no other.
  std::set<std::tuple<Index, int, Index>> corners_p, corners_t;
  for (size_t f = 0; f < face_count(P); ++f)
    for (Index k = P.face_offsets[f]; k < P.face_offsets[f + 1]; ++k)
      corners_p.insert({P.base_face[f], P.face_level[f], P.face_vertices[size_t(k)]});
  for (size_t f = 0; f < face_count(T); ++f)
    for (Index k = T.face_offsets[f]; k < T.face_offsets[f + 1]; ++k)
      corners_t.insert({T.base_face[f], T.face_level[f], T.face_vertices[size_t(k)]});
  CHECK(corners_p == corners_t);
}

void check_same_area(const Pair& p) {
  double a = 0, b = 0;
  for (size_t f = 0; f < face_count(p.polygons); ++f) a += area(p.polygons, f);
  for (size_t f = 0; f < face_count(p.triangles); ++f) b += area(p.triangles, f);
  CHECK(std::abs(a - b) < 1e-12 * std::max(1.0, a));
}

Level creased_grid(const test::Mesh& grid) {
  Level base = grid.level();
  base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
  base.edge_sharpness[size_t(find_edge(base, 8, 9))] = 10.f;
  base.edge_sharpness[size_t(find_edge(base, 9, 10))] = 10.f;
  return base;
}

}  // namespace

TEST_CASE("Triangulated transitions of Catmull-Clark on a cube: quads and triangles tiling the polygons") {
  const test::Mesh cube = test::cube();
  const auto scheme = load_scheme("catmull-clark");
  for (int levels : {3, 4, 5}) {
    CAPTURE(levels);
    check_tiles_polygons(adapt_both(*scheme, cube.level(), cube.positions, levels));
  }
  // With limit positions: the same limit points (each vertex evaluated where the polygons
  // put it), and a tolerance.
  const test::Mesh bumpy = limit_test::bumped(test::cube(), 0.3);
  const LimitSurface surface(scheme, bumpy.level());
  const Pair p = adapt_both(*scheme, bumpy.level(), bumpy.positions, 5, &surface, 2e-3, true);
  check_tiles_polygons(p);
}

TEST_CASE("Triangulated transitions on planar grids with a crease and a boundary: the same area in R^3") {
  const test::Mesh grid = test::grid(6, 5);
  const Level base = creased_grid(grid);
  const Pair cc = adapt_both(*load_scheme("catmull-clark"), base, grid.positions, 4);
  check_tiles_polygons(cc);
  check_same_area(cc);
  const test::Mesh tri = test::grid(6, 5, true);
  const Level tri_base = creased_grid(tri);
  const Pair loop = adapt_both(*load_scheme("loop"), tri_base, tri.positions, 4);
  check_tiles_polygons(loop);
  check_same_area(loop);
}

TEST_CASE("Triangulated transitions of Loop: the octahedron closed, and with a tolerance and limit positions") {
  const test::Mesh octa = limit_test::octahedron();
  const auto scheme = load_scheme("loop");
  check_tiles_polygons(adapt_both(*scheme, octa.level(), octa.positions, 3));
  const test::Mesh bumpy = limit_test::bumped(limit_test::octahedron(), 0.3);
  const LimitSurface surface(scheme, bumpy.level());
  const Pair p = adapt_both(*scheme, bumpy.level(), bumpy.positions, 5, &surface, 2e-3, true);
  check_tiles_polygons(p);
}

TEST_CASE("An unknown transitions name is refused naming the choices") {
  CHECK(transitions_from_name("polygons") == AdaptiveTransitions::Polygons);
  CHECK(transitions_from_name("triangles") == AdaptiveTransitions::Triangles);
  CHECK_THROWS_WITH_AS(transitions_from_name("quads"), doctest::Contains("give polygons"), OptionError);
}

TEST_CASE("Every transition polygon of a square or triangle, 0 to 3 finer vertices a side, is tiled exactly") {
  // One face, its level's corners at the domain's corners and k equally spaced finer vertices
  // on each side (k = 1: the fixed patterns, in every rotation; more: the zipped triangles), as
  // neighbours 0 to 2 levels finer put them. The faces must tile it: 3 or 4 corners each, a
  // positive area each, the areas adding up to the face's, every side of the polygon in one
  // new face and every other edge in two, once each way.
  for (const int n : {3, 4}) {
    const std::vector<std::array<double, 2>> corner =
        n == 4 ? std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}
               : std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {0, 1}};
    const int configurations = n == 4 ? 256 : 64;
    for (int code = 1; code < configurations; ++code) {
      CAPTURE(n);
      CAPTURE(code);
      AdaptiveMesh m;
      for (int i = 0, c = code; i < n; ++i, c /= 4) {
        const int k = c % 4;
        const auto &a = corner[size_t(i)], &b = corner[size_t((i + 1) % n)];
        for (int j = 0; j <= k; ++j) {
          const double t = double(j) / (k + 1);
          m.corner_uv.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
          m.corner_is_face_corner.push_back(j == 0);
          m.face_vertices.push_back(Index(m.face_vertices.size()));
          m.positions.insert(m.positions.end(), {m.corner_uv.back()[0], m.corner_uv.back()[1], 0.0});
        }
      }
      m.face_offsets.push_back(Index(m.face_vertices.size()));
      m.face_level = {0};
      m.base_face = {0};
      const AdaptiveMesh polygon = m;
      tessellate_transitions(m);
      CHECK(m.positions == polygon.positions);
      std::map<std::pair<Index, Index>, int> directed;
      double total = 0, smallest = 1;
      int bad_size = 0;
      for (size_t f = 0; f < face_count(m); ++f) {
        const Index first = m.face_offsets[f], size = m.face_offsets[f + 1] - first;
        bad_size += size != 3 && size != 4;
        for (Index k = 0; k < size; ++k)
          ++directed[{m.face_vertices[size_t(first + k)], m.face_vertices[size_t(first + (k + 1) % size)]}];
        const double a = uv_area(m, f);
        CHECK(std::abs(area(m, f) - a) < 1e-15);  // the corners' (u, v) follow their vertices
        smallest = std::min(smallest, a), total += a;
      }
      CHECK(bad_size == 0);
      CHECK(smallest > 1e-3);
      CHECK(std::abs(total - uv_area(polygon, 0)) < 1e-15);
      const Index N = Index(polygon.face_vertices.size());
      int wrong = 0;
      for (const auto& [edge, count] : directed) {
        const bool side = edge.second == (edge.first + 1) % N;
        wrong += count != 1 || (!side && !directed.count({edge.second, edge.first}));
      }
      for (Index v = 0; v < N; ++v) wrong += !directed.count({v, (v + 1) % N});
      CHECK(wrong == 0);
    }
  }
}
