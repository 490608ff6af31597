// Limit evaluation at (face, u, v) against OpenSubdiv's Bfr: Catmull-Clark and Loop.
#include <doctest/doctest.h>

#include "unit/limit/bfr_surface.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

#include <cmath>
#include <random>

#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

subdiv_test::OsdMesh osd_mesh(const test::Mesh& m, std::vector<subdiv_test::OsdCrease> creases = {}) {
  subdiv_test::OsdMesh om;
  om.vertex_count = m.vertex_count;
  om.face_offsets.assign(m.offsets.begin(), m.offsets.end());
  om.face_vertices.assign(m.corners.begin(), m.corners.end());
  om.xyz = m.positions;
  om.creases = std::move(creases);
  return om;
}

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
                     subdiv_test::OsdScheme osd_scheme, int approx, int samples, bool triangles) {
  const auto scheme = load_scheme(scheme_name);
  const LimitSurface surface(scheme, tagged_level(m, creases));
  subdiv_test::OsdOptions oo;
  oo.scheme = osd_scheme;
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
