// extract_neighbourhood keeps per-thread scratch arrays over the level it cuts from, cleared
// entry by entry (local_patch.h): cuts from levels of different sizes, one after another,
// must each be the same as on a first use. On a regular quad torus the cut is known in
// closed form: a face centre with radius r takes the (2r + 1)^2 faces touching the
// (2r)^2 vertices closer than r, a vertex centre the (2r)^2 faces around the (2r - 1)^2.
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include "framework/analysis/surface/local_patch.h"
#include "framework/topology/level.h"

using namespace subdiv;

namespace {

Level quad_torus(int n) {
  std::vector<Index> offsets{0}, corners;
  auto id = [n](int i, int j) { return Index((j % n) * n + (i % n)); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      corners.insert(corners.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      offsets.push_back(Index(corners.size()));
    }
  return build_level(Index(n * n), offsets, corners);
}

// The cut's faces are its original faces, corner by corner, through `original`.
void check_cut(const Level& L, const Extracted& e, CentreKind kind, Index centre, int radius) {
  const int side = kind == CentreKind::Face ? 2 * radius + 1 : 2 * radius;
  CHECK(e.level.face_count() == side * side);
  CHECK(e.level.vertex_count == (side + 1) * (side + 1));
  REQUIRE(e.face_original.size() == size_t(e.level.face_count()));
  for (Index f = 0; f < e.level.face_count(); ++f) {
    const auto mine = e.level.face(f);
    const auto theirs = L.face(e.face_original[size_t(f)]);
    REQUIRE(mine.size() == theirs.size());
    for (size_t i = 0; i < mine.size(); ++i) CHECK(e.original[size_t(mine[i])] == theirs[i]);
  }
  if (kind == CentreKind::Vertex) {
    CHECK(e.local(centre) == 0);
  } else {
    CHECK(std::count(e.face_original.begin(), e.face_original.end(), centre) == 1);
    for (Index v : L.face(centre)) CHECK(e.local(v) != kNone);
  }
}

}  // namespace

TEST_CASE("extract_neighbourhood: cuts from a large and a small level alternately are each exact") {
  const Level big = quad_torus(120), small = quad_torus(9);
  // Centres near the end of the large level, so that the scratch entries it leaves set
  // would lie past the small level's size if they were not cleared.
  const Index big_face = big.face_count() - 2, big_vertex = big.vertex_count - 3;
  for (int round = 0; round < 2; ++round) {
    check_cut(big, extract_neighbourhood(big, CentreKind::Face, big_face, 3), CentreKind::Face, big_face, 3);
    check_cut(small, extract_neighbourhood(small, CentreKind::Face, 40, 2), CentreKind::Face, 40, 2);
    check_cut(big, extract_neighbourhood(big, CentreKind::Vertex, big_vertex, 2), CentreKind::Vertex, big_vertex, 2);
    check_cut(small, extract_neighbourhood(small, CentreKind::Vertex, 0, 3), CentreKind::Vertex, 0, 3);
    check_cut(small, extract_neighbourhood(small, CentreKind::Face, 80, 1), CentreKind::Face, 80, 1);
  }
}

TEST_CASE("extract_neighbourhood: every face of a level in turn, each cut the same shape") {
  const Level L = quad_torus(12);
  for (Index f = 0; f < L.face_count(); ++f)
    check_cut(L, extract_neighbourhood(L, CentreKind::Face, f, 2), CentreKind::Face, f, 2);
}
