// Adaptive refinement of rational meshes (framework/pipeline/adaptive_request.h): the
// homogeneous points (w·p, w) are refined like any point data and projected. Checked against
// two independent routes: uniform rational refinement (every face of the cube touches a
// valence-3 vertex, so adaptive level 1 is uniform level 1), and the rational limit surface
// evaluated at each vertex's (face, u, v) (rational_evaluate's projection); uniform weights
// change nothing projective; a tolerance is refused with its reason.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/pipeline/adaptive_request.h"
#include "framework/pipeline/evaluate_request.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// Weights in [0.5, 2] that differ from vertex to vertex.
std::vector<double> uneven_weights(size_t n) {
  std::vector<double> w(n);
  for (size_t v = 0; v < n; ++v) w[v] = 0.5 + 1.5 * std::fmod(0.618033988749895 * double(v + 1), 1.0);
  return w;
}

MeshData weighted_cube(std::vector<double> w) {
  MeshData d = test::mesh_data(test::cube());
  d.point_data.push_back({"weight", 1, std::move(w)});
  return d;
}

AdaptiveResult adaptive(MeshData mesh, int levels, bool limit, double tolerance = 0) {
  AdaptiveRequest r;
  r.refine.mesh = std::move(mesh);
  r.refine.mesh_name = "weighted cube";
  r.refine.scheme.text = "catmull-clark";
  r.refine.levels = levels;
  r.limit = limit;
  r.tolerance = tolerance;
  return refine_adaptive_request(std::move(r));
}

std::vector<std::array<double, 3>> sorted_points(const std::vector<double>& xyz) {
  std::vector<std::array<double, 3>> p(xyz.size() / 3);
  for (size_t v = 0; v < p.size(); ++v) p[v] = {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
  std::sort(p.begin(), p.end());
  return p;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

}  // namespace

TEST_CASE("adaptive refinement of a rational cube: level 1 is the uniform rational level 1") {
  const std::vector<double> w = uneven_weights(8);
  const AdaptiveResult a = adaptive(weighted_cube(w), 1, false);
  RefineRequest u;
  u.mesh = weighted_cube(w);
  u.mesh_name = "weighted cube";
  u.scheme.text = "catmull-clark";
  u.levels = 1;
  const RefineResult uniform = refine_mesh(std::move(u));
  const auto ours = sorted_points(a.mesh.positions), theirs = sorted_points(uniform.levels.back().positions);
  REQUIRE(ours.size() == theirs.size());
  double worst = 0;
  for (size_t v = 0; v < ours.size(); ++v)
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(ours[v][c] - theirs[v][c]));
  CHECK(worst < 1e-14);
  // And not the polynomial refinement: the weights matter.
  const AdaptiveResult plain = adaptive(test::mesh_data(test::cube()), 1, false);
  CHECK(largest_difference(a.mesh.positions, plain.mesh.positions) > 1e-3);
}

TEST_CASE("adaptive refinement of a rational cube with limit positions: every vertex on the rational limit") {
  const std::vector<double> w = uneven_weights(8);
  const AdaptiveResult a = adaptive(weighted_cube(w), 3, true);
  EvaluateRequest e;
  e.mesh = weighted_cube(w);
  e.mesh_name = "weighted cube";
  e.scheme.text = "catmull-clark";
  const PreparedEvaluation p = prepare_evaluation(std::move(e));
  REQUIRE_FALSE(p.weights.empty());
  // Each vertex's (face, u, v): from the first face corner that uses it.
  const size_t V = a.mesh.positions.size() / 3;
  std::vector<Index> faces(V, kNone);
  std::vector<double> uv(2 * V);
  for (size_t f = 0; f + 1 < a.mesh.face_offsets.size(); ++f)
    for (Index c = a.mesh.face_offsets[f]; c < a.mesh.face_offsets[f + 1]; ++c) {
      const Index v = a.mesh.face_vertices[size_t(c)];
      if (faces[size_t(v)] != kNone) continue;
      faces[size_t(v)] = a.mesh.base_face[f];
      uv[2 * size_t(v)] = a.mesh.corner_uv[size_t(c)][0];
      uv[2 * size_t(v) + 1] = a.mesh.corner_uv[size_t(c)][1];
    }
  const EvaluatedPoints limit = evaluate_limit_points(p, faces, uv, 0);
  CHECK(largest_difference(a.mesh.positions, limit.position) < 1e-13);
}

TEST_CASE("adaptive refinement: equal weights are the polynomial surface; a tolerance with weights is refused") {
  const AdaptiveResult twos = adaptive(weighted_cube(std::vector<double>(8, 2.0)), 3, true);
  const AdaptiveResult plain = adaptive(test::mesh_data(test::cube()), 3, true);
  CHECK(largest_difference(twos.mesh.positions, plain.mesh.positions) < 1e-14);
  CHECK_THROWS_WITH_AS(adaptive(weighted_cube(uneven_weights(8)), 3, true, 1e-3),
                       doctest::Contains("homogeneous coordinates"), OptionError);
}

}  // namespace subdiv
