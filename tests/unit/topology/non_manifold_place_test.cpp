// non_manifold_place names the first place where a level stops being manifold, with the
// repair that fits it, for the commands that refuse such meshes.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "framework/topology/level.h"
#include "framework/topology/non_manifold_place.h"

using namespace subdiv;

namespace {

// A level from faces given as lists of 0-based vertices.
Level level_of(Index vertices, const std::vector<std::vector<Index>>& faces) {
  std::vector<Index> offsets{0}, corners;
  for (const auto& f : faces) {
    corners.insert(corners.end(), f.begin(), f.end());
    offsets.push_back(Index(corners.size()));
  }
  return build_level(vertices, offsets, corners);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("a manifold level has no place to name") {
  CHECK(non_manifold_place(level_of(4, {{0, 1, 2, 3}})).empty());
}

TEST_CASE("a face repeating a vertex in a row (OBJ 'f 1 2 2 3') names the face, the vertex and the repair") {
  const std::string place = non_manifold_place(level_of(5, {{0, 1, 1, 2}, {1, 4, 2}}));
  CAPTURE(place);
  CHECK(contains(place, "face 0 repeats vertex 1"));
  CHECK(contains(place, "remove the repeat"));
  CHECK(contains(place, "counted from 0"));
}

TEST_CASE("a face that comes back to a vertex runs an edge twice") {
  const std::string place = non_manifold_place(level_of(4, {{0, 1, 2, 1, 3}}));
  CAPTURE(place);
  CHECK(contains(place, "face 0 runs edge"));
  CHECK(contains(place, "twice"));
}

TEST_CASE("an edge with three faces names the edge, its faces and the repair") {
  const std::string place = non_manifold_place(level_of(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}));
  CAPTURE(place);
  CHECK(contains(place, "edge 0-1 has 3 faces (0, 1, 2)"));
  CHECK(contains(place, "split the mesh along it"));
}

TEST_CASE("a face written twice is named as such, beside its neighbours") {
  // Written twice the same way round (the other way round, two faces close into a manifold pillow).
  const std::string place = non_manifold_place(level_of(6, {{0, 1, 2, 3}, {1, 4, 5, 2}, {1, 4, 5, 2}}));
  CAPTURE(place);
  CHECK(contains(place, "faces 1 and 2 have the same corners (a face written twice)"));
  CHECK(contains(place, "remove one of them"));
}

TEST_CASE("two neighbours of opposite orientation: the shared edge, both faces and the repair") {
  const std::string place = non_manifold_place(level_of(6, {{0, 1, 2, 3}, {1, 4, 5, 2}, {0, 1, 5, 4}}));
  CAPTURE(place);
  CHECK(contains(place, "run edge"));
  CHECK(contains(place, "in the same direction"));
  CHECK(contains(place, "flip one of them"));
}

TEST_CASE("two triangles touching at one vertex (a bow-tie) name the vertex and its faces") {
  const std::string place = non_manifold_place(level_of(5, {{0, 1, 2}, {0, 3, 4}}));
  CAPTURE(place);
  CHECK(contains(place, "the faces around vertex 0 (0, 1) meet only at the vertex"));
  CHECK(contains(place, "its own copy of the vertex"));
}

TEST_CASE("a fan of many flaps lists a few faces and the count, not all of them") {
  std::vector<std::vector<Index>> faces;
  for (Index f = 0; f < 40; ++f) faces.push_back({0, 1, Index(2 + f)});
  const std::string place = non_manifold_place(level_of(42, faces));
  CAPTURE(place);
  CHECK(contains(place, "edge 0-1 has 40 faces (0, 1, 2, 3, 4, 5, ... 40 in all)"));
}
