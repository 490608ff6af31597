// Derivatives at boundary vertices (limit/corner_limit.cpp, regular_vertex): present where the
// parameterisation is regular there, absent at extraordinary boundary vertices.
//
// A smooth boundary vertex of Loop with two triangles (a regular one has three) is
// extraordinary: its local subdivision matrix has eigenvalue 1/2 along the boundary and 3/8
// across it, so the limit's d/du and d/dv there are parallel and no face's parameterisation
// is regular; derivatives used to be reported there, from the unfolded grid's coordinates, and
// were wrong (0.78 instead of the boundary curve's 0.5 in x on the grid below). A corner (the
// vertex tagged infinitely sharp) keeps its two boundary curves apart and the plane in the
// unfolded coordinates, so its derivatives exist; they are checked against one-sided
// differences of the evaluated limit, whose error shrinks like (3/4)^k at h = 2^-k (the
// ratio of the eigenvalues 3/8 and 1/2).
#include <doctest/doctest.h>

#include <cmath>

#include "framework/features/sharpness.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

// A 3 x 2 grid of quads, each split into two triangles along the diagonal from its first
// corner: the grid's corner vertex 0 has two triangles; bumped so nothing cancels.
test::Mesh triangle_grid() {
  test::Mesh m;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) m.add_vertex(i + 0.1 * j, j, 0.2 * std::sin(1.3 * i + 0.7 * j));
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const Index a = 4 * j + i, b = a + 1, c = a + 5, d = a + 4;
      m.add_face({a, b, c});
      m.add_face({a, c, d});
    }
  return m;
}

double distance(const std::vector<double>& a, const std::vector<double>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// |one-sided difference along direction (du, dv) at step 2^-k - the reported derivative|.
double difference_error(const LimitSurface& s, const test::Mesh& m, int k, bool along_u) {
  const double h = std::ldexp(1.0, -k);
  const LimitSample at = s.evaluate(0, 0, 0, m.positions, 3);
  const LimitSample near = s.evaluate(0, along_u ? h : 0, along_u ? 0 : h, m.positions, 3);
  std::vector<double> slope(3);
  for (size_t c = 0; c < 3; ++c) slope[c] = (near.position[c] - at.position[c]) / h;
  return distance(slope, along_u ? at.du : at.dv);
}

}  // namespace

TEST_CASE("Loop: no derivatives at a smooth boundary vertex with two triangles (extraordinary)") {
  const test::Mesh m = triangle_grid();
  for (BoundaryInterpolation mode : {BoundaryInterpolation::EdgesAndCorners, BoundaryInterpolation::EdgesOnly}) {
    LimitSurfaceOptions o;
    o.features.boundary = mode;
    const LimitSurface s(load_scheme("loop"), m.level(), o);
    CHECK_FALSE(s.evaluate(0, 0, 0, m.positions, 3).has_derivatives);
    CHECK(s.evaluate(0, 0.25, 0.25, m.positions, 3).has_derivatives);  // beside it they exist
  }
}

TEST_CASE("Loop: at a corner with two triangles the derivatives are the limit's one-sided slopes") {
  const test::Mesh m = triangle_grid();
  Level base = m.level();
  base.vertex_sharpness.assign(size_t(base.vertex_count), 0.f);
  base.vertex_sharpness[0] = kInfinitelySharp;
  const LimitSurface s(load_scheme("loop"), base);
  REQUIRE(s.evaluate(0, 0, 0, m.positions, 3).has_derivatives);
  // Along the boundary the limit is the corner's cubic B-spline curve: the slope converges like h.
  CHECK(difference_error(s, m, 40, true) < 1e-9);
  // Across, the next eigenvalue 3/8 makes the slope converge like (3/4)^k.
  const double e30 = difference_error(s, m, 30, false), e40 = difference_error(s, m, 40, false);
  CHECK(e40 < 2e-3);
  CHECK(e40 < 0.1 * e30);  // (3/4)^10 = 0.056
}

TEST_CASE("Catmull-Clark: a one-face boundary vertex has derivatives as a corner, none as a smooth vertex") {
  // An L of three quads: its outer corners have one face; with EdgesAndCorners they are
  // corners (the bicubic corner patch), with EdgesOnly extraordinary (eigenvalues 1/2 and 1/4).
  test::Mesh m;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) m.add_vertex(i, j, 0.1 * std::sin(1.3 * i + 0.7 * j));
  m.add_face({0, 1, 4, 3});
  m.add_face({1, 2, 5, 4});
  m.add_face({3, 4, 7, 6});
  LimitSurfaceOptions o;
  o.features.boundary = BoundaryInterpolation::EdgesAndCorners;
  const LimitSurface corners(load_scheme("catmull-clark"), m.level(), o);
  REQUIRE(corners.evaluate(0, 0, 0, m.positions, 3).has_derivatives);
  CHECK(difference_error(corners, m, 30, true) < 1e-7);
  CHECK(difference_error(corners, m, 30, false) < 1e-7);
  o.features.boundary = BoundaryInterpolation::EdgesOnly;
  const LimitSurface smooth(load_scheme("catmull-clark"), m.level(), o);
  CHECK_FALSE(smooth.evaluate(0, 0, 0, m.positions, 3).has_derivatives);
}
