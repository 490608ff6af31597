// The sqrt3 split on non-manifold input (framework/refine/sqrt3_split.cpp): a non-manifold
// edge is not flipped but kept as a crease, like a boundary edge in Kobbelt's rule. Checks:
// a valid mesh (no new non-manifold edges, no degenerate faces, the Euler characteristic of
// the input), the face and vertex counts of the rule, one warning per level, and that the
// mesh away from the non-manifold edge refines as it would without it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "framework/engine/refiner.h"
#include "framework/io/mesh_level.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "unit/topology/nonmanifold_meshes.h"

using namespace subdiv;
using namespace subdiv::nonmanifold_test;

namespace {

Hierarchy sqrt3_refined(const FeatureMesh& m, int levels) {
  RefineOptions options;
  options.levels = levels;
  return refine(*load_scheme("sqrt3"), level_from_mesh(m.mesh, m.name), options);
}

Index count_non_manifold_edges(const Level& L) {
  Index n = 0;
  for (Index e = 0; e < L.edge_count(); ++e) n += L.non_manifold_edge(e);
  return n;
}

bool has_degenerate_face(const Level& L) {
  for (Index f = 0; f < L.face_count(); ++f) {
    const auto c = L.face(f);
    if (c.size() != 3 || c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) return true;
  }
  return false;
}

// The mesh `m` with two more triangles hinged on its edge (a, b), the first on one side and
// the second on the other, so the edge has four faces.
FeatureMesh with_flaps_on(FeatureMesh m, Index a, Index b) {
  const Index up = m.add_vertex(0.3, 0.4, 1.1), down = m.add_vertex(0.2, 0.6, -0.9);
  m.add_face({a, b, up});
  m.add_face({b, a, down});
  m.name += " with two flaps";
  return m;
}

}  // namespace

TEST_CASE("sqrt3 on non-manifold meshes: a valid mesh of the input's topology, at levels 1-3") {
  for (const auto& m : {flap_fan(3, true), flap_fan(4, true), bow_tie(true), flipped_face(true)}) {
    CAPTURE(m.name);
    const Hierarchy h = sqrt3_refined(m, 3);
    const Level& base = h.levels[0];
    for (int l = 1; l <= 3; ++l) {
      CAPTURE(l);
      const Level& parent = h.levels[size_t(l) - 1];
      const Level& child = h.levels[size_t(l)];
      CHECK_FALSE(has_degenerate_face(child));
      CHECK(euler_characteristic(child) == euler_characteristic(base));
      // Every step makes three triangles of each (these inputs have at most one feature edge
      // per triangle where it trisects).
      CHECK(child.face_count() == 3 * parent.face_count());
      // No edge becomes non-manifold that was not: a kept edge stays one (odd steps), a
      // trisected one becomes three (even steps); every other edge has one face or two
      // that run it opposite ways (what build_level checks before it leaves an edge unmarked).
      CHECK(count_non_manifold_edges(child) == count_non_manifold_edges(parent) * (l % 2 == 0 ? 3 : 1));
      // Vertices: one per face in odd steps; in even steps one per face without a feature
      // edge and two per feature edge (here every triangle of the odd step's output has at most one).
      if (l % 2 == 1) CHECK(child.vertex_count == parent.vertex_count + parent.face_count());
      CHECK(std::isfinite(interpolate(h, l, m.mesh.positions, 3).back()));
    }
    // One warning per level, each naming the non-manifold edges it kept.
    REQUIRE(h.warnings.size() == 3);
    for (int l = 1; l <= 3; ++l) {
      CHECK(h.warnings[size_t(l) - 1].find(fmt::format("level {}: the sqrt3 split", l)) == 0);
      CHECK(h.warnings[size_t(l) - 1].find("non-manifold edge(s) as sharp creases") != std::string::npos);
    }
  }
}

