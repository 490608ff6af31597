// The bundled example meshes are what the README promises: closed meshes have Euler
// characteristic 2 (torus 0), every face is oriented consistently, tags are where stated.
#include <map>
#include <set>
#include <utility>

#include "framework/io/mesh_read.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

const fs::path kExamples = fs::path(SUBDIV_SOURCE_DIR) / "examples" / "meshes";

struct EdgeCensus {
  long edges = 0;
  bool consistent = true;  // every directed edge used at most once
  bool closed = true;      // every edge has two faces
};

EdgeCensus census(const MeshData& m) {
  std::map<std::pair<Index, Index>, int> directed;
  for (Index f = 0; f < m.face_count(); ++f)
    for (Index k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k) {
      const Index next = k + 1 == m.face_offsets[f + 1] ? m.face_offsets[f] : k + 1;
      ++directed[{m.face_vertices[k], m.face_vertices[next]}];
    }
  EdgeCensus c;
  for (const auto& [edge, count] : directed) {
    c.consistent = c.consistent && count == 1;
    const bool twin = directed.count({edge.second, edge.first}) != 0;
    c.closed = c.closed && twin;
    c.edges += twin ? (edge.first < edge.second) : 1;
  }
  return c;
}

// Six times the enclosed volume: positive when faces are CCW seen from outside.
double signed_volume(const MeshData& m) {
  double volume = 0;
  auto p = [&](Index v) { return &m.positions[3 * v]; };
  for (Index f = 0; f < m.face_count(); ++f) {
    const double* a = p(m.face_vertices[m.face_offsets[f]]);
    for (Index k = m.face_offsets[f] + 1; k + 1 < m.face_offsets[f + 1]; ++k) {
      const double *b = p(m.face_vertices[k]), *c = p(m.face_vertices[k + 1]);
      volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
  }
  return volume;
}

}  // namespace

TEST_CASE("example meshes: counts, Euler characteristic and orientation") {
  struct Expect {
    const char* file;
    Index vertices, faces;
    long euler;
    bool closed;
  };
  const Expect expected[] = {
      {"cube.obj", 8, 6, 2, true},           {"cube-creased.obj", 8, 6, 2, true},
      {"tetrahedron.obj", 4, 4, 2, true},    {"octahedron.obj", 6, 8, 2, true},
      {"pyramid.obj", 5, 5, 2, true},        {"torus-quads.obj", 48, 48, 0, true},
      {"plane-with-hole.obj", 24, 12, 0, false},
  };
  for (const Expect& e : expected) {
    CAPTURE(e.file);
    const MeshData m = read_mesh(kExamples / e.file);
    CHECK(m.vertex_count() == e.vertices);
    CHECK(m.face_count() == e.faces);
    const EdgeCensus c = census(m);
    CHECK(c.consistent);
    CHECK(c.closed == e.closed);
    CHECK(m.vertex_count() - c.edges + m.face_count() == e.euler);
    if (e.closed) CHECK(signed_volume(m) > 0);
    std::set<Index> used(m.face_vertices.begin(), m.face_vertices.end());
    CHECK(used.size() == size_t(m.vertex_count()));  // no isolated vertices
  }
}

TEST_CASE("example meshes: pyramid mixes polygons, torus is regular") {
  const MeshData pyramid = read_mesh(kExamples / "pyramid.obj");
  std::multiset<Index> sizes;
  for (Index f = 0; f < pyramid.face_count(); ++f)
    sizes.insert(pyramid.face_offsets[f + 1] - pyramid.face_offsets[f]);
  CHECK(sizes == std::multiset<Index>{3, 3, 3, 3, 4});

  const MeshData torus = read_mesh(kExamples / "torus-quads.obj");
  std::vector<int> valence(torus.vertex_count(), 0);
  for (Index v : torus.face_vertices) ++valence[v];
  for (int n : valence) CHECK(n == 4);
}

TEST_CASE("example meshes: cube-creased tags the top edges and one corner") {
  const MeshData m = read_mesh(kExamples / "cube-creased.obj");
  REQUIRE(m.creases.size() == 4);
  for (const CreaseTag& c : m.creases) {
    CHECK(c.sharpness == 10.0);
    CHECK(m.positions[3 * c.v0 + 2] == 0.5);  // both ends on the top face z = 0.5
    CHECK(m.positions[3 * c.v1 + 2] == 0.5);
  }
  REQUIRE(m.corners.size() == 1);
  CHECK(m.positions[3 * m.corners[0].v + 2] == -0.5);
}
