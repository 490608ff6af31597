// Modified butterfly (Zorin, Schröder & Sweldens 1996, "Interpolating subdivision for
// meshes with arbitrary topology") along boundaries and creases: the new point of a
// boundary or crease edge is the 4-point rule of Dyn, Levin & Gregory 1987 along the
// boundary (crease) polygon, (-1/16, 9/16, 9/16, -1/16), a crease being a boundary to each
// side (Zorin's convention); old vertices stay; planar data stays planar next to boundaries.
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "unit/refine/modified_butterfly_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// An annulus of nu x (nv + 1) vertices, triangulated, irregular in shape: two closed
// boundary loops (j = 0 and j = nv), every boundary vertex with 3 faces (no corners).
// `plane`: all points on the plane z = 0.3 x - 0.2 y + 1.
Mesh annulus(int nu, int nv, bool plane) {
  Mesh m;
  const double pi = std::acos(-1.0);
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * pi * (i + 0.2 * std::sin(1.3 * i + j)) / nu, r = 1 + 0.5 * j + 0.07 * std::cos(2.1 * i);
      const double x = r * std::cos(u), y = r * std::sin(u);
      m.add_vertex(x, y, plane ? 0.3 * x - 0.2 * y + 1 : 0.2 * std::sin(3 * u) + 0.05 * j * j);
    }
  auto id = [&](int i, int j) { return Index(j * nu + (i + nu) % nu); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// Dyn, Levin & Gregory 1987 with w = 1/16: the new point between p1 and p2.
Point four_point(const Point& p0, const Point& p1, const Point& p2, const Point& p3) {
  Point q;
  for (int c = 0; c < 3; ++c) q[c] = -p0[c] / 16 + 9 * p1[c] / 16 + 9 * p2[c] / 16 - p3[c] / 16;
  return q;
}

// Checks every edge (id(i, j), id(i + 1, j)) of the closed polygon j against the 4-point
// rule on the polygon's points i - 1, i, i + 1, i + 2.
void check_polygon_follows_four_point(const Level& base, const std::vector<double>& positions, int nu, int j,
                                      const OneLevel& r) {
  auto id = [&](int i) { return Index(j * nu + (i + nu) % nu); };
  for (int i = 0; i < nu; ++i) {
    CAPTURE(i);
    const Index e = find_edge(base, id(i), id(i + 1));
    const Point expected = four_point(at(positions, id(i - 1)), at(positions, id(i)), at(positions, id(i + 1)),
                                      at(positions, id(i + 2)));
    const Point got = at(r.positions, edge_child(r.h.origins[0], e));
    for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(expected[c]).epsilon(1e-13));
  }
}

}  // namespace

TEST_CASE("modified butterfly: boundary edges follow the 4-point rule (-1/16, 9/16, 9/16, -1/16)") {
  const int nu = 9, nv = 3;
  const Mesh m = annulus(nu, nv, false);
  const Level base = m.level();
  const OneLevel r = refine_level(base, m.positions);
  check_polygon_follows_four_point(base, m.positions, nu, 0, r);
  check_polygon_follows_four_point(base, m.positions, nu, nv, r);
}

TEST_CASE("modified butterfly: crease edges follow the 4-point rule along the crease polygon") {
  const int nu = 8, nv = 6;
  const Mesh m = torus(nu, nv, true);
  Level base = m.level();
  base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
  for (int i = 0; i < nu; ++i) base.edge_sharpness[size_t(find_edge(base, Index(i), Index((i + 1) % nu)))] = 10.f;
  const OneLevel r = refine_level(base, m.positions);
  check_polygon_follows_four_point(base, m.positions, nu, 0, r);
}

TEST_CASE("modified butterfly: old vertices stay, next to boundaries and creases too") {
  const Mesh m = annulus(9, 3, false);
  const OneLevel r = refine_level(m.level(), m.positions, 2);
  // Two levels: a vertex child of a vertex child is the base vertex.
  const ChildOrigins& o1 = r.h.origins[0];
  const ChildOrigins& o2 = r.h.origins[1];
  for (Index c = 0; c < Index(o2.kind.size()); ++c) {
    if (o2.kind[c] != OriginKind::Vertex || o1.kind[o2.parent[c]] != OriginKind::Vertex) continue;
    const Point want = at(m.positions, o1.parent[o2.parent[c]]), got = at(r.positions, c);
    for (int k = 0; k < 3; ++k) CHECK(got[k] == want[k]);
  }
}

TEST_CASE("modified butterfly: planar data next to boundaries stays planar (affine weights), levels 1-3") {
  const Mesh m = annulus(10, 3, true);
  for (int levels = 1; levels <= 3; ++levels) {
    const OneLevel r = refine_level(m.level(), m.positions, levels);
    double worst = 0;
    for (size_t v = 0; v < r.positions.size() / 3; ++v) {
      const Point p = at(r.positions, Index(v));
      worst = std::max(worst, std::abs(p[2] - (0.3 * p[0] - 0.2 * p[1] + 1)));
    }
    CHECK(worst < 1e-13);
  }
}
