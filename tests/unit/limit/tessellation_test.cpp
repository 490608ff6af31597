// The sampled limit surface: crack-free (neighbouring faces share their edge samples, so a
// closed mesh stays closed), every point on the limit, unit normals.
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "framework/limit/tessellation.h"
#include "framework/pipeline/evaluate_request.h"
#include "framework/pipeline/limit_mesh.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/cli_runner.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

using limit_test::octahedron;

Level level_of(const Tessellation& t) { return build_level(t.point_count(), t.face_offsets, t.face_vertices); }

int boundary_edges(const Level& L) {
  int n = 0;
  for (Index e = 0; e < L.edge_count(); ++e) n += L.edge_on_boundary(e) ? 1 : 0;
  return n;
}

void check_points(const LimitSurface& s, const Tessellation& t, std::span<const double> P) {
  for (Index i = 0; i < t.point_count(); i += 7) {
    const LimitSample p = s.evaluate(t.uv_face[size_t(i)], t.uv[size_t(2 * i)], t.uv[size_t(2 * i + 1)], P, 3);
    for (int c = 0; c < 3; ++c) CHECK(t.positions[size_t(3 * i + c)] == p.position[size_t(c)]);
    const double* n = &t.normals[size_t(3 * i)];
    CHECK(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) == doctest::Approx(1.0).epsilon(1e-12));
  }
}

}  // namespace

TEST_CASE("Tessellating closed meshes gives closed meshes: Catmull-Clark cube, Loop octahedron") {
  {
    const test::Mesh m = test::cube();
    const LimitSurface s(load_scheme("catmull-clark"), m.level());
    const int N = 4;
    const Tessellation t = tessellate(s, m.positions, N);
    CHECK(t.face_count() == 6 * N * N);
    CHECK(t.point_count() == 8 + 12 * (N - 1) + 6 * (N - 1) * (N - 1));  // shared corners and edges
    const Level L = level_of(t);
    CHECK(boundary_edges(L) == 0);
    CHECK(euler_characteristic(L) == 2);
    check_points(s, t, m.positions);
    // The cube [0, 1]^3 with outward-facing faces: its limit is convex and normals point
    // away from its centre.
    for (Index i = 0; i < t.point_count(); ++i) {
      double d = 0;
      for (int c = 0; c < 3; ++c) d += t.normals[size_t(3 * i + c)] * (t.positions[size_t(3 * i + c)] - 0.5);
      CHECK(d > 0);
    }
  }
  {
    const test::Mesh m = octahedron();
    const LimitSurface s(load_scheme("loop"), m.level());
    const int N = 3;
    const Tessellation t = tessellate(s, m.positions, N);
    CHECK(t.face_count() == 8 * N * N);
    CHECK(t.point_count() == 6 + 12 * (N - 1) + 8 * (N - 1) * (N - 2) / 2);
    const Level L = level_of(t);
    CHECK(boundary_edges(L) == 0);
    CHECK(euler_characteristic(L) == 2);
    check_points(s, t, m.positions);
  }
}

TEST_CASE("Tessellating n-gons: sub-face grids meet the neighbours' edges; odd N is refused") {
  test::Mesh m = test::pyramid();  // a quad base and four triangles, under Catmull-Clark
  const LimitSurface s(load_scheme("catmull-clark"), m.level());
  const Tessellation t = tessellate(s, m.positions, 4);
  const Level L = level_of(t);
  CHECK(boundary_edges(L) == 0);
  CHECK(euler_characteristic(L) == 2);
  check_points(s, t, m.positions);
  CHECK_THROWS_WITH_AS(tessellate(s, m.positions, 3), doctest::Contains("use an even N"), Error);
  CHECK_THROWS_AS(tessellate(s, m.positions, 0), Error);
}

