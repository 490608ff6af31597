// Second derivatives of the limit surface: against OpenSubdiv's Bfr where it is exact
// (regular faces, boundaries, sharp and semi-sharp creases), against central differences of
// the first derivatives next to extraordinary vertices, and absent where the scheme is not C2.
#include <doctest/doctest.h>

#include "unit/limit/bfr_surface.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

test::Mesh bumped(test::Mesh m) {
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[size_t(3 * v + 2)] += 0.1 * std::sin(1.7 * v + 0.3);
  return m;
}

double distance3(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (size_t c = 0; c < 3; ++c) s += (a[c] - b[c]) * (a[c] - b[c]);
  return std::sqrt(s);
}

double norm3(const std::vector<double>& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

}  // namespace

#ifdef SUBDIV_HAVE_OPENSUBDIV

namespace {

struct Crease {
  Index a, b;
  float sharpness;
};

double distance3(const std::vector<double>& a, const std::array<double, 3>& b) {
  return distance3(a, std::vector<double>(b.begin(), b.end()));
}

struct Comparison {
  double worst = 0;           // from Bfr's position and second derivatives
  int inconsistent = 0;       // points where Bfr's second derivatives are not those of its first
  double worst_to_differences = 0;  // there: from central differences of Bfr's first derivatives
};

std::vector<double> vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

// Ours against Bfr (its approximation levels at their maximum) at random points of every face.
// Where Bfr's second derivatives disagree with central differences of its own first
// derivatives, those differences are the reference instead, and the points are counted.
Comparison compare(const char* scheme_name, const test::Mesh& m, const std::vector<Crease>& creases, bool triangles,
                   BoundaryInterpolation boundary, CreaseMethod method, int samples) {
  Level base = m.level();
  subdiv_test::OsdMesh om;
  om.vertex_count = m.vertex_count;
  om.face_offsets.assign(m.offsets.begin(), m.offsets.end());
  om.face_vertices.assign(m.corners.begin(), m.corners.end());
  om.xyz = m.positions;
  if (!creases.empty()) base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
  for (const Crease& k : creases) {
    base.edge_sharpness[size_t(find_edge(base, k.a, k.b))] = k.sharpness;
    om.creases.push_back({k.a, k.b, k.sharpness});
  }
  LimitSurfaceOptions lo;
  lo.features.boundary = boundary;
  lo.features.crease_method = method;
  const LimitSurface surface(load_scheme(scheme_name), base, lo);
  subdiv_test::OsdOptions oo;
  oo.scheme = triangles ? subdiv_test::OsdScheme::Loop : subdiv_test::OsdScheme::CatmullClark;
  oo.boundary = boundary == BoundaryInterpolation::EdgesOnly ? subdiv_test::OsdBoundary::EdgesOnly
                                                             : subdiv_test::OsdBoundary::EdgesAndCorners;
  oo.creasing = method == CreaseMethod::Chaikin ? subdiv_test::OsdCreasing::Chaikin : subdiv_test::OsdCreasing::Uniform;
  const subdiv_test::BfrLimit bfr(om, oo, 10, 10);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  Comparison out;
  const Index faces = Index(m.offsets.size()) - 1;
  const LimitSurface& S = surface;
  for (int i = 0; i < samples; ++i) {
    const Index f = Index(rng() % unsigned(faces));
    double u = unit(rng), v = unit(rng);
    if (triangles && u + v > 0.95) u = 0.95 - u, v = 0.95 - v;
    if (!S.check(f, u, v).empty()) continue;  // a hole (EdgesOnly makes the boundary faces holes)
    const LimitSample ours = S.evaluate(f, u, v, m.positions, 3, 2);
    const auto ref = bfr.evaluate(f, u, v);
    REQUIRE(ours.has_second_derivatives);
    out.worst = std::max({out.worst, distance3(ours.position, ref.p), distance3(ours.du, ref.du)});
    const double h = 1e-5;
    const auto up = bfr.evaluate(f, u + h, v), um = bfr.evaluate(f, u - h, v);
    const auto vp = bfr.evaluate(f, u, v + h), vm = bfr.evaluate(f, u, v - h);
    std::vector<double> duu(3), duv(3), dvv(3);
    for (size_t c = 0; c < 3; ++c) {
      duu[c] = (up.du[c] - um.du[c]) / (2 * h);
      duv[c] = (vp.du[c] - vm.du[c]) / (2 * h);
      dvv[c] = (vp.dv[c] - vm.dv[c]) / (2 * h);
    }
    const double consistent = std::max({distance3(duu, vec(ref.duu)), distance3(duv, vec(ref.duv)),
                                        distance3(dvv, vec(ref.dvv))});
    if (consistent < 1e-6) {
      out.worst = std::max({out.worst, distance3(ours.duu, ref.duu), distance3(ours.duv, ref.duv),
                            distance3(ours.dvv, ref.dvv)});
    } else {
      ++out.inconsistent;
      out.worst_to_differences = std::max({out.worst_to_differences, distance3(ours.duu, duu),
                                           distance3(ours.duv, duv), distance3(ours.dvv, dvv)});
    }
  }
  return out;
}

}  // namespace

