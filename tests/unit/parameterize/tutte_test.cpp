// Tutte's embedding (framework/parameterize): the boundary on the unit circle or square in
// boundary order, every interior vertex the weighted average of its neighbours (Tutte 1963;
// mean-value weights, Floater 2003), no face flipped (Tutte's theorem for a convex
// boundary), non-discs refused with the reason, and UVs that `subdiv refine` carries as
// face-varying data.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/parameterize/parameterize_mesh.h"
#include "framework/parameterize/tutte.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/util/error.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

constexpr double kPi = 3.14159265358979323846;

// An (n x n) grid, optionally triangulated, bent into a bumpy, non-planar disc whose
// vertices are not evenly spaced (so that uniform and mean-value weights differ).
test::Mesh bumpy_disc(int n, bool triangles) {
  test::Mesh m = test::grid(n, n, triangles);
  for (Index v = 0; v < m.vertex_count; ++v) {
    double* p = &m.positions[size_t(3 * v)];
    const double x = p[0] / n, y = p[1] / n;
    p[0] = x * x * (3 - 2 * x), p[1] = y + 0.2 * x * y * (1 - y), p[2] = 0.4 * std::sin(3 * x) * std::cos(2 * y);
  }
  return m;
}

using test::mesh_data;

// Twice the signed area of face f in the uv plane (shoelace formula).
double signed_area(const Level& level, const std::vector<double>& uv, Index f) {
  const auto c = level.face(f);
  double a = 0;
  for (size_t i = 0; i < c.size(); ++i) {
    const size_t p = size_t(c[i]), q = size_t(c[(i + 1) % c.size()]);
    a += uv[2 * p] * uv[2 * q + 1] - uv[2 * q] * uv[2 * p + 1];
  }
  return a;
}

void check_interior_averages(const Level& level, const test::Mesh& m, const TutteResult& r, TutteWeights w) {
  double worst = 0;
  for (Index v = 0; v < level.vertex_count; ++v) {
    if (level.on_boundary(v)) continue;
    double avg[2] = {0, 0};
    for (const auto& entry : tutte_row(level, m.positions, v, w)) {
      CHECK(entry.second > 0);  // convex combinations: the theorem needs positive weights
      for (size_t c = 0; c < 2; ++c) avg[c] += entry.second * r.uv[2 * size_t(entry.first) + c];
    }
    for (size_t c = 0; c < 2; ++c) worst = std::max(worst, std::abs(avg[c] - r.uv[2 * size_t(v) + c]));
  }
  CHECK(worst <= 1e-12);
}

void check_no_flips(const Level& level, const TutteResult& r) {
  double smallest = 1;
  for (Index f = 0; f < level.face_count(); ++f) smallest = std::min(smallest, signed_area(level, r.uv, f));
  CHECK(smallest > 0);
}

}  // namespace

TEST_CASE("tutte: the boundary lies on the unit circle in boundary order, interiors are weighted averages") {
  for (bool triangles : {false, true})
    for (TutteWeights w : {TutteWeights::Uniform, TutteWeights::MeanValue}) {
      CAPTURE(triangles);
      CAPTURE(int(w));
      const test::Mesh m = bumpy_disc(9, triangles);
      const Level level = m.level();
      TutteOptions o;
      o.weights = w;
      const TutteResult r = tutte_embedding(level, m.positions, o, "disc");
      REQUIRE(r.boundary.size() == 36);
      double turned = 0, worst = 0;
      for (size_t i = 0; i < r.boundary.size(); ++i) {
        const size_t a = size_t(r.boundary[i]), b = size_t(r.boundary[(i + 1) % r.boundary.size()]);
        worst = std::max(worst, std::abs(std::hypot(r.uv[2 * a], r.uv[2 * a + 1]) - 1));
        double step = std::atan2(r.uv[2 * b + 1], r.uv[2 * b]) - std::atan2(r.uv[2 * a + 1], r.uv[2 * a]);
        if (step < 0) step += 2 * kPi;
        CHECK(step > 0);  // counter-clockwise, one vertex after the other
        turned += step;
      }
      CHECK(worst <= 1e-14);
      CHECK(turned == doctest::Approx(2 * kPi).epsilon(1e-12));  // once around
      check_interior_averages(level, m, r, w);
      check_no_flips(level, r);
    }
}