TEST_CASE("Tessellating a dual scheme's limit gives a closed mesh with outward normals: Doo-Sabin cube and pyramid") {
  for (const test::Mesh& m : {test::cube(), test::pyramid()}) {
    const LimitSurface s(load_scheme("doo-sabin"), m.level());
    const Tessellation t = tessellate(s, m.positions, 4);
    const Level L = level_of(t);
    CHECK(boundary_edges(L) == 0);
    CHECK(euler_characteristic(L) == 2);
    check_points(s, t, m.positions);
    // Both are convex: the normals point away from the control points' centroid.
    std::array<double, 3> centre{};
    for (Index v = 0; v < m.vertex_count; ++v)
      for (int c = 0; c < 3; ++c) centre[size_t(c)] += m.positions[size_t(3 * v + c)] / m.vertex_count;
    for (Index i = 0; i < t.point_count(); ++i) {
      double d = 0, l = 0;
      for (int c = 0; c < 3; ++c) {
        d += t.normals[size_t(3 * i + c)] * (t.positions[size_t(3 * i + c)] - centre[size_t(c)]);
        l += t.normals[size_t(3 * i + c)] * t.normals[size_t(3 * i + c)];
      }
      CHECK(d > 0);
      CHECK(std::fabs(l - 1) < 1e-12);
    }
  }
}

TEST_CASE("Tessellations carry the face-varying data: bilinear per base face in the mode All, seams kept") {
  EvaluateRequest r;
  r.mesh_file = test::source_path("examples/meshes/textured-tube.obj");
  r.scheme.text = "catmull-clark";
  const PreparedEvaluation p = prepare_evaluation(r);
  REQUIRE(p.face_varying.size() == 1);
  const int N = 4;
  const Tessellation t = tessellate(*p.surface, p.mesh.positions, N);  // for each corner's (u, v)
  const MeshData sampled = sampled_limit_mesh(p, N);
  REQUIRE(sampled.face_vertices == t.face_vertices);
  REQUIRE(sampled.face_varying.size() == 1);
  const FaceVaryingArray& a = sampled.face_varying[0];
  CHECK(a.role == ArrayRole::TextureCoordinates);
  REQUIRE(a.indices.size() == t.face_vertices.size());
  // The mode All (OpenSubdiv's default): each corner's value is the bilinear blend of its base
  // face's corner values at the corner's (u, v) in that face (the tube's faces are quads).
  const FaceVaryingArray& given = p.mesh.face_varying[0];
  const int C = a.components;
  double worst = 0;
  for (Index f = 0; f < t.face_count(); ++f) {
    const Index b = t.base_face[size_t(f)];
    const Index first = p.mesh.face_offsets[size_t(b)];
    REQUIRE(p.mesh.face_offsets[size_t(b) + 1] - first == 4);
    for (Index c = t.face_offsets[size_t(f)]; c < t.face_offsets[size_t(f) + 1]; ++c) {
      const double u = t.corner_uv[size_t(2 * c)], v = t.corner_uv[size_t(2 * c + 1)];
      const double w[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
      for (int k = 0; k < C; ++k) {
        double expected = 0;
        for (int q = 0; q < 4; ++q)
          expected += w[q] * given.values[size_t(given.indices[size_t(first + q)]) * size_t(C) + size_t(k)];
        worst = std::max(worst, std::fabs(expected - a.values[size_t(a.indices[size_t(c)]) * size_t(C) + size_t(k)]));
      }
    }
  }
  CHECK(worst < 1e-14);
  // The tube's seam splits values: more values than points, and a point with two values lies
  // on a base edge (u or v of 0 or 1 in the face it was evaluated in).
  CHECK(a.value_count() > t.point_count());
  std::vector<std::vector<Index>> values_at(size_t(t.point_count()));
  for (size_t c = 0; c < t.face_vertices.size(); ++c) values_at[size_t(t.face_vertices[c])].push_back(a.indices[c]);
  for (Index i = 0; i < t.point_count(); ++i) {
    auto& v = values_at[size_t(i)];
    std::sort(v.begin(), v.end());
    if (std::unique(v.begin(), v.end()) - v.begin() < 2) continue;
    const double u = t.uv[size_t(2 * i)], w = t.uv[size_t(2 * i + 1)];
    CHECK((u == 0 || u == 1 || w == 0 || w == 1));
  }
}
