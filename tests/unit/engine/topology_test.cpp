#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include "framework/topology/level_rings.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

// Ring face i lies between ring edges i and i+1: both must be edges of the face.
bool face_has_edge(const Level& L, Index f, Index e) {
  for (Index x : L.face_edge_list(f))
    if (x == e) return true;
  return false;
}

void check_rings_consistent(const Level& L) {
  for (Index v = 0; v < L.vertex_count; ++v) {
    const auto edges = L.ring_edges(v);
    const auto faces = L.ring_faces(v);
    REQUIRE(edges.size() == faces.size() + (L.on_boundary(v) ? 1 : 0));
    for (size_t i = 0; i < faces.size(); ++i) {
      CHECK(face_has_edge(L, faces[i], edges[i]));
      CHECK(face_has_edge(L, faces[i], edges[(i + 1) % edges.size()]));
      // CCW: face i runs out of v along ring edge i.
      const auto verts = L.face(faces[i]);
      const int c = L.vertex_face_corner[L.vertex_face_offsets[v] + i];
      CHECK(verts[c] == v);
      CHECK(L.face_edge_list(faces[i])[c] == edges[i]);
    }
  }
}

}  // namespace

TEST_CASE("cube: counts, Euler characteristic, closed rings") {
  const Level L = test::cube().level();
  CHECK(L.vertex_count == 8);
  CHECK(L.edge_count() == 12);
  CHECK(L.face_count() == 6);
  CHECK(euler_characteristic(L) == 2);
  for (Index v = 0; v < 8; ++v) {
    CHECK(L.valence(v) == 3);
    CHECK_FALSE(L.on_boundary(v));
  }
  for (Index e = 0; e < 12; ++e) CHECK_FALSE(L.edge_on_boundary(e));
  check_rings_consistent(L);
}

TEST_CASE("open grid: boundary edges and vertices, boundary rings start and end on the boundary") {
  const Level L = test::grid(3, 2).level();
  CHECK(L.vertex_count == 12);
  CHECK(L.face_count() == 6);
  CHECK(L.edge_count() == 17);
  CHECK(euler_characteristic(L) == 1);
  int boundary_edges = 0;
  for (Index e = 0; e < L.edge_count(); ++e) boundary_edges += L.edge_on_boundary(e);
  CHECK(boundary_edges == 10);
  CHECK(L.on_boundary(0));
  CHECK(L.valence(0) == 2);
  CHECK(L.incident_face_count(0) == 1);
  CHECK_FALSE(L.on_boundary(5));  // (1,1) is interior
  CHECK(L.valence(5) == 4);
  for (Index v = 0; v < L.vertex_count; ++v)
    if (L.on_boundary(v)) {
      CHECK(L.edge_on_boundary(L.ring_edges(v).front()));
      CHECK(L.edge_on_boundary(L.ring_edges(v).back()));
    }
  check_rings_consistent(L);
}

TEST_CASE("torus and pyramid: Euler characteristic 0 and 2") {
  CHECK(euler_characteristic(test::torus(6, 4).level()) == 0);
  CHECK(euler_characteristic(test::torus(5, 7, true).level()) == 0);
  const Level P = test::pyramid().level();
  CHECK(euler_characteristic(P) == 2);
  check_rings_consistent(P);
}

TEST_CASE("two components, one with a hole") {
  test::Mesh m = test::grid(3, 3);
  // Remove the middle face (index 4) to make a hole, and add a separate triangle.
  m.corners.erase(m.corners.begin() + 16, m.corners.begin() + 20);
  m.offsets.erase(m.offsets.begin() + 5);
  for (size_t i = 5; i < m.offsets.size(); ++i) m.offsets[i] -= 4;
  m.add_vertex(10, 0, 0), m.add_vertex(11, 0, 0), m.add_vertex(10, 1, 0);
  m.add_face({16, 17, 18});
  const Level L = m.level();
  CHECK(L.face_count() == 9);
  CHECK(euler_characteristic(L) == 0 + 1);  // annulus (0) plus a disk (1)
  check_rings_consistent(L);
}

