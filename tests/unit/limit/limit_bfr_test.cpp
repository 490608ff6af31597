// Limit evaluation at (face, u, v) against OpenSubdiv's Bfr: Catmull-Clark and Loop.
#include <doctest/doctest.h>

#include "unit/limit/bfr_surface.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

#include <cmath>
#include <algorithm>
#include <random>

#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

using subdiv_test::osd_mesh;

namespace {

Level tagged_level(const test::Mesh& m, const std::vector<subdiv_test::OsdCrease>& creases) {
  Level base = m.level();
  if (!creases.empty()) {
    base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
    for (const auto& k : creases) base.edge_sharpness[size_t(find_edge(base, k.v0, k.v1))] = k.sharpness;
  }
  return base;
}

// Bumps the z of every vertex so that no symmetry hides an error.
test::Mesh bumped(test::Mesh m) {
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[size_t(3 * v + 2)] += 0.1 * std::sin(1.7 * v + 0.3);
  return m;
}

double distance(const std::vector<double>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

struct Worst {
  double position = 0, derivative = 0;
};

Worst compare_random(const char* scheme_name, const test::Mesh& m, const std::vector<subdiv_test::OsdCrease>& creases,
                     subdiv_test::OsdScheme osd_scheme, int approx, int samples, bool triangles,
                     BoundaryInterpolation boundary = BoundaryInterpolation::EdgesAndCorners,
                     CreaseMethod method = CreaseMethod::Uniform) {
  const auto scheme = load_scheme(scheme_name);
  LimitSurfaceOptions lo;
  lo.features.boundary = boundary;
  lo.features.crease_method = method;
  const LimitSurface surface(scheme, tagged_level(m, creases), lo);
  subdiv_test::OsdOptions oo;
  oo.scheme = osd_scheme;
  oo.boundary = boundary == BoundaryInterpolation::EdgesOnly ? subdiv_test::OsdBoundary::EdgesOnly
                                                             : subdiv_test::OsdBoundary::EdgesAndCorners;
  oo.creasing = method == CreaseMethod::Chaikin ? subdiv_test::OsdCreasing::Chaikin : subdiv_test::OsdCreasing::Uniform;
  const subdiv_test::BfrLimit bfr(osd_mesh(m, creases), oo, approx, approx);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Worst w;
  const Index faces = Index(m.offsets.size()) - 1;
  for (int i = 0; i < samples; ++i) {
    const Index f = Index(rng() % unsigned(faces));
    double u = unit(rng), v = unit(rng);
    if (triangles && u + v > 1) u = 1 - u, v = 1 - v;
    const LimitSample ours = surface.evaluate(f, u, v, m.positions, 3);
    const auto ref = bfr.evaluate(f, u, v);
    w.position = std::max(w.position, distance(ours.position, ref.p));
    REQUIRE(ours.has_derivatives);
    w.derivative = std::max(w.derivative, std::max(distance(ours.du, ref.du), distance(ours.dv, ref.dv)));
  }
  return w;
}

}  // namespace

TEST_CASE("Catmull-Clark on a regular grid with boundaries and a sharp crease: Bfr's exact patches to 1e-12") {
  const test::Mesh m = bumped(test::grid(5, 4));
  const Worst w = compare_random("catmull-clark", m, {{7, 8, 10.f}, {8, 9, 10.f}}, subdiv_test::OsdScheme::CatmullClark, 10,
                                 60, false);
  CHECK(w.position < 1e-12);
  CHECK(w.derivative < 1e-11);
}

#endif

#ifdef SUBDIV_HAVE_OPENSUBDIV

TEST_CASE("Loop on a regular triangle grid with boundaries and a sharp crease: Bfr's exact patches to 1e-12") {
  const test::Mesh m = bumped(test::grid(5, 4, true));
  const Worst w = compare_random("loop", m, {{7, 8, 10.f}, {8, 9, 10.f}}, subdiv_test::OsdScheme::Loop, 10, 60, true);
  CHECK(w.position < 1e-12);
  CHECK(w.derivative < 1e-11);
}

TEST_CASE("Semi-sharp creases (uniform and Chaikin decay) and both boundary modes: Bfr's exact answers to 1e-12") {
  // Semi-sharp creases become smooth after finitely many levels; away from irregular
  // vertices Bfr is exact with its sharp approximation level at the maximum.
  const std::vector<subdiv_test::OsdCrease> semi{{7, 8, 1.5f}, {8, 9, 2.0f}, {13, 14, 0.5f}};
  for (CreaseMethod method : {CreaseMethod::Uniform, CreaseMethod::Chaikin})
    for (BoundaryInterpolation boundary : {BoundaryInterpolation::EdgesAndCorners, BoundaryInterpolation::EdgesOnly}) {
      CAPTURE(int(method));
      CAPTURE(int(boundary));
      const Worst cc = compare_random("catmull-clark", bumped(test::grid(5, 4)), semi,
                                      subdiv_test::OsdScheme::CatmullClark, 10, 40, false, boundary, method);
      CHECK(cc.position < 1e-12);
      CHECK(cc.derivative < 1e-11);
      const Worst loop = compare_random("loop", bumped(test::grid(5, 4, true)), semi, subdiv_test::OsdScheme::Loop, 10,
                                        40, true, boundary, method);
      CHECK(loop.position < 1e-12);
      CHECK(loop.derivative < 1e-11);
    }
}

TEST_CASE("Catmull-Clark and Loop near extraordinary vertices: Bfr approaches ours as its approximation level rises") {
  struct Case {
    const char* scheme;
    subdiv_test::OsdScheme osd;
    test::Mesh mesh;
  };
  for (const Case& c : {Case{"catmull-clark", subdiv_test::OsdScheme::CatmullClark, test::cube()},
                        Case{"loop", subdiv_test::OsdScheme::Loop, limit_test::octahedron()}}) {
    CAPTURE(std::string(c.scheme));
    const auto scheme = load_scheme(c.scheme);
    const test::Mesh m = bumped(c.mesh);
    const LimitSurface surface(scheme, m.level());
    double previous = 1e300;
    for (int level : {1, 3, 5, 7}) {
      subdiv_test::OsdOptions oo;
      oo.scheme = c.osd;
      const subdiv_test::BfrLimit bfr(osd_mesh(m), oo, level, 10);
      double worst = 0, worst_derivative = 0;
      // Points next to corner 0 of face 0 (an extraordinary vertex on both meshes).
      for (double t : {0.01, 0.03, 0.1}) {
        const LimitSample ours = surface.evaluate(0, t, 0.7 * t, m.positions, 3);
        const auto ref = bfr.evaluate(0, t, 0.7 * t);
        worst = std::max(worst, distance(ours.position, ref.p));
        worst_derivative = std::max(worst_derivative, std::max(distance(ours.du, ref.du), distance(ours.dv, ref.dv)));
      }
      MESSAGE(std::string(c.scheme), ": Bfr ApproxLevelSmooth ", level, ", largest distance ", worst,
              ", of derivatives ", worst_derivative);
      CHECK(worst < previous);
      previous = worst;
      if (level == 7) CHECK(worst_derivative < 1e-9);
    }
    CHECK(previous < 1e-6);
  }
}

TEST_CASE("Catmull-Clark on n-gons: Bfr's QUAD_SUBFACES parameterisation, exact away from the n-gon's centre") {
  // A pentagon and a triangle among quads; points in the sub-faces of the n-gons.
  test::Mesh m;
  m.positions.reserve(3 * 17);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) m.positions.insert(m.positions.end(), {double(i), double(j), 0.1 * std::sin(1.3 * i + 2.1 * j)});
  m.positions.insert(m.positions.end(), {1.5, 1.5, 0.3});  // 16: splits the middle quad into a pentagon and a triangle
  m.vertex_count = 17;
  auto id = [](int i, int j) { return Index(j * 4 + i); };
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (!(i == 1 && j == 1)) m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  m.add_face({id(1, 1), id(2, 1), id(2, 2), 16, id(1, 2)});
  m.add_face({id(2, 2), id(1, 2), 16});
  const auto scheme = load_scheme("catmull-clark");
  const LimitSurface surface(scheme, m.level());
  subdiv_test::OsdOptions oo;
  const subdiv_test::BfrLimit exact(osd_mesh(m), oo, 10, 10);
  const Index pentagon = 8, triangle = 9;
  // Bfr's sub-face tiles: pentagon 3 columns, triangle 2; (u, v) within the tile's first half.
  struct At {
    Index face;
    double u, v;
  };
  const std::vector<At> points{{pentagon, 0.1, 0.2}, {pentagon, 1.3, 0.05}, {pentagon, 0.2, 1.1},
                               {pentagon, 2.05, 0.3}, {triangle, 1.2, 0.1},  {triangle, 0.4, 1.05}};
  for (const At& p : points) {
    const LimitSample ours = surface.evaluate(p.face, p.u, p.v, m.positions, 3);
    const auto ref = exact.evaluate(p.face, p.u, p.v);
    CHECK(distance(ours.position, ref.p) < 1e-6);
    CHECK(distance(ours.du, ref.du) < 1e-5);
  }
}

