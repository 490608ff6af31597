// Local adaptive refinement (limit/adaptive_refine.h): the work grows with the number of
// features, not 4^L; the uniform level L is recovered when every face must be split; with
// limit positions every vertex is a limit point of the uniform level L (its vertex's limit
// mask, analysis/surface/limit_evaluation.h, not the evaluator the refinement uses); with a
// tolerance the distance to the limit surface, sampled densely and independently, is below it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/engine/refiner.h"
#include "framework/limit/adaptive_refine.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

AdaptiveMesh adapt(const Scheme& scheme, const Level& base, std::span<const double> points, int levels,
                   const LimitSurface* surface = nullptr, bool limit = false, double tolerance = 0) {
  AdaptiveOptions o;
  o.levels = levels;
  o.limit = limit;
  o.tolerance = tolerance;
  o.surface = surface;
  return refine_adaptive(scheme, base, points, o);
}

Index face_count(const AdaptiveMesh& m) { return Index(m.face_offsets.size()) - 1; }

// Closed, every edge in exactly two faces (no T-junction), manifold, Euler characteristic.
void check_watertight(const AdaptiveMesh& m, int euler) {
  const Level L = build_level(Index(m.positions.size() / 3), m.face_offsets, m.face_vertices);
  int wrong = 0;
  for (Index e = 0; e < L.edge_count(); ++e) wrong += L.edge_face_count(e) != 2;
  CHECK(wrong == 0);
  CHECK(L.manifold());
  CHECK(L.vertex_count - L.edge_count() + L.face_count() == euler);
}

// A torus of 8 x 6 quads with two pairs of neighbouring quads merged into hexagons: each
// merge leaves the removed edge's two ends with valence 3 (4 extraordinary vertices, 2
// hexagons; Euler characteristic still 0).
test::Mesh torus_with_extraordinary_vertices() {
  const test::Mesh t = test::torus(8, 6);
  test::Mesh m;
  for (Index v = 0; v < t.vertex_count; ++v)
    m.add_vertex(t.positions[3 * size_t(v)], t.positions[3 * size_t(v) + 1], t.positions[3 * size_t(v) + 2]);
  auto face = [&](Index f) {
    return std::vector<Index>(t.corners.begin() + t.offsets[size_t(f)], t.corners.begin() + t.offsets[size_t(f) + 1]);
  };
  // Faces f and f + 1 (neighbours along the torus' long way) share their edge (corner 1, corner 2) of f.
  auto merged = [&](Index f) {
    const std::vector<Index> a = face(f), b = face(f + 1);  // a = (p, q, r, s), b = (q, x, y, r)
    return std::vector<Index>{a[0], a[1], b[1], b[2], a[2], a[3]};
  };
  auto add = [&](const std::vector<Index>& vs) {
    m.corners.insert(m.corners.end(), vs.begin(), vs.end());
    m.offsets.push_back(Index(m.corners.size()));
  };
  for (Index f = 0; f < Index(t.offsets.size()) - 1; ++f) {
    if (f == 9 || f == 28) {
      add(merged(f));
      ++f;
      continue;
    }
    add(face(f));
  }
  return m;
}

double distance(std::span<const double> a, std::span<const double> b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// The largest distance from every point of `m` to the nearest of `points`.
double farthest_from(const AdaptiveMesh& m, const std::vector<double>& points) {
  double worst = 0;
  for (size_t v = 0; v < m.positions.size() / 3; ++v) {
    double nearest = 1e300;
    for (size_t w = 0; w < points.size() / 3; ++w)
      nearest = std::min(nearest, distance({&m.positions[3 * v], 3}, {&points[3 * w], 3}));
    worst = std::max(worst, nearest);
  }
  return worst;
}

}  // namespace

TEST_CASE("Adaptive refinement is local: faces and work grow linearly with L (cube, torus with 4 extraordinary "
          "vertices), not as 4^L") {
  const auto scheme = load_scheme("catmull-clark");
  const test::Mesh cube = test::cube(), torus = torus_with_extraordinary_vertices();
  for (const test::Mesh* mesh : {&cube, &torus}) {
    std::vector<Index> faces, work;
    for (int L = 1; L <= 8; ++L) {
      const AdaptiveMesh m = adapt(*scheme, mesh->level(), mesh->positions, L);
      check_watertight(m, mesh == &cube ? 2 : 0);
      faces.push_back(face_count(m));
      Index computed = 0;
      for (Index c : m.computed_faces) computed += c;
      work.push_back(computed);
    }
    // Each further level adds the same number of faces (from L = 4) and of computed faces
    // (from L = 6, once the rings computed around neighbouring features have separated):
    // the neighbourhoods of the features are self-similar, so the work is linear in L.
    for (size_t l = 3; l < faces.size(); ++l) {
      CAPTURE(l);
      CHECK(faces[l] - faces[l - 1] == faces[l - 1] - faces[l - 2]);
      if (l >= 5) CHECK(work[l] - work[l - 1] == work[l - 1] - work[l - 2]);
    }
    MESSAGE("faces per L = 1..8: ", faces[0], " ", faces[1], " ", faces[2], " ", faces[3], " ", faces[4], " ",
            faces[5], " ", faces[6], " ", faces[7], "; computed child faces: ", work[7], " at L = 8");
  }
  // On the torus only the faces around the 4 extraordinary vertices and the 2 hexagons are
  // split: a regular face two rings away stays at level 0.
  const AdaptiveMesh m = adapt(*scheme, torus.level(), torus.positions, 4);
  CHECK(std::count(m.face_level.begin(), m.face_level.end(), 0) > 20);
}

