// Level marks non-manifold edges and vertices as OpenSubdiv's Vtr does (vtr/level.cpp,
// completeTopologyFromFaceVertices), keeps manifold meshes on the fast path, and still
// refuses input no one can refine.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "framework/io/mesh_level.h"
#include "framework/topology/level.h"
#include "framework/util/error.h"
#include "unit/topology/nonmanifold_meshes.h"

using namespace subdiv;
using namespace subdiv::nonmanifold_test;

namespace {

Level level_of(const feature_test::FeatureMesh& m) { return level_from_mesh(m.mesh, m.name); }

int count_marked(const std::vector<std::uint8_t>& marks) {
  int n = 0;
  for (auto m : marks) n += m != 0;
  return n;
}

}  // namespace

TEST_CASE("a manifold mesh stays manifold: no marks, the fast path's arrays") {
  const Level L = level_of(feature_test::grid(3, 3));
  CHECK(L.manifold());
  CHECK(L.edge_face_offsets.empty());
  CHECK(euler_characteristic(L) == 1);  // a disc
}

TEST_CASE("an edge with 3 or 4 faces is non-manifold, and so are its two ends") {
  for (int flaps : {3, 4}) {
    const Level L = level_of(flap_fan(flaps, false));
    CAPTURE(flaps);
    REQUIRE_FALSE(L.manifold());
    const Index hinge = find_edge(L, 0, 1);
    REQUIRE(hinge != kNone);
    CHECK(L.edge_face_count(hinge) == flaps);
    CHECK(L.faces_of_edge(hinge).size() == size_t(flaps));
    CHECK(L.non_manifold_edge(hinge));
    CHECK(count_marked(L.edge_non_manifold) == 1);
    CHECK(L.non_manifold_vertex(0));
    CHECK(L.non_manifold_vertex(1));
    CHECK(count_marked(L.vertex_non_manifold) == 2);
    // Every face and edge is still listed around the hinge's ends.
    CHECK(L.incident_face_count(0) == flaps);
    CHECK(L.valence(0) == 1 + flaps);
    CHECK_FALSE(L.edge_on_boundary(hinge));
    CHECK(L.on_boundary(0));  // its flaps' outer edges have one face
  }
}

TEST_CASE("a bow-tie vertex (two fans) is non-manifold; its edges are not") {
  const Level L = level_of(bow_tie(false));
  const Index shared = feature_test::grid_id(2, 2, 2);
  CHECK(L.non_manifold_vertex(shared));
  CHECK(count_marked(L.vertex_non_manifold) == 1);
  CHECK(count_marked(L.edge_non_manifold) == 0);
  CHECK(L.incident_face_count(shared) == 2);
  CHECK(L.valence(shared) == 4);
}

TEST_CASE("two faces running an edge the same way mark the edge non-manifold") {
  const Level L = level_of(flipped_face(false));
  CHECK(count_marked(L.edge_non_manifold) == 4);  // the flipped quad's four edges
  CHECK(count_marked(L.vertex_non_manifold) == 4);
  for (Index e = 0; e < L.edge_count(); ++e)
    if (L.non_manifold_edge(e)) CHECK(L.edge_face_count(e) == 2);
}

TEST_CASE("a quad that repeats a vertex gets an edge from that vertex to itself, marked") {
  const Level L = level_of(quad_pole());
  const Index pole = L.face(4)[2];
  CHECK(L.face(4)[3] == pole);
  const Index self = L.face_edge_list(4)[2];
  CHECK(L.edge_vertices[2 * self] == pole);
  CHECK(L.edge_vertices[2 * self + 1] == pole);
  CHECK(L.non_manifold_edge(self));
  CHECK(L.non_manifold_vertex(pole));
  // The 3x3 grid's 24 edges (its neighbours still use them all), the pole edge and the
  // diagonal the collapsed quad now closes with.
  CHECK(L.edge_count() == 24 + 2);
}

TEST_CASE("input no one can refine is still refused, naming the problem") {
  feature_test::FeatureMesh m = feature_test::grid(1, 1);
  SUBCASE("an index out of range") {
    m.mesh.face_vertices[2] = 99;
    CHECK_THROWS_WITH_AS(level_of(m), doctest::Contains("names vertex 99"), Error);
  }
  SUBCASE("a face with one vertex") {
    m.mesh.face_offsets = {0, 1};
    m.mesh.face_vertices = {0};
    CHECK_THROWS_WITH_AS(level_of(m), doctest::Contains("needs at least 3"), Error);
  }
  SUBCASE("a NaN coordinate") {
    m.mesh.positions[4] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH_AS(level_of(m), doctest::Contains("non-finite"), Error);
  }
  SUBCASE("a hole naming a face that does not exist") {
    m.mesh.holes = {3};
    CHECK_THROWS_WITH_AS(level_of(m), doctest::Contains("hole 0 names face 3"), Error);
  }
}
