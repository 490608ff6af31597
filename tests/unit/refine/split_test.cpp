#include <cmath>
#include <doctest/doctest.h>
#include <tbb/global_control.h>
#include <set>

#include "framework/refine/splitter.h"
#include "support/test_meshes.h"

using namespace subdiv;

TEST_CASE("quad split counts: V' = V+E+F, F' = corners, E' = 2E + corners; Euler kept") {
  for (const auto& mesh : {test::cube(), test::pyramid(), test::grid(3, 2), test::torus(5, 4)}) {
    Level L = mesh.level();
    for (int level = 0; level < 3; ++level) {
      SplitResult r = split_quad(L);
      CHECK(r.child.vertex_count == L.vertex_count + L.edge_count() + L.face_count());
      CHECK(r.child.face_count() == L.corner_count());
      CHECK(r.child.edge_count() == 2 * L.edge_count() + L.corner_count());
      CHECK(euler_characteristic(r.child) == euler_characteristic(L));
      CHECK(r.child.all_faces_have_size(4));
      CHECK(r.origins.kind[L.vertex_count] == OriginKind::Edge);
      CHECK(r.origins.kind.back() == OriginKind::Face);
      L = std::move(r.child);
    }
  }
}

TEST_CASE("triangle split counts: V' = V+E, F' = 4F, E' = 2E + 3F; Euler kept") {
  for (const auto& mesh : {test::octahedron(), test::grid(2, 3, true), test::torus(4, 5, true)}) {
    Level L = mesh.level();
    for (int level = 0; level < 3; ++level) {
      SplitResult r = split_triangle(L);
      CHECK(r.child.vertex_count == L.vertex_count + L.edge_count());
      CHECK(r.child.face_count() == 4 * L.face_count());
      CHECK(r.child.edge_count() == 2 * L.edge_count() + 3 * L.face_count());
      CHECK(euler_characteristic(r.child) == euler_characteristic(L));
      L = std::move(r.child);
    }
  }
}

TEST_CASE("boundary vertices stay on the boundary after splitting") {
  const Level L = test::grid(2, 2).level();
  const SplitResult r = split_quad(L);
  for (Index v = 0; v < L.vertex_count; ++v) CHECK(r.child.on_boundary(v) == L.on_boundary(v));
  for (Index e = 0; e < L.edge_count(); ++e)
    CHECK(r.child.on_boundary(L.vertex_count + e) == L.edge_on_boundary(e));
}

namespace {

// The child level built directly by a split must be the level the generic builder makes
// from the same faces: same edges (as vertex pairs with the same faces), same CCW rings.
void check_same_topology(const Level& direct) {
  const Level generic = build_level(direct.vertex_count, direct.face_offsets, direct.face_vertices);
  REQUIRE(direct.edge_count() == generic.edge_count());
  for (Index e = 0; e < direct.edge_count(); ++e) {
    const Index a = direct.edge_vertices[2 * e], b = direct.edge_vertices[2 * e + 1];
    const Index g = find_edge(generic, a, b);
    REQUIRE(g != kNone);
    CHECK(direct.edge_on_boundary(e) == generic.edge_on_boundary(g));
    // Slot 0 is the face running a -> b in both.
    const bool same_direction = generic.edge_vertices[2 * g] == a;
    CHECK(direct.edge_faces[2 * e] == generic.edge_faces[2 * g + (same_direction ? 0 : 1)]);
  }
  for (Index f = 0; f < direct.face_count(); ++f)
    for (int i = 0; i < direct.face_size(f); ++i) {
      const Index e = direct.face_edge_list(f)[i];
      const Index a = direct.face(f)[i], b = direct.face(f)[(i + 1) % direct.face_size(f)];
      CHECK(((direct.edge_vertices[2 * e] == a && direct.edge_vertices[2 * e + 1] == b) ||
             (direct.edge_vertices[2 * e] == b && direct.edge_vertices[2 * e + 1] == a)));
    }
  for (Index v = 0; v < direct.vertex_count; ++v) {
    CHECK(direct.on_boundary(v) == generic.on_boundary(v));
    const auto df = direct.ring_faces(v), gf = generic.ring_faces(v);
    REQUIRE(df.size() == gf.size());
    // The same cyclic order (interior rings may start anywhere; boundary rings must agree).
    size_t shift = 0;
    while (shift < gf.size() && gf[shift] != df[0]) ++shift;
    REQUIRE(shift < gf.size());
    if (direct.on_boundary(v)) CHECK(shift == 0);
    for (size_t i = 0; i < df.size(); ++i) {
      CHECK(df[i] == gf[(i + shift) % gf.size()]);
      CHECK(direct.vertex_face_corner[direct.vertex_face_offsets[v] + i] ==
            generic.vertex_face_corner[generic.vertex_face_offsets[v] + (i + shift) % gf.size()]);
    }
    const auto de = direct.ring_edges(v), ge = generic.ring_edges(v);
    REQUIRE(de.size() == ge.size());
    for (size_t i = 0; i < de.size(); ++i)
      CHECK(direct.other_end(de[i], v) == generic.other_end(ge[(i + shift) % ge.size()], v));
  }
}

}  // namespace

