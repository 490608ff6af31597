// Cutting a mesh into pieces (engine/face_partition.h) and a piece out of it
// (engine/mesh_pieces.h).
#include <doctest/doctest.h>

#include <algorithm>
#include <set>

#include "framework/engine/face_partition.h"
#include "framework/engine/mesh_pieces.h"
#include "framework/util/error.h"
#include "piece_meshes.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

std::vector<int> piece_sizes(const std::vector<int>& owner, int pieces) {
  std::vector<int> count(pieces, 0);
  for (int p : owner) ++count.at(p);
  return count;
}

}  // namespace

TEST_CASE("pieces cover every face, none is empty, and face counts are balanced") {
  const Mesh m = torus(24, 16);
  const Level L = m.level();
  for (int pieces = 1; pieces <= 9; ++pieces) {
    const FacePartition cut = partition_faces(L, m.positions, pieces);
    const std::vector<int> count = piece_sizes(cut.face_piece, pieces);
    const double mean = double(L.face_count()) / pieces;
    CAPTURE(pieces);
    CAPTURE(cut.method);
    CHECK(*std::min_element(count.begin(), count.end()) > 0);
    // METIS keeps every piece within 3% of the mean (its default imbalance), plus a face.
    CHECK(*std::max_element(count.begin(), count.end()) <= mean * 1.03 + 1);
  }
}

TEST_CASE("the curve split gives runs whose sizes differ by one face at most") {
  const Mesh m = bumpy_sheet(7, true);
  const Level L = m.level();
  for (int pieces = 1; pieces <= 7; ++pieces) {
    const std::vector<int> count = piece_sizes(partition_faces_along_curve(L, m.positions, pieces), pieces);
    CHECK(*std::max_element(count.begin(), count.end()) - *std::min_element(count.begin(), count.end()) <= 1);
  }
}

TEST_CASE("a piece count outside 1 .. faces is refused") {
  const Mesh m = cube();
  CHECK_THROWS_WITH_AS(partition_faces(m.level(), m.positions, 0), doctest::Contains("1 to 6"), Error);
  CHECK_THROWS_WITH_AS(partition_faces(m.level(), m.positions, 7), doctest::Contains("1 to 6"), Error);
}

TEST_CASE("a piece holds its faces and the rings around them, with the base mesh's tags") {
  const int n = 6;
  const Mesh m = bumpy_sheet(n, false);
  const Level base = featured_level(m, n);
  std::vector<int> owner(base.face_count(), 1);
  owner[base.face_count() / 2] = 0;
  const MeshPiece lone = cut_piece(base, owner, 0, 0);
  CHECK(lone.level.face_count() == 1);
  const MeshPiece ringed = cut_piece(base, owner, 0, 1);
  // Ring 1: every face sharing a vertex with the piece's face.
  std::set<Index> expected;
  for (Index v : base.face(base.face_count() / 2))
    for (Index f : base.ring_faces(v)) expected.insert(f);
  CHECK(std::set<Index>(ringed.base_face.begin(), ringed.base_face.end()) == expected);
  for (Index e = 0; e < ringed.level.edge_count(); ++e) {
    const Index a = ringed.base_vertex[ringed.level.edge_vertices[2 * e]];
    const Index b = ringed.base_vertex[ringed.level.edge_vertices[2 * e + 1]];
    CHECK(ringed.level.edge_sharp(e) == base.edge_sharp(find_edge(base, a, b)));
  }
  for (Index v = 0; v < ringed.level.vertex_count; ++v)
    CHECK(ringed.level.vertex_sharp(v) == base.vertex_sharp(ringed.base_vertex[v]));
  CHECK_THROWS_AS(cut_piece(base, owner, 2, 1), Error);
}

TEST_CASE("pieces of a manifold mesh are manifold: pinched ghost rings are filled") {
  const Mesh m = torus(10, 8, true);
  const Level base = m.level();
  std::vector<int> scattered(base.face_count());
  for (Index f = 0; f < base.face_count(); ++f) scattered[f] = int((f * 7919) % 5);
  int filled = 0;
  for (int piece = 0; piece < 5; ++piece)
    for (int rings = 0; rings <= 2; ++rings) {
      const MeshPiece cut = cut_piece(base, scattered, piece, rings);
      CAPTURE(piece);
      CAPTURE(rings);
      CHECK(cut.level.manifold());
      const auto own = std::count(scattered.begin(), scattered.end(), piece);
      CHECK(piece_face_count(base, scattered, piece, rings) == cut.level.face_count());
      filled += rings == 0 && cut.level.face_count() > own;
    }
  CHECK(filled > 0);  // scattered faces meet at single vertices: rings 0 alone has pinches to fill
}