TEST_CASE("Second derivatives on regular faces, boundaries and sharp creases: Bfr's exact patches to 1e-12") {
  const std::vector<Crease> sharp{{7, 8, 10.f}, {8, 9, 10.f}};
  for (BoundaryInterpolation boundary : {BoundaryInterpolation::EdgesAndCorners, BoundaryInterpolation::EdgesOnly}) {
    CAPTURE(int(boundary));
    const Comparison cc = compare("catmull-clark", bumped(test::grid(5, 4)), sharp, false, boundary,
                                  CreaseMethod::Uniform, 60);
    MESSAGE("catmull-clark: largest distance from Bfr ", cc.worst);
    CHECK(cc.worst < 1e-12);
    CHECK(cc.inconsistent == 0);
    const Comparison loop = compare("loop", bumped(test::grid(5, 4, true)), sharp, true, boundary,
                                    CreaseMethod::Uniform, 60);
    MESSAGE("loop: largest distance from Bfr ", loop.worst, "; ", loop.inconsistent,
            " points where Bfr's second derivatives are not the differences of its first, ours from those ",
            loop.worst_to_differences);
    CHECK(loop.worst < 1e-12);
    CHECK(loop.worst_to_differences < 1e-7);
  }
  const Comparison torus = compare("catmull-clark", bumped(test::torus(8, 6)), {}, false,
                                   BoundaryInterpolation::EdgesAndCorners, CreaseMethod::Uniform, 40);
  CHECK(torus.worst < 1e-12);
  const Comparison loop_torus = compare("loop", bumped(test::torus(8, 6, true)), {}, true,
                                        BoundaryInterpolation::EdgesAndCorners, CreaseMethod::Uniform, 40);
  CHECK(loop_torus.worst < 1e-12);
  CHECK(loop_torus.inconsistent == 0);
}

TEST_CASE("Second derivatives across semi-sharp creases (uniform and Chaikin decay): Bfr's exact answers to 1e-11") {
  const std::vector<Crease> semi{{7, 8, 1.5f}, {8, 9, 2.0f}, {13, 14, 0.5f}};
  for (CreaseMethod method : {CreaseMethod::Uniform, CreaseMethod::Chaikin}) {
    CAPTURE(int(method));
    const Comparison cc = compare("catmull-clark", bumped(test::grid(5, 4)), semi, false,
                                  BoundaryInterpolation::EdgesAndCorners, method, 40);
    CHECK(cc.worst < 1e-11);
    CHECK(cc.inconsistent == 0);
    const Comparison loop = compare("loop", bumped(test::grid(5, 4, true)), semi, true,
                                    BoundaryInterpolation::EdgesAndCorners, method, 40);
    CHECK(loop.worst < 1e-11);
    CHECK(loop.worst_to_differences < 1e-7);
  }
}

#endif