// Non-manifold input is accepted and marked (tests/unit/topology checks it against
// OpenSubdiv); only faces no one can refine are refused.
TEST_CASE("non-manifold input is marked, faces of fewer than 3 corners and bad indices refused") {
  SUBCASE("three faces on one edge") {
    test::Mesh m;
    for (int i = 0; i < 5; ++i) m.add_vertex(i, i * i, 0);
    m.add_face({0, 1, 2}), m.add_face({1, 0, 3}), m.add_face({0, 1, 4});
    const Level L = m.level();
    CHECK(L.non_manifold_edge(find_edge(L, 0, 1)));
    CHECK(L.edge_face_count(find_edge(L, 0, 1)) == 3);
  }
  SUBCASE("bowtie vertex") {
    test::Mesh m;
    for (int i = 0; i < 5; ++i) m.add_vertex(i, i * i, 0);
    m.add_face({0, 1, 2}), m.add_face({0, 3, 4});
    const Level L = m.level();
    CHECK(L.non_manifold_vertex(0));
    CHECK_FALSE(L.non_manifold_vertex(1));
  }
  SUBCASE("inconsistent orientation") {
    test::Mesh m;
    for (int i = 0; i < 4; ++i) m.add_vertex(i, i * i, 0);
    m.add_face({0, 1, 2}), m.add_face({0, 1, 3});
    const Level L = m.level();
    CHECK(L.non_manifold_edge(find_edge(L, 0, 1)));
  }
  SUBCASE("a face with 2 distinct vertices is kept and marked (OpenSubdiv refines it), a bad index refused") {
    test::Mesh m;
    for (int i = 0; i < 3; ++i) m.add_vertex(i, 0, 0);
    m.add_face({0, 1, 1});
    const Level L = m.level();
    CHECK(L.face_count() == 1);
    CHECK(L.non_manifold_edge(find_edge(L, 1, 1)));  // from a vertex to itself
    CHECK(L.non_manifold_edge(find_edge(L, 0, 1)));  // run twice by the face
    CHECK(L.non_manifold_vertex(0));
    test::Mesh b;
    for (int i = 0; i < 3; ++i) b.add_vertex(i, 0, 0);
    b.add_face({0, 1, 7});
    CHECK_THROWS_WITH_AS(b.level(), doctest::Contains("vertex 7"), Error);
  }
}

namespace {

// The general builder (level_general.cpp) on the same faces: for a manifold mesh it numbers
// edges as the fast path must (in order of each edge's first corner) and orders rings alike.
Level general_level(const test::Mesh& m) {
  Level L;
  L.vertex_count = m.vertex_count;
  L.face_offsets.assign(m.offsets.begin(), m.offsets.end());
  L.face_vertices.assign(m.corners.begin(), m.corners.end());
  identify_edges_general(L);
  complete_general_level(L);
  return L;
}

void check_same_level(const Level& a, const Level& b) {
  CHECK(a.face_edges == b.face_edges);
  CHECK(a.edge_vertices == b.edge_vertices);
  CHECK(a.edge_faces == b.edge_faces);
  CHECK(a.vertex_ring_offsets == b.vertex_ring_offsets);
  CHECK(a.vertex_edges == b.vertex_edges);
  CHECK(a.vertex_face_offsets == b.vertex_face_offsets);
  CHECK(a.vertex_faces == b.vertex_faces);
  CHECK(a.vertex_face_corner == b.vertex_face_corner);
  CHECK(a.vertex_on_boundary == b.vertex_on_boundary);
  CHECK(a.edge_non_manifold.empty());
  CHECK(a.vertex_non_manifold.empty());
}

// A mesh large enough for several parallel chunks (level_manifold.cpp): boundaries, holes,
// triangles and quads, vertices of valence 2 to 8.
test::Mesh holed_grid(int n) {
  test::Mesh m = test::grid(n, n, false);
  test::Mesh out;
  out.vertex_count = m.vertex_count, out.positions = m.positions;
  for (Index f = 0; f + 1 < Index(m.offsets.size()); ++f) {
    const int i = f % n, j = f / n;
    if (i % 7 == 3 && j % 5 == 2) continue;  // a hole
    std::vector<Index> q(m.corners.begin() + m.offsets[f], m.corners.begin() + m.offsets[f + 1]);
    if ((i + j) % 3 == 0) {
      out.add_face({q[0], q[1], q[2]}), out.add_face({q[0], q[2], q[3]});
    } else {
      out.add_face({q[0], q[1], q[2], q[3]});
    }
  }
  return out;
}

}  // namespace

TEST_CASE("the parallel manifold builder equals the general builder, on one thread and on two") {
  const test::Mesh meshes[] = {test::cube(), test::grid(3, 2), test::torus(150, 120), test::torus(90, 70, true),
                               holed_grid(160)};
  for (const test::Mesh& m : meshes) {
    const Level reference = general_level(m);
    REQUIRE(reference.edge_non_manifold.empty());
    for (int threads : {1, 2}) {
      CAPTURE(threads);
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
      check_same_level(m.level(), reference);
    }
  }
}

