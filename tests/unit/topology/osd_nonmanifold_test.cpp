// Non-manifold meshes refined as OpenSubdiv's Far refines them: positions equal to 1e-12 at
// levels 1-3 for Catmull-Clark and Loop under every boundary mode and both creasing methods.
#include "unit/topology/nonmanifold_meshes.h"
#include "unit/topology/osd_compare.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

using namespace subdiv;
using namespace subdiv::nonmanifold_test;

TEST_CASE("OpenSubdiv agreement: non-manifold edges with 3 and 4 faces (a fan of flaps)") {
  for (int flaps : {3, 4}) {
    check_all_setups(flap_fan(flaps, false), "catmull-clark");
    check_all_setups(flap_fan(flaps, true), "loop");
    check_all_setups(flap_fan(flaps, true), "catmull-clark");
  }
}

TEST_CASE("OpenSubdiv agreement: a bow-tie vertex (two fans meeting at one vertex)") {
  check_all_setups(bow_tie(false), "catmull-clark");
  check_all_setups(bow_tie(true), "loop");
}

TEST_CASE("OpenSubdiv agreement: inconsistently oriented neighbours") {
  check_all_setups(flipped_face(false), "catmull-clark");
  check_all_setups(flipped_face(true), "loop");
}

TEST_CASE("OpenSubdiv agreement: a quad that repeats a vertex (quad pole)") {
  check_all_setups(quad_pole(), "catmull-clark");
}

TEST_CASE("OpenSubdiv agreement: faces with fewer than 3 distinct vertices") {
  check_all_setups(collapsed_faces(false), "catmull-clark");
  check_all_setups(collapsed_faces(true), "loop");
}

TEST_CASE("OpenSubdiv agreement: a fan of flaps with a semi-sharp crease across the hinge") {
  auto m = flap_fan(3, false);
  m.name += ", creased";
  m.crease(2, 3, 1.5);
  m.crease(4, 5, 2.7);
  check_all_setups(m, "catmull-clark");
}

#endif