TEST_CASE("Next to extraordinary vertices the second derivatives are central differences of the first") {
  struct Case {
    const char* scheme;
    test::Mesh mesh;
  };
  for (const Case& c : {Case{"catmull-clark", test::cube()}, Case{"loop", limit_test::octahedron()}}) {
    CAPTURE(std::string(c.scheme));
    const test::Mesh m = bumped(c.mesh);
    const LimitSurface surface(load_scheme(c.scheme), m.level());
    // Corner 0 of face 0 is an extraordinary vertex on both meshes; points towards it.
    double worst = 0;
    for (double t : {0.3, 0.05, 0.01, 0.002}) {
      const double u = t, v = 0.6 * t, h = 1e-5 * t;
      const LimitSample s = surface.evaluate(0, u, v, m.positions, 3, 2);
      REQUIRE(s.has_second_derivatives);
      const auto first = [&](double a, double b) { return surface.evaluate(0, a, b, m.positions, 3, 1); };
      const LimitSample up = first(u + h, v), um = first(u - h, v), vp = first(u, v + h), vm = first(u, v - h);
      for (size_t k = 0; k < 3; ++k) {
        const double scale = norm3(s.duu) + norm3(s.duv) + norm3(s.dvv);
        const double duu = (up.du[k] - um.du[k]) / (2 * h), duv = (vp.du[k] - vm.du[k]) / (2 * h);
        const double dvu = (up.dv[k] - um.dv[k]) / (2 * h), dvv = (vp.dv[k] - vm.dv[k]) / (2 * h);
        worst = std::max({worst, std::fabs(duu - s.duu[k]) / scale, std::fabs(duv - s.duv[k]) / scale,
                          std::fabs(dvu - s.duv[k]) / scale, std::fabs(dvv - s.dvv[k]) / scale});
      }
    }
    MESSAGE(std::string(c.scheme), ": largest relative difference from central differences ", worst);
    CHECK(worst < 1e-6);
  }
}

TEST_CASE("Second derivatives are absent at an extraordinary vertex and for a scheme that is only C1") {
  const test::Mesh cube = bumped(test::cube());
  const LimitSurface cc(load_scheme("catmull-clark"), cube.level());
  const LimitSample at = cc.evaluate(0, 0, 0, cube.positions, 3, 2);
  CHECK_FALSE(at.has_derivatives);
  CHECK_FALSE(at.has_second_derivatives);
  // The butterfly scheme's limit is C1 and not C2 (Dyn, Levin & Gregory 1990; Zorin,
  // Schröder & Sweldens 1996): no polynomial patch covers any face.
  const test::Mesh octa = bumped(limit_test::octahedron());
  const LimitSurface butterfly(load_scheme("butterfly"), octa.level());
  const LimitSample b = butterfly.evaluate(0, 0.3, 0.2, octa.positions, 3, 2);
  CHECK(b.has_derivatives);
  CHECK_FALSE(b.has_second_derivatives);
  // Order 1 computes no second derivatives; an order above 2 is refused.
  CHECK_FALSE(cc.evaluate(0, 0.3, 0.2, cube.positions, 3, 1).has_second_derivatives);
  CHECK_THROWS_AS(cc.evaluate(0, 0.3, 0.2, cube.positions, 3, 3), subdiv::Error);
}

TEST_CASE("Second-derivative stencils applied to the control points give the evaluated second derivatives") {
  const test::Mesh cube = bumped(test::cube());
  const LimitSurface cc(load_scheme("catmull-clark"), cube.level());
  for (double t : {0.4, 0.01}) {
    const LimitSample s = cc.evaluate(2, t, 0.5 * t, cube.positions, 3, 2);
    const LimitStencil w = cc.stencil(2, t, 0.5 * t, 2);
    REQUIRE(w.has_second_derivatives);
    const std::vector<double>* weights[3] = {&w.duu, &w.duv, &w.dvv};
    const std::vector<double>* expected[3] = {&s.duu, &s.duv, &s.dvv};
    for (int d = 0; d < 3; ++d) {
      std::vector<double> applied(3, 0.0);
      for (size_t k = 0; k < w.vertices.size(); ++k)
        for (size_t c = 0; c < 3; ++c) applied[c] += (*weights[d])[k] * cube.positions[size_t(w.vertices[k]) * 3 + c];
      CHECK(distance3(applied, *expected[d]) < 1e-12 * (1 + norm3(*expected[d])));
    }
  }
}
