// Faces round a vertex of high valence (OpenSubdiv's catmark_pole360 and loop_pole360 in
// small): every face's cut holds the whole fan, so what the evaluation works out per face
// or per point is worked out once and shared (LimitSurfaceOptions::shortcuts). Shared or
// not, the numbers must be the very bits the general way gives for each point alone.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/limit/same_bits.h"

using namespace subdiv;

namespace {

constexpr double kPi = 3.141592653589793;

// A disc of n sectors: a pole (vertex 0) inside a ring of n vertices at radius 1 and a
// boundary ring of n at radius 2, as OpenSubdiv's pole shapes: triangles (inner i, inner
// i + 1, pole) round the pole and a band of quads (outer i, outer i + 1, inner i + 1, inner i)
// — split into two triangles each with `triangles` — CCW seen from +z. A bump that differs
// from sector to sector, so that no two faces agree by symmetry.
test::Mesh pole_fan(int n, bool triangles) {
  test::Mesh m;
  m.add_vertex(0, 0, 0.3);
  for (int ring = 1; ring <= 2; ++ring)
    for (int i = 0; i < n; ++i) {
      const double a = 2 * kPi * i / n;
      m.add_vertex(ring * std::cos(a), ring * std::sin(a), 0.1 * std::sin(1.7 * i + ring));
    }
  auto inner = [&](int i) { return Index(1 + i % n); };
  auto outer = [&](int i) { return Index(1 + n + i % n); };
  for (int i = 0; i < n; ++i) {
    m.add_face({inner(i), inner(i + 1), 0});
    if (triangles) {
      m.add_face({outer(i), outer(i + 1), inner(i + 1)});
      m.add_face({outer(i), inner(i + 1), inner(i)});
    } else {
      m.add_face({outer(i), outer(i + 1), inner(i + 1), inner(i)});
    }
  }
  return m;
}

// Evaluates the faces `faces` at a corner, an edge point and inside, with and without the
// shortcuts, and compares the bits (positions, derivatives, stencils).
void same_bits(const char* scheme, const test::Mesh& m, const std::vector<Index>& faces) {
  const Level base = m.level();
  LimitSurfaceOptions general;
  general.shortcuts = false;
  const LimitSurface a(load_scheme(scheme), base), b(load_scheme(scheme), base, general);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.01, 0.45);
  const bool sub_faces = !a.triangles();
  for (Index f : faces)
    for (int k = 0; k < (sub_faces && base.face_size(f) == 3 ? 5 : 3); ++k) {
      // The pole is corner 2 of the fan's triangles: (0, 1) in a triangle, and in Bfr's sub-face
      // layout of a triangle (Catmull-Clark) the corner (0, 0) of sub-face 2, [0, 1/2] x [1, 3/2];
      // then a point on an edge, one inside and, in a triangle's sub-faces 1 and 2, one inside each.
      const double ru = unit(rng), rv = unit(rng);
      const double u = k == 0 ? 0.0 : k == 3 ? 1 + ru : ru;
      const double v = k == 0 ? 1.0 : k == 1 ? 0.0 : k == 4 ? 1 + rv : rv;
      INFO(scheme << ", valence " << (m.vertex_count - 1) / 2 << ", face " << f << " at (" << u << ", " << v << ")");
      limit_test::check_same_bits(a, b, f, u, v, m.positions, 1);
    }
}

}  // namespace

TEST_CASE("Round a pole of valence 20, 65 and 360 the shortcuts give the general way's bits") {
  for (int n : {20, 65, 360}) {
    // The fan's triangles, the quads or triangles beside them, and both ends of the numbering
    // (where a face's cut wraps round the mesh's face order). The general way refines the
    // whole fan for each point: a few faces at valence 360.
    std::vector<Index> cc, loop;
    const int per = n == 360 ? 1 : 3;
    for (int i : {0, 1, n / 2, n - 1})
      for (int j = 0; j < per; ++j) cc.push_back(Index(2 * ((i + j) % n))), cc.push_back(Index(2 * ((i + j) % n) + 1));
    for (int i : {0, n / 3, n - 1})
      for (int j = 0; j < 3; ++j) loop.push_back(Index(3 * i + j));
    same_bits("catmull-clark", pole_fan(n, false), cc);
    same_bits("loop", pole_fan(n, true), loop);
  }
}
