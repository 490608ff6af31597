// Feature-adaptive refinement: watertight (every edge of a closed mesh in exactly two faces,
// Euler characteristic kept), fewer faces than uniform refinement, refinement only around
// what is irregular, and with `limit` the vertices on the limit surface.
#include <doctest/doctest.h>

#include <cmath>

#include "framework/limit/adaptive_refine.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

AdaptiveMesh adapt(const Scheme& scheme, const Level& base, std::span<const double> points, int levels,
                   const LimitSurface* limit = nullptr) {
  AdaptiveOptions o;
  o.levels = levels;
  o.limit = limit != nullptr;
  o.surface = limit;
  return refine_adaptive(scheme, base, points, o);
}

Level level_of(const AdaptiveMesh& m) {
  return build_level(Index(m.positions.size() / 3), m.face_offsets, m.face_vertices);
}

void check_closed_and_watertight(const AdaptiveMesh& m, int euler) {
  const Level L = level_of(m);
  int wrong = 0;
  for (Index e = 0; e < L.edge_count(); ++e) wrong += L.edge_face_count(e) != 2;
  CHECK(wrong == 0);  // no boundary edge, no T-junction (a T leaves an edge with one face)
  CHECK(L.manifold());
  CHECK(L.vertex_count - L.edge_count() + L.face_count() == euler);
}

}  // namespace

TEST_CASE("Adaptive Catmull-Clark on a cube: closed, watertight, refined only at the corners, fewer faces") {
  const test::Mesh cube = test::cube();
  const auto scheme = load_scheme("catmull-clark");
  for (int levels : {1, 3, 5}) {
    CAPTURE(levels);
    const AdaptiveMesh m = adapt(*scheme, cube.level(), cube.positions, levels);
    check_closed_and_watertight(m, 2);
    CHECK(m.uniform_faces == 6 * (1 << (2 * levels)));
    const Index faces = Index(m.face_offsets.size()) - 1;
    // Every face touches a valence-3 corner at level 0; from level 1 on, only the 3 faces
    // around each of the 8 corners are refined further, and each refined face leaves 3 of
    // its 4 children coarse: 8 * 3 * 4 faces at the last level, 8 * 3 * 3 at each other.
    CHECK(faces == (levels == 1 ? 24 : 96 + 72 * (levels - 2)));
    CHECK(faces <= m.uniform_faces);
    if (levels > 1) CHECK(faces < m.uniform_faces);
    MESSAGE("cube, level ", levels, ": ", faces, " faces against ", m.uniform_faces, " uniform");
  }
}

TEST_CASE("Adaptive refinement of a regular torus refines nothing; Loop on an octahedron is watertight") {
  const test::Mesh torus = test::torus(8, 6);
  const AdaptiveMesh t = adapt(*load_scheme("catmull-clark"), torus.level(), torus.positions, 3);
  CHECK(Index(t.face_offsets.size()) - 1 == 48);
  check_closed_and_watertight(t, 0);
  const test::Mesh octa = limit_test::octahedron();
  const AdaptiveMesh o = adapt(*load_scheme("loop"), octa.level(), octa.positions, 4);
  check_closed_and_watertight(o, 2);
  CHECK(Index(o.face_offsets.size()) - 1 < o.uniform_faces);
}

TEST_CASE("Adaptive refinement with limit positions: the base vertices are the limit surface's corners") {
  const test::Mesh cube = test::cube();
  const auto scheme = load_scheme("catmull-clark");
  const LimitSurface surface(scheme, cube.level());
  const AdaptiveMesh m = adapt(*scheme, cube.level(), cube.positions, 3, &surface);
  check_closed_and_watertight(m, 2);
  // Every corner of every base face, evaluated on the limit surface, is a vertex of the mesh.
  const Level base = cube.level();
  const double corner_uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (Index f = 0; f < base.face_count(); ++f)
    for (int k = 0; k < 4; ++k) {
      const LimitSample s = surface.evaluate(f, corner_uv[k][0], corner_uv[k][1], cube.positions, 3, 0);
      double nearest = 1e300;
      for (size_t v = 0; v < m.positions.size() / 3; ++v) {
        double d = 0;
        for (size_t c = 0; c < 3; ++c) d += std::pow(m.positions[3 * v + c] - s.position[c], 2);
        nearest = std::min(nearest, std::sqrt(d));
      }
      CHECK(nearest < 1e-12);
    }
}

TEST_CASE("Adaptive refinement of an open grid with a crease: faces along the crease refined, boundary kept") {
  test::Mesh grid = test::grid(6, 5);
  Level base = grid.level();
  base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
  base.edge_sharpness[size_t(find_edge(base, 8, 9))] = 10.f;
  base.edge_sharpness[size_t(find_edge(base, 9, 10))] = 10.f;
  const AdaptiveMesh m = adapt(*load_scheme("catmull-clark"), base, grid.positions, 3);
  const Level L = level_of(m);
  int bad = 0, boundary = 0;
  for (Index e = 0; e < L.edge_count(); ++e) {
    bad += L.edge_face_count(e) < 1 || L.edge_face_count(e) > 2;
    boundary += L.edge_face_count(e) == 1;
  }
  CHECK(bad == 0);
  // The grid's outer boundary (22 edges) is split only where the faces along it touch the
  // crease's end vertices or its boundary corners: no interior T-junction adds boundary edges,
  // so the mesh keeps one boundary loop: V - E + F = 1 (a disc).
  CHECK(L.vertex_count - L.edge_count() + L.face_count() == 1);
  CHECK(boundary >= 22);
  CHECK(Index(m.face_offsets.size()) - 1 < m.uniform_faces);
}

