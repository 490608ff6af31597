// The sqrt2 plugin: a new splitter, a JSON scheme using it carried by the plugin, and JSON
// files on disk naming the plugin's split.
#include <doctest/doctest.h>
#include <fstream>

#include "framework/refine/splitter.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/cli_runner.h"
#include "support/refine_helpers.h"
#include "support/test_meshes.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

TEST_CASE("the sqrt2 splitter: faces double, interior edges flip into quads, closed meshes stay closed") {
  load_example_plugins();
  const SplitKind kind = split_kind_from_name("sqrt2");
  CHECK(int(kind) >= kFirstRegisteredSplit);
  const Level cube_level = cube().level();
  const SplitResult one = split(kind, cube_level, 0);
  // Cube V = 8, E = 12, F = 6: one vertex per face is added, one quad per edge made.
  CHECK(one.child.vertex_count == 14);
  CHECK(one.child.face_count() == 12);
  CHECK(one.child.all_faces_have_size(4));
  CHECK(one.child.edge_count() == 24);
  CHECK(euler_characteristic(one.child) == 2);
  for (Index v = 0; v < 8; ++v) CHECK(one.child.valence(v) == 3);    // old corners
  for (Index v = 8; v < 14; ++v) CHECK(one.child.valence(v) == 4);   // face points
  for (Index v = 0; v < 8; ++v) CHECK(one.origins.kind[v] == OriginKind::Vertex);
  for (Index v = 8; v < 14; ++v) CHECK(one.origins.kind[v] == OriginKind::Face);
  const SplitResult two = split(kind, one.child, 1);
  CHECK(two.child.face_count() == 24);
  CHECK(euler_characteristic(two.child) == 2);
}

TEST_CASE("the sqrt2 splitter on an open grid: boundary edges are halved into triangles") {
  load_example_plugins();
  const Level g = grid(4, 4).level();  // V = 25, E = 40 (16 on the boundary), F = 16
  const SplitResult r = split(split_kind_from_name("sqrt2"), g, 0);
  CHECK(r.child.vertex_count == 25 + 16 + 16);
  int quads = 0, triangles = 0;
  for (Index f = 0; f < r.child.face_count(); ++f) (r.child.face_size(f) == 4 ? quads : triangles)++;
  CHECK(quads == 24 + 4);     // one per interior edge, one per grid corner
  CHECK(triangles == 32 - 8);  // two per boundary edge, but corners take quads
  for (Index corner : {0, 4, 20, 24}) CHECK(r.child.valence(corner) == 2);
  CHECK(euler_characteristic(r.child) == 1);
  int edge_children = 0;
  for (auto k : r.origins.kind) edge_children += k == OriginKind::Edge;
  CHECK(edge_children == 16);
}

TEST_CASE("the plugin's JSON scheme sqrt2: affine stencils, flat stays flat, corners stay") {
  load_example_plugins();
  const auto scheme = load_scheme("sqrt2");
  CHECK(scheme->split() == split_kind_from_name("sqrt2"));
  CHECK(scheme->curve->name == "cubic-bspline");
  Mesh g = grid(4, 4);
  const Refined r = refine_mesh(g, "sqrt2", 3);
  for (size_t i = 2; i < r.positions.size(); i += 3) CHECK(r.positions[i] == 0.0);
  for (const StencilTable& t : r.hierarchy.stencils)
    for (Index row = 0; row < t.row_count(); ++row) {
      double sum = 0;
      for (Index i = t.offsets[row]; i < t.offsets[row + 1]; ++i) sum += t.weights[i];
      CHECK(sum == doctest::Approx(1.0).epsilon(1e-13));
    }
  // The corner (0, 0) keeps its place (boundary corners stay by default).
  CHECK(r.positions[0] == 0.0);
  CHECK(r.positions[1] == 0.0);
  // Old vertices move halfway to the mean of their new face points. Cube corner (0,0,0):
  // its faces' centroids (1/2,1/2,0), (1/2,0,1/2), (0,1/2,1/2) average to (1/3,1/3,1/3).
  const Refined c = refine_mesh(cube(), "sqrt2", 1);
  for (int d = 0; d < 3; ++d) CHECK(c.positions[d] == doctest::Approx(1.0 / 6));
  CHECK(c.positions[3 * 8 + 2] == doctest::Approx(0.0));  // the face point of the bottom face z = 0
}

TEST_CASE("a JSON file on disk can name the plugin's split") {
  load_example_plugins();
  const auto dir = fresh_dir("plugin-sqrt2-json");
  std::ofstream(dir / "sqrt2-linear.json") << R"({
  "name": "sqrt2-linear",
  "split": "sqrt2",
  "curve": "two-point",
  "rules": {"face": [{"sum": "vertices", "w": "1/k"}], "vertex": [{"at": "self", "w": "1"}]}
})";
  const auto scheme = load_scheme((dir / "sqrt2-linear.json").string());
  const Refined r = refine_mesh(cube(), (dir / "sqrt2-linear.json").string(), 2);
  CHECK(r.hierarchy.levels[2].face_count() == 24);
  CHECK(r.positions[0] == 0.0);  // old vertices stay with this rule
  // Rules for an element the split makes no points for are refused, naming the split's.
  std::ofstream(dir / "bad.json") << R"({"name": "bad", "split": "sqrt2", "rules": {"corner": [{"at": "self", "w": "1"}]}})";
  CHECK_THROWS_WITH_AS(load_scheme((dir / "bad.json").string()), doctest::Contains("unknown key \"corner\""), Error);
}

// Every built-in split refines non-manifold meshes; a plugin's split that does not say it can
// (SplitterInfo::handles_non_manifold, which sqrt2 leaves false) is refused them by the engine,
// naming the split and the edge.
TEST_CASE("a plugin's split that does not opt in refuses a non-manifold mesh, naming the edge") {
  load_example_plugins();
  const auto scheme = load_scheme("sqrt2");
  REQUIRE_FALSE(splitter_info(scheme->split()).handles_non_manifold);
  // Three quads hinged on the edge (0, 1).
  test::Mesh m;
  m.add_vertex(0, 0, 0), m.add_vertex(0, 1, 0);
  m.add_vertex(1, 0, 0), m.add_vertex(1, 1, 0), m.add_vertex(-1, 0, 0), m.add_vertex(-1, 1, 0);
  m.add_vertex(0, 0, 1), m.add_vertex(0, 1, 1);
  m.add_face({0, 1, 3, 2}), m.add_face({1, 0, 4, 5}), m.add_face({0, 1, 7, 6});
  RefineOptions options;
  options.levels = 1;
  CHECK_THROWS_WITH_AS(refine(*scheme, m.level(), options),
                       doctest::Contains("uses the 'sqrt2' split, which needs a manifold mesh, but edge 0-1 has 3 faces (0, 1, 2)"),
                       Error);
}