#endif

#ifdef SUBDIV_HAVE_OPENSUBDIV

TEST_CASE("Faces next to a hole: Bfr's exact answers to 1e-12; the hole itself is refused") {
  const test::Mesh m = bumped(test::grid(5, 4));
  const Index hole = 7;
  Level base = m.level();
  base.face_hole.assign(size_t(base.face_count()), 0);
  base.face_hole[size_t(hole)] = 1;
  const LimitSurface surface(load_scheme("catmull-clark"), base);
  subdiv_test::OsdMesh om = osd_mesh(m);
  om.holes = {hole};
  const subdiv_test::BfrLimit bfr(om, {}, 10, 10);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0;
  for (Index f : {Index(1), Index(2), Index(6), Index(8), Index(12)})
    for (int i = 0; i < 6; ++i) {
      const double u = unit(rng), v = unit(rng);
      const LimitSample ours = surface.evaluate(f, u, v, m.positions, 3);
      const auto ref = bfr.evaluate(f, u, v);
      worst = std::max({worst, distance(ours.position, ref.p), distance(ours.du, ref.du), distance(ours.dv, ref.dv)});
    }
  CHECK(worst < 1e-11);
  CHECK(surface.check(hole, 0.5, 0.5).find("hole") != std::string::npos);
}

#endif

