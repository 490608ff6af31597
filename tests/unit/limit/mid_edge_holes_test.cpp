// Limit evaluation of the mid-edge scheme (Peters & Reif 1997) on closed meshes with holes
// (tagged faces): a hole removes faces, not rules (OpenSubdiv's convention, docs/limit.md),
// so every other face has the surface of the mesh without the tags, continuous across its
// edges, and a point in a hole is refused with the face.
#include <doctest/doctest.h>

#include <array>

#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

using limit_test::bumped;
using limit_test::distance;

TEST_CASE("mid-edge with holes: a hole removes faces, not rules") {
  // The bumped cube with face 2 a hole, and the pyramid (triangles: sub-faces) with its apex
  // triangle 1 a hole.
  for (const test::Mesh& m : {bumped(test::cube()), bumped(test::pyramid())}) {
    Level holed = m.level();
    holed.face_hole.assign(size_t(holed.face_count()), 0);
    const Index hole = holed.face_count() == 6 ? 2 : 1;
    holed.face_hole[size_t(hole)] = 1;
    const auto scheme = load_scheme("mid-edge");
    const LimitSurface plain(scheme, m.level()), with_hole(scheme, holed);
    double worst = 0, worst_derivative = 0;
    for (Index f = 0; f < holed.face_count(); ++f) {
      if (f == hole) continue;
      for (const std::array<double, 2> uv : {std::array<double, 2>{0.21, 0.37}, {0.5, 0.5}, {0.45, 0.05}, {0, 0}}) {
        const LimitSample p = plain.evaluate(f, uv[0], uv[1], m.positions, 3);
        const LimitSample q = with_hole.evaluate(f, uv[0], uv[1], m.positions, 3);
        worst = std::max(worst, distance(p.position, q.position));
        CHECK(p.has_derivatives == q.has_derivatives);
        if (p.has_derivatives)
          worst_derivative = std::max({worst_derivative, distance(p.du, q.du), distance(p.dv, q.dv)});
      }
    }
    CHECK(worst < 1e-15);
    CHECK(worst_derivative < 1e-13);
    CHECK_THROWS_WITH_AS(with_hole.evaluate(hole, 0.2, 0.2, m.positions, 3), doctest::Contains("hole"), Error);
  }
}
