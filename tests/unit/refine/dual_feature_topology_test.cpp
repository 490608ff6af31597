// The dual split with features (refine/dual_crease_topology.h) is the plain dual split where
// a level has no interior features: boundaries stay what they were (a boundary is a crease
// with one side, refined by the same sector rule), face for face and corner for corner.
#include <doctest/doctest.h>

#include <string>

#include "framework/refine/dual_crease_topology.h"
#include "framework/refine/splitter.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

// Child vertex i of the feature split as the parent corner it stands for.
std::vector<Index> corners_of(const Level& parent, const ChildOrigins& o) {
  std::vector<Index> out;
  for (size_t i = 0; i < o.kind.size(); ++i) out.push_back(parent.face_offsets[o.parent[i]] + o.local[i]);
  return out;
}

}  // namespace

TEST_CASE("dual split: the feature topology equals the plain one on meshes with boundaries and no interior features") {
  struct Named {
    std::string name;
    Level level;
  };
  for (const Named& m : {Named{"quad grid", test::grid(4, 3).level()}, Named{"triangle grid", test::grid(3, 3, true).level()},
                         Named{"pyramid", test::pyramid().level()}, Named{"torus", test::torus(6, 5).level()}}) {
    CAPTURE(m.name);
    const Level& L = m.level;
    const Level plain = split_dual(L).child;
    const DualFeatureSplit feature = dual_feature_split(L, true);
    REQUIRE(feature.child.face_count() == plain.face_count());
    REQUIRE(feature.child.vertex_count == L.corner_count());  // one point per corner: nothing glued or split
    const std::vector<Index> corner = corners_of(L, feature.origins);
    for (Index f = 0; f < plain.face_count(); ++f) {
      REQUIRE(feature.child.face_size(f) == plain.face_size(f));
      for (int c = 0; c < plain.face_size(f); ++c) CHECK(corner[feature.child.face(f)[c]] == plain.face(f)[c]);
    }
    CHECK(euler_characteristic(feature.child) == euler_characteristic(L));
  }
}
