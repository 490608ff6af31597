// Level and ChildOrigins arrays are not zero-filled when sized (util/scratch_vector.h): every
// element must be written before it is read. With scratch_poison() on, new elements start
// as the byte 0xA5 instead of whatever the heap held; a refinement that read an unwritten
// element would then give other topology or other points than the same refinement with the
// elements zeroed the way the heap's fresh pages are. Full topology on every level, so that
// every array of every split is built.
#include <doctest/doctest.h>

#include "framework/util/scratch_vector.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

struct RefinedTwice {
  Hierarchy h;
  std::vector<double> points;
};

RefinedTwice refine(const Scheme& scheme, const Level& base, const std::vector<double>& positions, bool poison) {
  scratch_poison() = poison;
  RefineOptions options;
  options.levels = 2;
  RefinedTwice r{refine_topology(scheme, base, options), positions};
  for (int l = 0; l < 2; ++l) r.points = step_values(scheme, r.h, l, r.points, 3, options);
  scratch_poison() = false;
  return r;
}

void check_same_level(const Level& a, const Level& b) {
  CHECK(a.vertex_count == b.vertex_count);
  CHECK(a.face_offsets == b.face_offsets);
  CHECK(a.face_vertices == b.face_vertices);
  CHECK(a.face_edges == b.face_edges);
  CHECK(a.edge_vertices == b.edge_vertices);
  CHECK(a.edge_faces == b.edge_faces);
  CHECK(a.vertex_ring_offsets == b.vertex_ring_offsets);
  CHECK(a.vertex_edges == b.vertex_edges);
  CHECK(a.vertex_face_offsets == b.vertex_face_offsets);
  CHECK(a.vertex_faces == b.vertex_faces);
  CHECK(a.vertex_face_corner == b.vertex_face_corner);
  CHECK(a.vertex_on_boundary == b.vertex_on_boundary);
}

}  // namespace

TEST_CASE("every level and origin array is written before it is read (poisoned new elements give the same bits)") {
  for (const auto& case_ : {std::pair{"catmull-clark", torus(6, 5)}, std::pair{"catmull-clark", pyramid()},
                            std::pair{"loop", grid(4, 3, true)}, std::pair{"loop", torus(6, 5, true)},
                            std::pair{"sqrt3", torus(6, 5, true)}, std::pair{"sqrt3", grid(4, 3, true)},
                            std::pair{"doo-sabin", torus(6, 5)}, std::pair{"doo-sabin", pyramid()},
                            std::pair{"mid-edge", grid(4, 3)}, std::pair{"loop-composite", torus(6, 5, true)}}) {
    const std::string scheme_name = case_.first;
    CAPTURE(scheme_name);
    const auto scheme = load_scheme(case_.first);
    const RefinedTwice clean = refine(*scheme, case_.second.level(), case_.second.positions, false);
    const RefinedTwice poisoned = refine(*scheme, case_.second.level(), case_.second.positions, true);
    REQUIRE(clean.h.levels.size() == poisoned.h.levels.size());
    for (size_t l = 0; l < clean.h.levels.size(); ++l) check_same_level(clean.h.levels[l], poisoned.h.levels[l]);
    for (size_t l = 0; l < clean.h.origins.size(); ++l) {
      CHECK(clean.h.origins[l].kind == poisoned.h.origins[l].kind);
      CHECK(clean.h.origins[l].parent == poisoned.h.origins[l].parent);
      CHECK(clean.h.origins[l].local == poisoned.h.origins[l].local);
      CHECK(clean.h.origins[l].parent_face == poisoned.h.origins[l].parent_face);
    }
    CHECK(clean.points == poisoned.points);
  }
}