namespace {

// Two meshes joined at one vertex: b's vertex `b_shared` becomes a's `a_shared`.
test::Mesh joined_at_vertex(const test::Mesh& a, Index a_shared, const test::Mesh& b, Index b_shared) {
  test::Mesh out = a;
  auto id = [&](Index v) { return v == b_shared ? a_shared : a.vertex_count + v - (v > b_shared ? 1 : 0); };
  for (Index v = 0; v < b.vertex_count; ++v)
    if (v != b_shared) out.add_vertex(b.positions[3 * v], b.positions[3 * v + 1], b.positions[3 * v + 2]);
  for (size_t f = 0; f + 1 < b.offsets.size(); ++f) {
    for (Index c = b.offsets[f]; c < b.offsets[f + 1]; ++c) out.corners.push_back(id(b.corners[c]));
    out.offsets.push_back(Index(out.corners.size()));
  }
  return out;
}

void check_same_marks(const Level& a, const Level& b) {
  CHECK(a.edge_non_manifold == b.edge_non_manifold);
  CHECK(a.vertex_non_manifold == b.vertex_non_manifold);
  CHECK(a.edge_face_offsets == b.edge_face_offsets);
  CHECK(a.edge_face_list == b.edge_face_list);
}

}  // namespace

// The fast path leaves a vertex with more than one fan to the general builder: its ring
// walk comes back to its start (closed fans) or reaches the boundary (open fans) before it
// has seen every corner. Large grids put the two boundary corners of the shared vertex in
// different parallel chunks.
TEST_CASE("vertices where fans meet go to the general builder, on one thread and on two") {
  const test::Mesh grid = test::grid(200, 200), octahedron = test::octahedron();
  const Index grid_corner = 200 * 201 + 200;  // the far corner, on the boundary
  test::Mesh flap;
  for (int i = 0; i < 3; ++i) flap.add_vertex(i, 1 + i, 2);
  flap.add_face({0, 1, 2});
  const test::Mesh cases[] = {joined_at_vertex(grid, grid_corner, grid, 0),           // two open fans
                              joined_at_vertex(octahedron, 4, octahedron, 5),         // two closed fans
                              joined_at_vertex(octahedron, 4, flap, 0),               // closed and open
                              joined_at_vertex(grid, grid_corner, octahedron, 0)};
  const Index shared[] = {grid_corner, 4, 4, grid_corner};
  for (size_t i = 0; i < std::size(cases); ++i) {
    CAPTURE(i);
    const Level reference = general_level(cases[i]);
    REQUIRE(reference.non_manifold_vertex(shared[i]));
    for (int threads : {1, 2}) {
      CAPTURE(threads);
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
      const Level L = cases[i].level();
      CHECK(L.non_manifold_vertex(shared[i]));
      CHECK(L.face_edges == reference.face_edges);
      CHECK(L.vertex_edges == reference.vertex_edges);
      CHECK(L.vertex_faces == reference.vertex_faces);
      CHECK(L.vertex_on_boundary == reference.vertex_on_boundary);
      check_same_marks(L, reference);
    }
  }
}

// A hostile file's single face of the largest size (OpenSubdiv's limit, 65,535 corners):
// checking it for repeated vertices must not take k^2 steps, and its topology is a disk's
// (two of them back to back: a sphere's). One corner more is refused by name.
TEST_CASE("a face of 65,535 corners: a disk, and a repeated vertex among them is found; larger ones refused") {
  constexpr Index n = kMaxFaceSize;
  std::vector<Index> offsets{0, n}, corners(n);
  for (Index i = 0; i < n; ++i) corners[i] = i;
  const Level disk = build_level(n, offsets, corners);
  CHECK(disk.edge_count() == n);
  CHECK(euler_characteristic(disk) == 1);
  CHECK(disk.on_boundary(n / 2));
  CHECK(disk.valence(n / 2) == 2);
  // Two such faces back to back: a sphere, every vertex of valence 2 between the two faces.
  std::vector<Index> both_offsets{0, n, 2 * n}, both(corners);
  both.insert(both.end(), corners.rbegin(), corners.rend());
  const Level pillow = build_level(n, both_offsets, both);
  CHECK(euler_characteristic(pillow) == 2);
  CHECK_FALSE(pillow.on_boundary(n / 2));
  CHECK(pillow.incident_face_count(n / 2) == 2);
  corners[n - 1] = n / 2;  // vertex n/2 twice: the general builder marks it
  const Level pinched = build_level(n, offsets, corners);
  CHECK(pinched.non_manifold_vertex(n / 2));
  corners.push_back(n - 1);
  offsets.back() = n + 1;
  CHECK_THROWS_WITH_AS(build_level(n, offsets, corners),
                       doctest::Contains("face 0 has 65536 vertices; faces may have at most 65535"), Error);
}