TEST_CASE("tutte: a square boundary puts the corners at the square's corners and the rest on its sides") {
  const test::Mesh m = bumpy_disc(6, true);
  const Level level = m.level();
  TutteOptions o;
  o.boundary = BoundaryShape::Square;
  SUBCASE("the sharpest turns: the grid's four corners") {}
  SUBCASE("given corners, in any order") { o.corners = {48, 0, 6, 42}; }
  const TutteResult r = tutte_embedding(level, m.positions, o, "disc");
  REQUIRE(r.corners.size() == 4);
  CHECK(r.corners == std::vector<Index>{0, 6, 48, 42});
  const double expected[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (size_t k = 0; k < 4; ++k) {
    CHECK(r.uv[2 * size_t(r.corners[k])] == expected[k][0]);
    CHECK(r.uv[2 * size_t(r.corners[k]) + 1] == expected[k][1]);
  }
  // Along the perimeter, counter-clockwise: the position s in [0, 4) increases.
  auto perimeter = [&](Index v) {
    const double u = r.uv[2 * size_t(v)], w = r.uv[2 * size_t(v) + 1];
    if (w == 0) return u;
    if (u == 1) return 1 + w;
    if (w == 1) return 3 - u;
    REQUIRE(u == 0);  // on one of the four sides
    return 4 - w;
  };
  for (size_t i = 1; i < r.boundary.size(); ++i) CHECK(perimeter(r.boundary[i]) > perimeter(r.boundary[i - 1]));
  check_interior_averages(level, m, r, TutteWeights::Uniform);
  check_no_flips(level, r);
}

TEST_CASE("tutte: meshes that are not discs are refused with the reason") {
  auto refused = [](const test::Mesh& m, const char* reason) {
    CAPTURE(reason);
    CHECK_THROWS_WITH_AS(tutte_embedding(m.level(), m.positions, {}, "m.obj"), doctest::Contains(reason), Error);
  };
  refused(test::cube(), "m.obj: the mesh has 0 boundary loops");
  test::Mesh holed = test::grid(3, 3);  // the middle quad left out: two boundary loops
  holed.corners.erase(holed.corners.begin() + 16, holed.corners.begin() + 20);
  holed.offsets.resize(9);
  refused(holed, "2 boundary loops");
  test::Mesh handle = test::torus(6, 6);  // a torus less one face: one loop, but V - E + F = -1
  handle.corners.resize(handle.corners.size() - 4);
  handle.offsets.pop_back();
  refused(handle, "Euler characteristic V - E + F is -1");
  test::Mesh two = test::grid(1, 1);  // two separate quads
  for (int i = 0; i < 4; ++i) two.add_vertex(5 + (i & 1), (i >> 1) & 1, 0);
  two.add_face({4, 5, 7, 6});
  refused(two, "2 connected parts");
  TutteOptions bad;
  bad.boundary = BoundaryShape::Square;
  bad.corners = {0, 3, 15, 5};  // 5 is inside a 3 x 3 grid
  CHECK_THROWS_WITH_AS(tutte_embedding(test::grid(3, 3).level(), test::grid(3, 3).positions, bad, "m.obj"),
                       doctest::Contains("corner 5 is not a boundary vertex"), Error);
}

TEST_CASE("tutte: the UVs survive an OBJ round trip and subdiv refine carries them as face-varying data") {
  const test::Mesh m = bumpy_disc(5, false);
  const ParameterizedMesh p = parameterize_mesh(mesh_data(m), {}, "disc");
  const auto file = std::filesystem::temp_directory_path() / "subdivkit_tutte_round_trip.obj";
  write_mesh(file, p.mesh);
  RefineRequest r;
  r.mesh_file = file.string();
  r.scheme.text = "catmull-clark";
  r.levels = 2;
  const RefineResult refined = refine_mesh(r);
  std::filesystem::remove(file);
  const LevelData& fine = refined.levels.back();
  REQUIRE(fine.face_varying.size() == 1);
  const FaceVaryingArray& uv = fine.face_varying.front();
  CHECK(uv.components == 2);
  CHECK(uv.indices.size() == refined.hierarchy.levels.back().face_vertices.size());
  // Refined UVs of a one-to-one map stay inside the disc and keep every face's orientation.
  double largest = 0, smallest_area = 1;
  for (Index k = 0; k < uv.value_count(); ++k) largest = std::max(largest, std::hypot(uv.values[2 * size_t(k)], uv.values[2 * size_t(k) + 1]));
  const Level& level = refined.hierarchy.levels.back();
  for (Index f = 0; f < level.face_count(); ++f) {
    const auto c = level.face(f);
    double a = 0;
    for (size_t i = 0; i < c.size(); ++i) {
      const size_t s = size_t(uv.indices[size_t(level.face_offsets[size_t(f)]) + i]);
      const size_t t = size_t(uv.indices[size_t(level.face_offsets[size_t(f)]) + (i + 1) % c.size()]);
      a += uv.values[2 * s] * uv.values[2 * t + 1] - uv.values[2 * t] * uv.values[2 * s + 1];
    }
    smallest_area = std::min(smallest_area, a);
  }
  CHECK(largest <= 1 + 1e-12);
  CHECK(smallest_area > 0);
}

}  // namespace subdiv
