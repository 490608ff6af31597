// index_corners (framework/topology/corner_index.cpp) sorts corners by vertex in parallel
// chunks; both level builders read its order, so it must equal a plain serial counting sort
// for any number of chunks and threads, and the slot heads the manifold builder asks for
// must be each corner's next vertex.
#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include "framework/topology/level_rings.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

Level faces_only(Index vertex_count, const std::vector<Index>& offsets, const std::vector<Index>& corners) {
  Level L;
  L.vertex_count = vertex_count;
  L.face_offsets.assign(offsets.begin(), offsets.end());
  L.face_vertices.assign(corners.begin(), corners.end());
  return L;
}

// The reference: each vertex's corners in corner order, by appending.
void check_against_serial(const Level& L, const CornerIndex& ci) {
  std::vector<std::vector<Index>> around(size_t(L.vertex_count));
  std::vector<Index> face(size_t(L.corner_count()));
  for (Index f = 0; f < L.face_count(); ++f)
    for (Index c = L.face_offsets[f]; c < L.face_offsets[f + 1]; ++c) face[c] = f, around[L.face_vertices[c]].push_back(c);
  REQUIRE(ci.face.size() == face.size());
  CHECK(std::equal(face.begin(), face.end(), ci.face.begin()));
  REQUIRE(ci.vertex_offsets.size() == size_t(L.vertex_count) + 1);
  REQUIRE(ci.vertex_corners.size() == size_t(L.corner_count()));
  CHECK(ci.vertex_offsets[0] == 0);
  bool same = true;
  for (Index v = 0; v < L.vertex_count; ++v) {
    same = same && ci.vertex_offsets[v + 1] - ci.vertex_offsets[v] == Index(around[v].size());
    same = same && std::equal(around[v].begin(), around[v].end(), ci.vertex_corners.begin() + ci.vertex_offsets[v]);
  }
  CHECK(same);
  // With slot heads: each slot's corner's edge runs to the next corner's vertex.
  if (ci.heads.empty()) return;
  REQUIRE(ci.heads.size() == size_t(L.corner_count()));
  bool heads_right = true;
  for (size_t i = 0; i < ci.heads.size(); ++i) {
    const Index c = ci.vertex_corners[i];
    heads_right = heads_right && ci.heads[i] == L.face_vertices[next_corner(L, face[c], c)];
  }
  CHECK(heads_right);
}

// Meshes with what a counting sort can get wrong: boundaries, a vertex with two fans and
// one on a three-face edge, isolated vertices at both ends and between, a face of 1,000
// corners, a face that repeats a vertex, and a torus big enough for several default chunks.
std::vector<Level> meshes() {
  std::vector<Level> out;
  const test::Mesh grid = test::grid(40, 30, true);
  out.push_back(faces_only(grid.vertex_count, grid.offsets, grid.corners));
  // A bow-tie (vertex 0 has two fans) and three triangles on edge (0, 1); vertices 7 and 9
  // are used by no face, nor are the last ones.
  out.push_back(faces_only(14, {0, 3, 6, 9, 12, 15, 19}, {0, 1, 2, 0, 3, 4, 0, 1, 5, 1, 0, 6, 8, 10, 11, 2, 2, 11, 12}));
  {  // a 1,000-gon capped by a fan, with 50 isolated vertices first
    std::vector<Index> offsets{0}, corners;
    const Index n = 1000, first = 50, apex = first + n;
    for (Index i = 0; i < n; ++i) corners.push_back(first + i);
    offsets.push_back(n);
    for (Index i = 0; i < n; ++i) corners.insert(corners.end(), {first + (i + 1) % n, first + i, apex}), offsets.push_back(Index(corners.size()));
    out.push_back(faces_only(apex + 1, offsets, corners));
  }
  const test::Mesh torus = test::torus(300, 250);
  out.push_back(faces_only(torus.vertex_count, torus.offsets, torus.corners));
  out.push_back(faces_only(0, {0}, {}));
  return out;
}

}  // namespace

TEST_CASE("index_corners equals a serial counting sort for any number of chunks and threads, slot heads included") {
  for (const Level& L : meshes()) {
    CAPTURE(L.corner_count());
    for (Index chunks : {1, 2, 3, 5, 64}) {
      CAPTURE(chunks);
      check_against_serial(L, index_corners(L, chunks));
      const CornerIndex with_heads = index_corners(L, chunks, SlotHeads::kYes);
      CHECK(with_heads.heads.size() == size_t(L.corner_count()));
      check_against_serial(L, with_heads);
    }
    for (int threads : {1, 2, 3}) {
      CAPTURE(threads);
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
      check_against_serial(L, index_corners(L));
      check_against_serial(L, index_corners(L, SlotHeads::kYes));
    }
  }
}