TEST_CASE("sqrt3 keeps a fan's hinge: 3 triangles on it at odd levels, its three thirds at even ones") {
  const auto m = flap_fan(3, true);
  const Hierarchy h = sqrt3_refined(m, 2);
  CHECK(count_non_manifold_edges(h.levels[0]) == 1);
  const Level& odd = h.levels[1];
  const Index hinge = find_edge(odd, 0, 1);
  REQUIRE(hinge != kNone);
  CHECK(odd.edge_face_count(hinge) == 3);
  CHECK(odd.edge_sharp(hinge) >= 10.f);
  const Level& even = h.levels[2];
  CHECK(find_edge(even, 0, 1) == kNone);
  for (Index e = 0; e < even.edge_count(); ++e)
    if (even.non_manifold_edge(e)) CHECK(even.edge_face_count(e) == 3);
  // The hinge's ends are corners (infinitely sharp, features/base_tags.h) and stay put.
  const auto p = interpolate(h, 2, m.mesh.positions, 3);
  for (int c = 0; c < 6; ++c) CHECK(p[size_t(c)] == m.mesh.positions[size_t(c)]);
}

TEST_CASE("sqrt3: the mesh away from a non-manifold edge refines as without it") {
  const FeatureMesh plain = feature_test::grid(8, 8, true);
  const Index a = feature_test::grid_id(1, 1, 8), b = feature_test::grid_id(2, 2, 8);
  const FeatureMesh flapped = with_flaps_on(plain, a, b);
  const int levels = 3;
  const Hierarchy hp = sqrt3_refined(plain, levels), hf = sqrt3_refined(flapped, levels);
  CHECK(hp.warnings.empty());
  REQUIRE(hf.warnings.size() == size_t(levels));
  // The children of base vertices keep their numbers at every level (refine/splitter.h), so
  // base vertex v is child v on both sides; compare those at grid distance 4 or more from
  // the hinge, beyond the reach of three sqrt3 steps.
  const auto p = interpolate(hp, levels, plain.mesh.positions, 3);
  const auto f = interpolate(hf, levels, flapped.mesh.positions, 3);
  int compared = 0, near_moved = 0;
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i) {
      const Index v = feature_test::grid_id(i, j, 8);
      double d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(p[3 * size_t(v) + c] - f[3 * size_t(v) + c]));
      if (std::min(std::max(std::abs(i - 1), std::abs(j - 1)), std::max(std::abs(i - 2), std::abs(j - 2))) >= 4) {
        CAPTURE(v);
        CHECK(d < 1e-12);
        ++compared;
      } else {
        near_moved += d > 1e-9;
      }
    }
  CHECK(compared > 20);
  CHECK(near_moved > 0);  // the crease does change the surface near it
}

TEST_CASE("sqrt3 on faces with fewer than 3 distinct vertices: every new point used, a warning per level") {
  // No Euler characteristic here: it changes in the first trisecting step, where the edges
  // from a vertex to itself are cut (the split rebuilds each level's edges from its faces,
  // which need not count such edges as the input did). What must hold: a valid level with
  // no stray vertex (an edge from a vertex to itself uses both its trisection points) and
  // finite positions.
  const auto m = collapsed_faces(true);
  const Hierarchy h = sqrt3_refined(m, 3);
  for (int l = 1; l <= 3; ++l) {
    CAPTURE(l);
    const Level& L = h.levels[size_t(l)];
    std::vector<char> used(size_t(L.vertex_count), 0);
    for (Index v : L.face_vertices) used[size_t(v)] = 1;
    CHECK(std::count(used.begin(), used.end(), 0) == 0);
    for (double x : interpolate(h, l, m.mesh.positions, 3)) REQUIRE(std::isfinite(x));
  }
  CHECK(h.warnings.size() == 3);
  // The collapsed triangle (a, b, b) runs a-b once each way, so its face point p gets one
  // child triangle each way: (a, b, p) and (b, a, p).
  const Level& base = h.levels[0];
  const Index collapsed = base.face_count() - 2;
  const Index a = base.face(collapsed)[0], b = base.face(collapsed)[1];
  int forward = 0, backward = 0;
  const Level& child = h.levels[1];
  for (Index f = 0; f < child.face_count(); ++f) {
    if (h.origins[0].parent_face[size_t(f)] != collapsed) continue;
    const auto c = child.face(f);
    for (int i = 0; i < 3; ++i) {
      forward += c[i] == a && c[(i + 1) % 3] == b;
      backward += c[i] == b && c[(i + 1) % 3] == a;
    }
  }
  CHECK(forward == 1);
  CHECK(backward == 1);
}
