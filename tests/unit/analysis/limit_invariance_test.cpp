// The limit is invariant under refinement: the limit position of a vertex at level L and of
// its child at level L + 1 agree (the child's masks see the refined points, whose limit is
// the same surface). Closed meshes, boundaries, creases, irregular control meshes.
#include <doctest/doctest.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

void check_invariance(const std::string& scheme, const Mesh& mesh, int levels, double tolerance = 1e-12,
                      const std::vector<std::pair<Index, Index>>& sharp = {}) {
  CAPTURE(scheme);
  const auto s = load_scheme(scheme);
  RefineOptions o;
  o.levels = levels + 1;
  Level base = mesh.level();
  if (!sharp.empty()) {
    base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
    for (auto [a, b] : sharp) base.edge_sharpness[size_t(find_edge(base, a, b))] = 10.f;
  }
  const Hierarchy h = refine(*s, base, o);
  std::vector<std::vector<double>> P{mesh.positions};
  for (const auto& t : h.stencils) P.push_back(t.apply(P.back(), 3));
  std::vector<LimitResult> r;
  for (int l = 0; l <= levels + 1; ++l) {
    LimitOptions lo;
    lo.first_step = l;
    r.push_back(limit_positions(*s, h.levels[size_t(l)], P[size_t(l)], lo));
    CHECK(r.back().approximate == 0);
  }
  for (int l = 0; l <= levels; ++l) {
    CAPTURE(l);
    const ChildOrigins& o0 = h.origins[size_t(l)];
    int shared = 0;
    for (size_t c = 0; c < o0.kind.size(); ++c) {
      if (o0.kind[c] != OriginKind::Vertex) continue;
      const Index v = o0.parent[c];
      ++shared;
      CHECK(distance(at(r[size_t(l)].positions, v), at(r[size_t(l) + 1].positions, Index(c))) < tolerance);
      CHECK(dot(at(r[size_t(l)].normals, v), at(r[size_t(l) + 1].normals, Index(c))) > 1 - 1e-12);
    }
    CHECK(shared == h.levels[size_t(l)].vertex_count);
  }
}

}  // namespace

TEST_CASE("limit positions are invariant under refinement: Catmull-Clark") {
  check_invariance("catmull-clark", test::cube(), 3);
  check_invariance("catmull-clark", test::torus(8, 6), 2);
  check_invariance("catmull-clark", test::pyramid(), 2);  // triangles in the control mesh
  check_invariance("catmull-clark", test::grid(3, 2), 2);   // boundaries and corners
  check_invariance("catmull-clark", test::torus(8, 6), 2, 1e-12, {{0, 1}});  // two darts, creases between
  check_invariance("loop", test::torus(8, 6, true), 2, 1e-12, {{0, 1}, {1, 2}, {2, 3}});
}

TEST_CASE("limit positions are invariant under refinement: Loop, sqrt3, butterflies, composites") {
  check_invariance("loop", test::octahedron(), 3);
  check_invariance("loop", test::grid(3, 3, true), 2);
  check_invariance("sqrt3", test::octahedron(), 3);
  check_invariance("modified-butterfly", test::octahedron(), 2);
  check_invariance("loop-composite", test::octahedron(), 2);
  check_invariance("quad-bspline", test::cube(), 2);
}

TEST_CASE("limit normals on a creased cube: every vertex has one, crease normals between the faces") {
  Mesh cube = test::cube();
  Level L = cube.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 10.f);  // every edge sharp: the cube stays a cube
  const auto s = load_scheme("catmull-clark");
  RefineOptions o;
  o.levels = 2;
  const Hierarchy h = refine(*s, L, o);
  const auto P = interpolate(h, 2, cube.positions, 3);
  LimitOptions lo;
  lo.first_step = 2;
  const LimitResult r = limit_positions(*s, h.levels[2], P, lo);
  CHECK(r.approximate == 0);
  for (Index v = 0; v < h.levels[2].vertex_count; ++v) {
    const Vec3 n = at(r.normals, v);
    CHECK(dot(n, n) == doctest::Approx(1.0));
    // Points away from the centre.
    const Vec3 p = at(r.positions, v);
    CHECK(dot(n, {p[0] - 0.5, p[1] - 0.5, p[2] - 0.5}) > 0);
  }
  // A corner's limit is the corner itself, its normal the diagonal.
  CHECK(distance(at(r.positions, 0), {0, 0, 0}) < 1e-14);
  CHECK(dot(at(r.normals, 0), unit({-1, -1, -1})) > 1 - 1e-12);
}