TEST_CASE("Adaptive refinement recovers the uniform level L when every face must be split") {
  const auto scheme = load_scheme("catmull-clark");
  const test::Mesh torus = torus_with_extraordinary_vertices();
  const LimitSurface surface(scheme, torus.level());
  const int L = 2;
  const AdaptiveMesh m = adapt(*scheme, torus.level(), torus.positions, L, &surface, false, 1e-12);
  RefineOptions ro;
  ro.levels = L;
  const Hierarchy h = refine(*scheme, torus.level(), ro);
  std::vector<double> uniform(torus.positions.begin(), torus.positions.end());
  for (int l = 0; l < L; ++l) uniform = h.stencils[size_t(l)].apply(uniform, 3);
  CHECK(face_count(m) == h.levels.back().face_count());
  CHECK(m.positions.size() == uniform.size());
  CHECK(std::all_of(m.face_level.begin(), m.face_level.end(), [&](int l) { return l == L; }));
  CHECK(farthest_from(m, uniform) < 1e-13);
  check_watertight(m, 0);
}

TEST_CASE("With limit positions every vertex is the limit of a uniform level-L vertex (its limit mask)") {
  const auto scheme = load_scheme("catmull-clark");
  for (const test::Mesh& mesh : {test::cube(), torus_with_extraordinary_vertices()}) {
    const LimitSurface surface(scheme, mesh.level());
    const int L = 3;
    const AdaptiveMesh m = adapt(*scheme, mesh.level(), mesh.positions, L, &surface, true);
    RefineOptions ro;
    ro.levels = L;
    const Hierarchy h = refine(*scheme, mesh.level(), ro);
    std::vector<double> fine(mesh.positions.begin(), mesh.positions.end());
    for (int l = 0; l < L; ++l) fine = h.stencils[size_t(l)].apply(fine, 3);
    LimitOptions lo;
    lo.first_step = L;
    const std::vector<double> limits = limit_positions(*scheme, h.levels.back(), fine, lo).positions;
    CHECK(farthest_from(m, limits) < 1e-12);
  }
}

TEST_CASE("With a tolerance the distance to the limit, sampled densely, is below it; fewer faces than uniform") {
  const auto scheme = load_scheme("catmull-clark");
  const test::Mesh cube = test::cube();
  const LimitSurface surface(scheme, cube.level());
  const int L = 6;
  for (double tolerance : {1e-2, 3e-3}) {
    CAPTURE(tolerance);
    const AdaptiveMesh m = adapt(*scheme, cube.level(), cube.positions, L, &surface, true, tolerance);
    check_watertight(m, 2);
    // Each face's corners (the level's face, not the finer transition vertices) with their
    // (u, v); the bilinear patch through them against the limit at 9 x 9 points.
    double worst = 0;
    int at_cap = 0;
    for (size_t f = 0; f + 1 < m.face_offsets.size(); ++f) {
      std::vector<std::array<double, 2>> uv;
      std::vector<const double*> p;
      for (Index k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k)
        if (m.corner_is_face_corner[size_t(k)])
          uv.push_back(m.corner_uv[size_t(k)]), p.push_back(&m.positions[3 * size_t(m.face_vertices[size_t(k)])]);
      REQUIRE(uv.size() == 4);
      at_cap += m.face_level[f] == L;
      for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) {
          const double s = i / 8.0, t = j / 8.0, w[4] = {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
          double x[3] = {0, 0, 0}, u = 0, v = 0;
          for (int k = 0; k < 4; ++k) {
            u += w[k] * uv[size_t(k)][0], v += w[k] * uv[size_t(k)][1];
            for (int d = 0; d < 3; ++d) x[d] += w[k] * p[size_t(k)][d];
          }
          const LimitSample q = surface.evaluate(m.base_face[f], u, v, cube.positions, 3, 0);
          worst = std::max(worst, distance(q.position, {x, 3}));
        }
    }
    CHECK(worst <= tolerance);
    CHECK(face_count(m) < m.uniform_faces / 10);
    MESSAGE("tolerance ", tolerance, ": ", face_count(m), " faces (uniform level ", L, ": ", m.uniform_faces,
            "), ", at_cap, " at level ", L, ", largest distance at 9 x 9 points ", worst);
  }
}

TEST_CASE("Adaptive Loop on an octahedron and a regular triangulated torus") {
  const auto loop = load_scheme("loop");
  const test::Mesh octa = test::octahedron(), torus = test::torus(8, 6, true);
  std::vector<Index> faces;
  for (int L = 1; L <= 6; ++L) {
    const AdaptiveMesh m = adapt(*loop, octa.level(), octa.positions, L);
    check_watertight(m, 2);
    faces.push_back(face_count(m));
  }
  for (size_t l = 3; l < faces.size(); ++l) CHECK(faces[l] - faces[l - 1] == faces[l - 1] - faces[l - 2]);
  const AdaptiveMesh t = adapt(*loop, torus.level(), torus.positions, 4);
  CHECK(face_count(t) == torus.level().face_count());  // regular: nothing to split
}
