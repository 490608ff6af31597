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