TEST_CASE("Boundary interpolation none: the faces along the boundary are holes, as in uniform refinement") {
  // OpenSubdiv's VTX_BOUNDARY_NONE: a face with a boundary vertex has no limit surface; our
  // uniform refinement leaves it out (engine/refiner.cpp), so adaptive refinement must too.
  const test::Mesh grid = test::grid(6, 5);
  const Level base = grid.level();
  const auto scheme = load_scheme("catmull-clark");
  LimitSurfaceOptions lo;
  lo.features.boundary = BoundaryInterpolation::None;
  const LimitSurface surface(scheme, base, lo);
  for (bool limit : {false, true}) {
    CAPTURE(limit);
    AdaptiveOptions o;
    o.levels = 3;
    o.features.boundary = BoundaryInterpolation::None;
    o.limit = limit;
    o.surface = &surface;
    const AdaptiveMesh m = refine_adaptive(*scheme, base, grid.positions, o);
    CHECK(m.uniform_faces == (6 - 2) * (5 - 2) * 64);  // the 12 faces off the boundary
    const Index faces = Index(m.face_offsets.size()) - 1;
    CHECK(faces > 0);
    for (Index f = 0; f < faces; ++f) {
      bool on_boundary = false;
      for (Index v : base.face(m.base_face[size_t(f)])) on_boundary = on_boundary || base.on_boundary(v);
      CHECK_FALSE(on_boundary);
    }
    if (!limit) continue;
    // Every corner on the limit surface at its (base face, u, v).
    for (Index f = 0; f < faces; ++f)
      for (Index c = m.face_offsets[size_t(f)]; c < m.face_offsets[size_t(f) + 1]; ++c) {
        const auto uv = m.corner_uv[size_t(c)];
        const LimitSample s = surface.evaluate(m.base_face[size_t(f)], uv[0], uv[1], grid.positions, 3, 0);
        const Index v = m.face_vertices[size_t(c)];
        for (int k = 0; k < 3; ++k) CHECK(m.positions[size_t(3 * v + k)] == doctest::Approx(s.position[size_t(k)]).epsilon(1e-12));
      }
  }
}

TEST_CASE("Point arrays on adaptive meshes are placed like the positions, with and without the limit") {
  // The refinement and the limit are linear and reproduce affine functions (each row sums to
  // one), so an array that is an affine image of the positions stays that image of the
  // output positions — here (2x - z + 1, y + 0.5, 3z) and the position itself.
  const test::Mesh m = test::cube();
  const auto scheme = load_scheme("catmull-clark");
  const Level base = m.level();
  auto image = [](std::span<const double> p) {
    std::vector<double> d;
    for (size_t v = 0; v < p.size() / 3; ++v) {
      const double x = p[3 * v], y = p[3 * v + 1], z = p[3 * v + 2];
      d.insert(d.end(), {2 * x - z + 1, y + 0.5, 3 * z, x, y, z});
    }
    return d;
  };
  const LimitSurface surface(scheme, base);
  for (bool limit : {false, true}) {
    CAPTURE(limit);
    AdaptiveOptions o;
    o.levels = 3;
    o.limit = limit;
    o.surface = &surface;
    const std::vector<double> data = image(m.positions);
    const AdaptiveMesh a = refine_adaptive(*scheme, base, m.positions, o, data, 6);
    REQUIRE(a.data_channels == 6);
    REQUIRE(a.data.size() == a.positions.size() * 2);
    const std::vector<double> expected = image(a.positions);
    double worst = 0;
    for (size_t i = 0; i < expected.size(); ++i) worst = std::max(worst, std::fabs(expected[i] - a.data[i]));
    CHECK(worst < 1e-14);
  }
  AdaptiveOptions o;
  o.levels = 1;
  CHECK_THROWS_AS(refine_adaptive(*scheme, base, m.positions, o, std::vector<double>(5, 0.0), 1), Error);
}

TEST_CASE("Weight tables kept between adaptive refinements give the same meshes, bit for bit") {
  // A kept table is made for more valences and face sizes than the next mesh has (the
  // pyramid's triangles and valence-4 apex first): its values at the smaller ones must be
  // those a fresh call compiles.
  const auto scheme = load_scheme("catmull-clark");
  AdaptiveTables tables(*scheme);
  const test::Mesh meshes[] = {test::pyramid(), test::cube(), test::torus(8, 6), test::pyramid()};
  for (const test::Mesh& mesh : meshes) {
    AdaptiveOptions o;
    o.levels = 4;
    const AdaptiveMesh fresh = refine_adaptive(*scheme, mesh.level(), mesh.positions, o);
    o.tables = &tables;
    const AdaptiveMesh kept = refine_adaptive(*scheme, mesh.level(), mesh.positions, o);
    CHECK(kept.face_vertices == fresh.face_vertices);
    CHECK(kept.positions == fresh.positions);  // exactly
  }
  const auto loop = load_scheme("loop");
  AdaptiveOptions o;
  o.levels = 2;
  o.tables = &tables;
  const test::Mesh octahedron = test::octahedron();
  CHECK_THROWS_WITH_AS(refine_adaptive(*loop, octahedron.level(), octahedron.positions, o),
                       doctest::Contains("weight tables kept are scheme"), Error);
}