TEST_CASE("direct child topology of the primal splits equals the generic builder's") {
  for (const auto& mesh : {test::cube(), test::pyramid(), test::grid(3, 2), test::torus(5, 4)}) {
    Level L = mesh.level();
    for (int level = 0; level < 2; ++level) {
      SplitResult r = split_quad(L);
      check_same_topology(r.child);
      L = std::move(r.child);
    }
  }
  for (const auto& mesh : {test::octahedron(), test::grid(2, 3, true), test::torus(4, 5, true)}) {
    Level L = mesh.level();
    for (int level = 0; level < 2; ++level) {
      SplitResult r = split_triangle(L);
      check_same_topology(r.child);
      L = std::move(r.child);
    }
  }
}

// Child ring offsets are counted in blocks of 65,536 edges (primal_topology.cpp): grids
// with over 100,000 edges, whose boundary edges fall in several blocks.
TEST_CASE("direct child topology of the primal splits equals the generic builder's on meshes of several blocks, 1 and 2 threads") {
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    check_same_topology(split_quad(test::grid(260, 200).level()).child);
    check_same_topology(split_triangle(test::grid(200, 200, true).level()).child);
  }
}

namespace {

// The runs a split declares (ChildOrigins::runs) must be what its origin arrays say: every
// child of a kind is first + its element, and every element of the kind has one.
void check_declared_runs(const Level& parent, const ChildOrigins& o) {
  REQUIRE(o.runs.has_value());
  const Index elements[4] = {parent.vertex_count, parent.edge_count(), parent.face_count(), parent.corner_count()};
  Index seen[4] = {};
  for (Index c = 0; c < Index(o.kind.size()); ++c) {
    const int kind = int(o.kind[c]);
    REQUIRE(o.runs->first[kind] != kNone);
    CHECK(c == o.runs->first[kind] + o.parent[c]);
    ++seen[kind];
  }
  for (int kind = 0; kind < 4; ++kind) {
    CHECK(seen[kind] == o.runs->count[kind]);
    CHECK((seen[kind] == 0 || seen[kind] == elements[kind]));
  }
}

}  // namespace

TEST_CASE("the primal splits declare their children's runs as their origins lay them out") {
  for (const auto& mesh : {test::cube(), test::grid(3, 2), test::torus(5, 4)}) {
    const Level L = mesh.level();
    check_declared_runs(L, split_quad(L).origins);
    check_declared_runs(L, split_quad_faces(L).origins);
  }
  for (const auto& mesh : {test::octahedron(), test::grid(2, 3, true)}) {
    const Level L = mesh.level();
    check_declared_runs(L, split_triangle(L).origins);
    check_declared_runs(L, split_triangle_faces(L).origins);
  }
}

namespace {

// A 300-gon capping a prism (a CAD cylinder's end): more corners than 8 bits can number.
test::Mesh capped_prism(int k) {
  test::Mesh m;
  for (int ring = 0; ring < 2; ++ring)
    for (int i = 0; i < k; ++i) m.add_vertex(std::cos(2 * M_PI * i / k), std::sin(2 * M_PI * i / k), ring);
  std::vector<Index> bottom(k), top(k);
  for (int i = 0; i < k; ++i) bottom[i] = k - 1 - i, top[i] = k + i;
  m.corners.insert(m.corners.end(), bottom.begin(), bottom.end()), m.offsets.push_back(Index(m.corners.size()));
  m.corners.insert(m.corners.end(), top.begin(), top.end()), m.offsets.push_back(Index(m.corners.size()));
  for (int i = 0; i < k; ++i) m.add_face({i, (i + 1) % k, k + (i + 1) % k, k + i});
  return m;
}

}  // namespace

TEST_CASE("faces of more than 256 corners: ring corners and corner origins keep their place") {
  const Level L = capped_prism(300).level();
  for (Index v = 0; v < L.vertex_count; ++v)
    for (int i = 0; i < L.incident_face_count(v); ++i)
      CHECK(L.face(L.ring_faces(v)[i])[L.vertex_face_corner[L.vertex_face_offsets[v] + i]] == v);
  check_same_topology(split_quad(L).child);
  // The dual split makes one child per corner, named by (face, corner): all distinct.
  const ChildOrigins o = split_dual(L).origins;
  std::set<std::pair<Index, int>> corners;
  for (size_t c = 0; c < o.kind.size(); ++c) {
    REQUIRE(o.kind[c] == OriginKind::Corner);
    CHECK(o.local[c] < L.face_size(o.parent[c]));
    corners.insert({o.parent[c], o.local[c]});
  }
  CHECK(corners.size() == size_t(L.corner_count()));
}
