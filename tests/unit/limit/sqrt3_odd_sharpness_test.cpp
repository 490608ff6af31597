// Limit evaluation of √3 schemes where an edge's sharpness ends between the two steps of a
// pair (s mod 2 in (0, 1]: 0.5, 1, 2.5, 3): the split keeps the edge in the first step and
// flips it in the second, so the triangle kept beside it gets its face point at
// (4a + 4b + c)/9 of its base triangle, off the triadic lattice (Kobbelt 2000, section 5, for
// the kept edges). The first steps are then followed one at a time until the sharpness has
// decayed. Checked against the limit masks of the refined levels (the route of `subdiv
// refine --limit`) at every vertex two steps make, the (u, v) of the off-lattice points
// computed here from the centroid rule; the rate the refined points approach their limit;
// continuity across every edge; affine invariance; stencils; central differences.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/engine/refiner.h"
#include "framework/features/sharpness.h"
#include "framework/limit/limit_surface.h"
#include "framework/limit/sqrt3_limit.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/sanitizers.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"
#include "unit/limit/sqrt3_creased_meshes.h"
#include "unit/limit/sqrt3_points.h"

using namespace subdiv;

namespace {

using limit_test::distance;
using namespace limit_test::sqrt3;

// The (face, u, v) of a vertex of level 2 when the pair is not triadic: a vertex child and
// the face points of the triangles over a base edge are where where_two_steps_put says; the
// face point of a triangle (a, b, P) kept beside a sharp edge a-b of face f is the centroid
// of a, b and f's centroid: (4a + 4b + c)/9.
Where where_single_steps_put(const Level& L, const Hierarchy& h, Index v) {
  const ChildOrigins& o1 = h.origins[0];
  const Index p = h.origins[1].parent[size_t(v)];
  if (h.origins[1].kind[size_t(v)] == OriginKind::Face) {
    std::vector<Index> corners, faces;
    for (Index x : h.levels[1].face(p))
      (o1.kind[size_t(x)] == OriginKind::Vertex ? corners : faces).push_back(o1.parent[size_t(x)]);
    if (corners.size() == 2) {
      REQUIRE(faces.size() == 1);
      std::array<double, 3> bary{1.0 / 9, 1.0 / 9, 1.0 / 9};
      for (Index w : corners) bary[size_t(corner_of(L, faces[0], w))] = 4.0 / 9;
      return {faces[0], {bary[1], bary[2]}};
    }
  }
  return where_two_steps_put(L, h, v);
}

// The vertex of level `to` that vertex v of level `from` becomes (vertex children keep it).
Index descendant(const Hierarchy& h, int from, int to, Index v) {
  for (int l = from; l < to; ++l) {
    const ChildOrigins& o = h.origins[size_t(l)];
    Index found = kNone;
    for (Index y = 0; y < h.levels[size_t(l + 1)].vertex_count; ++y)
      if (o.kind[size_t(y)] == OriginKind::Vertex && o.parent[size_t(y)] == v) found = y;
    REQUIRE(found != kNone);
    v = found;
  }
  return v;
}

// Positions of every level of h.
std::vector<std::vector<double>> level_positions(const Hierarchy& h, const std::vector<double>& base) {
  std::vector<std::vector<double>> p{base};
  for (const auto& s : h.stencils) p.push_back(s.apply(p.back(), 3));
  return p;
}

}  // namespace

TEST_CASE("sqrt3, sharpness ending inside a pair: the limit at the vertices two steps make equals their limit masks") {
  // Sharpness 1 and 0.5 have decayed after two steps: level 2's limit masks are those of a
  // smooth mesh. Sharpness 2.5 and 3 keep the crease for a triadic pair first (the vertices
  // two steps make are on the lattice), then break the second pair: their limit is read from
  // the limit masks of level 4, where every crease has decayed.
  struct Case {
    Tagged t;
    int levels;
  };
  std::vector<Case> cases;
  cases.push_back({creased_torus(1.f), 2});
  cases.push_back({creased_torus(0.5f), 2});
  cases.push_back({creased_torus(2.5f), 4});
  cases.push_back({creased_torus(3.f), 4});
  cases.push_back({octahedron_with_equator(1.f), 2});
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(std::string(name));
    int which = 0;
    for (const Case& c : cases) {
      const int mesh = which++;
      CAPTURE(mesh);
      const auto scheme = load_scheme(name);
      const LimitSurface s(scheme, c.t.level);
      RefineOptions ro;
      ro.levels = c.levels;
      const Hierarchy h = refine(*scheme, c.t.level, ro);
      const auto p = level_positions(h, c.t.mesh.positions);
      LimitOptions lo;
      lo.first_step = c.levels;
      const LimitResult masks = limit_positions(*scheme, h.levels[size_t(c.levels)], p[size_t(c.levels)], lo);
      CHECK(masks.approximate == 0);
      double worst = 0;
      int off_lattice = 0;
      for (Index v = 0; v < h.levels[2].vertex_count; ++v) {
        const Where x = c.levels == 2 ? where_single_steps_put(c.t.level, h, v) : where_two_steps_put(c.t.level, h, v);
        off_lattice += std::fabs(3 * x.uv[0] - std::round(3 * x.uv[0])) > 1e-9;
        if (subdiv_test::thinned_out(v)) continue;
        const Index at = descendant(h, 2, c.levels, v);
        const LimitSample e = s.evaluate(x.face, x.uv[0], x.uv[1], c.t.mesh.positions, 3, 0);
        worst = std::max(worst, distance(e.position, std::span(masks.positions).subspan(size_t(3 * at), 3)));
      }
      MESSAGE(std::string(name) << " mesh " << mesh << ": " << off_lattice << " points off the lattice, " << worst);
      CHECK((c.levels == 2) == (off_lattice > 0));
      CHECK(worst < 1e-13);
    }
  }
}

