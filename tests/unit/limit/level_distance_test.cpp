// How far uniform level L is from the limit (subdiv evaluate --level-distance): the closed
// form at level 0, the uniform level's counts, and the rate at which the distance falls.
#include <doctest/doctest.h>

#include <cmath>

#include "framework/pipeline/level_distance.h"
#include "support/cli_runner.h"

using namespace subdiv;

namespace {

LevelDistance cube(int level) {
  EvaluateRequest r;
  r.mesh_file = test::source_path("examples/meshes/cube.obj");
  r.mesh_name = "cube.obj";
  r.scheme.text = "catmull-clark";
  return level_distance(r, level);
}

}  // namespace

TEST_CASE("level 0 of the cube: each corner is sqrt(3)/4 from its limit (Catmull-Clark's limit mask)") {
  // The limit of a valence-3 corner v is (9 v + 4 sum e + sum d) / 24 (n^2 v + 4 sum e + sum d
  // over n (n + 5)): for v = (1, 1, 1) / 2 the three edge neighbours sum to (1, 1, 1) / 2 and
  // the three opposite corners to -(1, 1, 1) / 2, so the limit is (1, 1, 1) / 4.
  const LevelDistance d = cube(0);
  CHECK(d.vertices == 8);
  CHECK(d.largest == doctest::Approx(std::sqrt(3.0) / 4).epsilon(1e-14));
  CHECK(d.mean == doctest::Approx(std::sqrt(3.0) / 4).epsilon(1e-14));
}

TEST_CASE("uniform level L: its counts, and the distance falling by 4 per level") {
  // Catmull-Clark's vertices approach their limit as the eigenvalue 1/4 (the subdominant
  // eigenvectors vanish at the centre vertex), also next to the valence-3 corners.
  const LevelDistance three = cube(3), four = cube(4);
  CHECK(three.vertices == 386);
  CHECK(three.mesh.face_count() == 384);
  CHECK(four.mesh.face_count() == 1536);
  const double rate = three.largest / four.largest;
  CHECK(rate > 3.8);
  CHECK(rate < 4.2);
  CHECK(three.mean / four.mean > 3.8);
  CHECK(three.mean / four.mean < 4.2);
}

TEST_CASE("Normals at the extraordinary vertices are the limit normal from the faces, not (0, 0, 0)") {
  // The cube's corners keep valence 3 at every level; by its symmetry the limit normal there
  // is (±1, ±1, ±1) / sqrt(3), pointing out. Every other vertex has a unit normal too.
  const LevelDistance d = cube(1);
  const DataArray* normals = nullptr;
  for (const DataArray& a : d.mesh.point_data)
    if (a.name == "Normals") normals = &a;
  REQUIRE(normals);
  int corners = 0;
  for (size_t v = 0; v < size_t(d.vertices); ++v) {
    const double* n = &normals->values[3 * v];
    const double* p = &d.mesh.positions[3 * v];
    CHECK(std::hypot(n[0], n[1], n[2]) == doctest::Approx(1.0).epsilon(1e-9));
    if (std::abs(std::abs(p[0]) - std::abs(p[1])) > 1e-12 || std::abs(std::abs(p[1]) - std::abs(p[2])) > 1e-12) continue;
    ++corners;
    for (int c = 0; c < 3; ++c) CHECK(n[c] == doctest::Approx(std::copysign(1 / std::sqrt(3.0), p[c])).epsilon(1e-6));
  }
  CHECK(corners == 8);
  CHECK(d.mesh.warnings.empty());
}
