// Holes and smooth triangles as OpenSubdiv's Far has them: positions equal to 1e-12 at
// levels 1-3 under every boundary mode and both creasing methods, and every face a hole
// exactly where Far's is (hole faces are left out of the output, see cli tests).
#include "unit/topology/nonmanifold_meshes.h"
#include "unit/topology/osd_compare.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

using namespace subdiv;
using namespace subdiv::nonmanifold_test;

TEST_CASE("OpenSubdiv agreement: holes shape their neighbours and stay holes") {
  for (const bool tri : {false, true}) {
    auto m = feature_test::grid(5, 4, tri);
    m.name = tri ? "triangle grid with holes" : "grid with holes";
    m.mesh.holes = {7, 12};  // inside, away from the boundary
    m.mesh.holes.push_back(0);  // at a boundary corner
    check_all_setups(m, tri ? "loop" : "catmull-clark");
  }
  auto fan = flap_fan(3, false);
  fan.name += ", one flap a hole";
  fan.mesh.holes = {1};
  check_all_setups(fan, "catmull-clark");
}

TEST_CASE("OpenSubdiv agreement: smooth triangles (TRI_SUB_SMOOTH) as the scheme parameter triangles=smooth") {
  const ParameterOverrides smooth{{"triangles", "smooth"}};
  auto tris = feature_test::grid(5, 4, true);
  tris.name = "catmull-clark, smooth triangles, triangle grid";
  tris.crease_path({feature_test::grid_id(0, 2, 5), feature_test::grid_id(1, 2, 5), feature_test::grid_id(2, 2, 5)}, 1.5);
  for (const Setup& s : kSetups) check_agreement(tris, "catmull-clark", s, 3, smooth, true);

  feature_test::FeatureMesh pyramid{"catmull-clark, smooth triangles, pyramid (a quad and four triangles)", {}};
  pyramid.add_vertex(0, 0, 0), pyramid.add_vertex(1, 0, 0), pyramid.add_vertex(1, 1, 0), pyramid.add_vertex(0, 1, 0);
  pyramid.add_vertex(0.5, 0.5, 1);
  pyramid.add_face({0, 3, 2, 1});
  pyramid.add_face({0, 1, 4}), pyramid.add_face({1, 2, 4}), pyramid.add_face({2, 3, 4}), pyramid.add_face({3, 0, 4});
  pyramid.perturb(0.05);
  for (const Setup& s : kSetups) check_agreement(pyramid, "catmull-clark", s, 3, smooth, true);

  auto fan = flap_fan(3, true);
  fan.name += ", smooth triangles";
  for (const Setup& s : kSetups) check_agreement(fan, "catmull-clark", s, 3, smooth, true);
}

TEST_CASE("smooth triangles change nothing on quads: the catmark and smooth rows are the same bits") {
  const auto quads = feature_test::cube();
  RefineOptions options;
  options.levels = 2;
  const auto plain = load_scheme("catmull-clark");
  const auto smooth = load_scheme("catmull-clark", {{"triangles", "smooth"}});
  const Hierarchy a = refine(*plain, level_from_mesh(quads.mesh, "cube"), options);
  const Hierarchy b = refine(*smooth, level_from_mesh(quads.mesh, "cube"), options);
  CHECK(interpolate(a, 2, quads.mesh.positions, 3) == interpolate(b, 2, quads.mesh.positions, 3));
}

#endif