TEST_CASE("sqrt3, sharpness ending inside a pair: an off-lattice point's refined descendants approach its limit at "
          "the regular rate") {
  // After two steps the crease has decayed and the torus is regular, where a vertex's
  // distance to its limit falls by 1/lambda^2 = 9 per double step (lambda = 1/3, as for the
  // regular √3 grid, docs/limit.md). The point is the face point of a kept triangle, at
  // (4a + 4b + c)/9: a wrong parameter would not be the limit of its descendants.
  const auto scheme = load_scheme("sqrt3");
  const Tagged t = creased_torus(1.f);
  const LimitSurface s(scheme, t.level);
  RefineOptions ro;
  ro.levels = 6;
  const Hierarchy h = refine(*scheme, t.level, ro);
  const auto p = level_positions(h, t.mesh.positions);
  Index v2 = kNone;
  Where x;
  for (Index v = 0; v < h.levels[2].vertex_count && v2 == kNone; ++v) {
    x = where_single_steps_put(t.level, h, v);
    if (std::fabs(9 * x.uv[0] - 4) < 1e-12 || std::fabs(9 * x.uv[0] - 1) < 1e-12) v2 = v;
  }
  REQUIRE(v2 != kNone);
  const LimitSample limit = s.evaluate(x.face, x.uv[0], x.uv[1], t.mesh.positions, 3, 0);
  std::vector<double> d;
  for (int l = 2; l <= 6; l += 2)
    d.push_back(distance(std::span(p[size_t(l)]).subspan(size_t(3 * descendant(h, 2, l, v2)), 3), limit.position));
  MESSAGE("distances at levels 2, 4, 6: " << d[0] << " " << d[1] << " " << d[2]);
  CHECK(d[0] / d[1] == doctest::Approx(9).epsilon(0.05));
  CHECK(d[1] / d[2] == doctest::Approx(9).epsilon(0.02));
}

TEST_CASE("sqrt3, sharpness ending inside a pair: continuous, affine invariant, stencils, derivatives") {
  const double A[3][3] = {{0.8, -0.3, 0.2}, {0.1, 1.1, -0.4}, {0.5, 0.2, 0.9}}, shift[3] = {1.5, -2, 0.25};
  for (const Tagged& t : {creased_torus(1.f), octahedron_with_equator(1.f)}) {
    const Level& L = t.level;
    const std::vector<double>& P = t.mesh.positions;
    const LimitSurface s(load_scheme("sqrt3"), L);
    CHECK(worst_edge_gap(s, L, P, {0.2, 0.731}) < 1e-13);
    std::vector<double> moved(P.size());
    for (size_t v = 0; v < moved.size() / 3; ++v)
      for (int r = 0; r < 3; ++r)
        moved[3 * v + size_t(r)] = shift[r] + A[r][0] * P[3 * v] + A[r][1] * P[3 * v + 1] + A[r][2] * P[3 * v + 2];
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0.05, 0.9);
    double worst_affine = 0, worst_stencil = 0, worst_difference = 0;
    for (Index f = 0; f < L.face_count(); f += subdiv_test::kSanitizerThinning) {
      double u = U(rng), v = U(rng);
      if (u + v > 0.95) u = 0.95 - u, v = 0.95 - v, u = std::max(u, 0.02), v = std::max(v, 0.02);
      const LimitSample p = s.evaluate(f, u, v, P, 3);
      const LimitSample q = s.evaluate(f, u, v, moved, 3);
      REQUIRE(p.has_derivatives);
      for (int r = 0; r < 3; ++r) {
        double y = shift[r];
        for (int c = 0; c < 3; ++c) y += A[r][c] * p.position[size_t(c)];
        worst_affine = std::max(worst_affine, std::fabs(q.position[size_t(r)] - y));
      }
      const LimitStencil w = s.stencil(f, u, v);
      std::array<double, 3> at{0, 0, 0}, du{0, 0, 0};
      for (size_t i = 0; i < w.vertices.size(); ++i)
        for (size_t r = 0; r < 3; ++r)
          at[r] += w.position[i] * P[size_t(3 * w.vertices[i]) + r], du[r] += w.du[i] * P[size_t(3 * w.vertices[i]) + r];
      worst_stencil = std::max({worst_stencil, distance(at, p.position), distance(du, p.du)});
      // The steps followed one at a time bend the parameterisation along the lines from a
      // face's corners to its centre: a small step keeps both sides of the difference in one
      // piece (a random point is not within 1e-7 of them).
      worst_difference = std::max(worst_difference, limit_test::central_difference_error(s, f, u, v, P, 1e-7));
    }
    CHECK(worst_affine < 1e-13);
    CHECK(worst_stencil < 1e-11);
    CHECK(worst_difference < 1e-5);
  }
}

TEST_CASE("sqrt3: sharpness that ends inside a pair is followed one step at a time as long as it lasts") {
  // sqrt3:2,sqrt3 on the same mesh is the sequence that follows the first two steps of the
  // scheme one at a time (its head); the √3 evaluator alone refuses such a mesh. Sharpness
  // that never ends inside a pair (2, 1.5, infinite) keeps the triadic pairs from the start.
  for (float s : {1.f, 0.5f, 2.5f, 3.f}) CHECK(sqrt3_single_step_levels(creased_torus(s).level) == (s > 2 ? 4 : 2));
  for (float s : {2.f, 1.5f, 4.f, 3.5f, kInfinitelySharp}) CHECK(sqrt3_single_step_levels(creased_torus(s).level) == 0);
}