#ifdef SUBDIV_HAVE_OPENSUBDIV

TEST_CASE("Regular regions take the closed-form bicubic patch at once: a torus against Bfr to 1e-12") {
  test::Mesh m = test::torus(8, 6);
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[size_t(3 * v + 2)] += 0.05 * std::sin(2.3 * v);
  const LimitSurface surface(load_scheme("catmull-clark"), m.level());
  const subdiv_test::BfrLimit bfr(osd_mesh(m), {}, 10, 10);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0;
  int most_steps = 0;
  for (int i = 0; i < 40; ++i) {
    const Index f = Index(rng() % 48u);
    const double u = unit(rng), v = unit(rng);
    const LimitSample ours = surface.evaluate(f, u, v, m.positions, 3);
    const auto ref = bfr.evaluate(f, u, v);
    worst = std::max({worst, distance(ours.position, ref.p), distance(ours.du, ref.du), distance(ours.dv, ref.dv)});
    most_steps = std::max(most_steps, ours.steps);
  }
  CHECK(worst < 1e-12);
  CHECK(most_steps == 0);  // every face of a regular torus is a bicubic B-spline patch
}

#endif

#ifdef SUBDIV_HAVE_OPENSUBDIV

TEST_CASE("Loop's regular triangles are found to be quartic patches: a triangulated torus against Bfr to 1e-12") {
  test::Mesh m = test::torus(8, 6, true);
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[size_t(3 * v + 2)] += 0.05 * std::sin(2.3 * v);
  const LimitSurface surface(load_scheme("loop"), m.level());
  subdiv_test::OsdOptions oo;
  oo.scheme = subdiv_test::OsdScheme::Loop;
  const subdiv_test::BfrLimit bfr(osd_mesh(m), oo, 10, 10);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0;
  int most_steps = 0;
  for (int i = 0; i < 40; ++i) {
    const Index f = Index(rng() % 96u);
    double u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const LimitSample ours = surface.evaluate(f, u, v, m.positions, 3);
    const auto ref = bfr.evaluate(f, u, v);
    worst = std::max({worst, distance(ours.position, ref.p), distance(ours.du, ref.du), distance(ours.dv, ref.dv)});
    most_steps = std::max(most_steps, ours.steps);
  }
  CHECK(worst < 1e-12);
  // A base face's own neighbourhood node leads to the regular node after one step, whose
  // patch is the quartic: at most one step per point.
  CHECK(most_steps <= 1);
}

#endif
