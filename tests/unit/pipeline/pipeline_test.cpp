// The pipeline (framework/pipeline): one request gives the engine's own refinement — no
// geometry of its own — with the shape options taken from the request, else the mesh's
// tags, else OpenSubdiv's defaults; options named in the front-end's words; the thread
// limit capped at the machine; the memory budget honoured before any work.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "framework/io/mesh_data.h"
#include "framework/pipeline/level_description.h"
#include "framework/pipeline/option_names.h"
#include "framework/util/option_spelling.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/pipeline/thread_limit.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::mesh_data;

RefineRequest request_for(const test::Mesh& m, const std::string& scheme, int levels) {
  RefineRequest r;
  r.mesh = mesh_data(m);
  r.mesh_name = "test mesh";
  r.scheme.text = scheme;
  r.levels = levels;
  return r;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double d = 0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace

TEST_CASE("the pipeline's points are the engine's stencil tables' points, level by level") {
  for (const char* scheme : {"catmull-clark", "loop", "doo-sabin"}) {
    CAPTURE(scheme);
    const test::Mesh m = std::string(scheme) == "loop" ? test::octahedron() : test::cube();
    const RefineResult result = refine_mesh(request_for(m, scheme, 2));
    const test::Refined reference = test::refine_mesh(m, scheme, 2);
    REQUIRE(result.levels.size() == 3);
    CHECK(result.hierarchy.levels.back().face_count() == reference.hierarchy.levels.back().face_count());
    CHECK(max_difference(result.levels.back().positions, reference.positions) <= 1e-14);
  }
}

TEST_CASE("only the finest level's data is kept when the request says so, and it is the same") {
  RefineRequest all = request_for(test::cube(), "catmull-clark", 3);
  RefineRequest last = all;
  last.keep_all_levels = false;
  const RefineResult a = refine_mesh(all), b = refine_mesh(last);
  for (size_t l = 0; l + 1 < b.levels.size(); ++l) CHECK(b.levels[l].positions.empty());
  CHECK(a.levels.back().positions == b.levels.back().positions);
}

TEST_CASE("with the finest level alone kept, coarser levels' topology is released and the finest level is the same") {
  for (const char* scheme : {"catmull-clark", "loop", "doo-sabin"}) {
    CAPTURE(scheme);
    const test::Mesh m = std::string(scheme) == "loop" ? test::octahedron() : test::cube();
    RefineRequest all = request_for(m, scheme, 3);
    RefineRequest last = all;
    last.keep_all_levels = false;
    last.described_arrays = ArraySelection::all();
    all.described_arrays = last.described_arrays;
    const RefineResult a = refine_mesh(all), b = refine_mesh(last);
    REQUIRE(b.hierarchy.levels.size() == 4);
    for (size_t l = 0; l + 1 < b.hierarchy.levels.size(); ++l) {
      // Counts stay (progress, base_face); rings, edges and corners are gone.
      CHECK(b.hierarchy.levels[l].face_count() == a.hierarchy.levels[l].face_count());
      CHECK(b.hierarchy.levels[l].face_vertices.capacity() == 0);
      CHECK(b.hierarchy.levels[l].vertex_faces.capacity() == 0);
      CHECK(b.hierarchy.origins[l].parent.capacity() == 0);
    }
    // The finest level and every described array read from the hierarchy are the same.
    CHECK(a.levels.back().positions == b.levels.back().positions);
    CHECK(a.hierarchy.levels.back().face_vertices == b.hierarchy.levels.back().face_vertices);
    const int finest = 3;
    const MeshData da = described_level_mesh(a.hierarchy, finest, LevelData(a.levels.back()), a.features,
                                             base_faces_down_to(a.hierarchy, finest), *all.described_arrays);
    const MeshData db = described_level_mesh(b.hierarchy, finest, LevelData(b.levels.back()), b.features,
                                             base_faces_down_to(b.hierarchy, finest), *last.described_arrays);
    REQUIRE(da.point_data.size() == db.point_data.size());
    REQUIRE(da.cell_data.size() == db.cell_data.size());
    for (size_t i = 0; i < da.point_data.size(); ++i) CHECK(da.point_data[i].values == db.point_data[i].values);
    for (size_t i = 0; i < da.cell_data.size(); ++i) CHECK(da.cell_data[i].values == db.cell_data[i].values);
  }
}

TEST_CASE("topology made level by level, the last level's faces after its points: the same level as all levels first") {
  // keep_all_levels takes refine_topology's whole hierarchy first; the finest level alone
  // makes each level's topology before its points (engine/topology_steps.h) and, on a closed
  // untagged mesh, the last level faces only, with its faces after its points. The same
  // bits, for 1 and 2 threads (a 64 x 48 torus: level 3 has 196,608 faces, enough for the
  // parallel loops to split).
  for (const bool triangles : {false, true}) {
    const char* scheme = triangles ? "loop" : "catmull-clark";
    CAPTURE(scheme);
    RefineRequest all = request_for(test::torus(64, 48, triangles), scheme, 3);
    RefineRequest last = all;
    last.keep_all_levels = false;
    const RefineResult a = refine_mesh(all);
    for (const int threads : {1, 2}) {
      CAPTURE(threads);
      const ThreadLimit limit(threads);
      const RefineResult b = refine_mesh(last);
      const Level& fa = a.hierarchy.levels.back();
      const Level& fb = b.hierarchy.levels.back();
      CHECK(fb.face_count() == 4 * a.hierarchy.levels[2].face_count());  // quads and triangles both split in four
      CHECK(fb.edge_vertices.empty());  // faces only
      CHECK(b.hierarchy.levels[2].face_vertices.capacity() == 0);  // the parent's faces went after use
      CHECK(a.levels.back().positions == b.levels.back().positions);
      CHECK(fa.vertex_count == fb.vertex_count);
      CHECK(fa.face_offsets == fb.face_offsets);
      CHECK(fa.face_vertices == fb.face_vertices);
      CHECK(a.hierarchy.origins.back().parent_face == b.hierarchy.origins.back().parent_face);
      CHECK(a.hierarchy.origins.back().kind == b.hierarchy.origins.back().kind);
    }
  }
}

TEST_CASE("shape options: the request's, else the mesh's tags, else OpenSubdiv's defaults") {
  const test::Mesh grid = test::grid(3, 3);
  RefineRequest r = request_for(grid, "catmull-clark", 1);
  CHECK(refine_mesh(r).features.boundary == BoundaryInterpolation::EdgesAndCorners);
  r.mesh.options.interpolate_boundary = 2;  // OBJ `t interpolateboundary 0/0/ 2`: edges only
  r.mesh.options.crease_method = "chaikin";
  const RefineResult tagged = refine_mesh(r);
  CHECK(tagged.features.boundary == BoundaryInterpolation::EdgesOnly);
  CHECK(tagged.features.crease_method == CreaseMethod::Chaikin);
  CHECK(tagged.tags.interpolate_boundary == 2);  // written back as it was used
  r.shape.boundary = BoundaryInterpolation::None;
  const RefineResult asked = refine_mesh(r);
  CHECK(asked.features.boundary == BoundaryInterpolation::None);
  CHECK(asked.tags.interpolate_boundary == 0);
  // With edges only, a boundary corner of the grid moves (it follows the boundary curve);
  // with edges and corners it stays: the options reached the engine.
  CHECK(tagged.levels.back().positions != refine_mesh(request_for(grid, "catmull-clark", 1)).levels.back().positions);
}

TEST_CASE("an unused vertex is dropped with a warning; per-vertex values then refused naming the option") {
  test::Mesh m = test::cube();
  m.add_vertex(5, 5, 5);
  RefineRequest r = request_for(m, "catmull-clark", 1);
  const RefineResult result = refine_mesh(r);
  REQUIRE(result.warnings.size() == 1);
  CHECK(result.levels.front().positions.size() == 8 * 3);
  r.vertex_parameters["lambda"] = std::vector<double>(9, 0.5);
  try {
    refine_mesh(r);
    FAIL("per-vertex values for a renumbered mesh were accepted");
  } catch (const OptionError& e) {
    CHECK(e.spelled({{"vertex_param", "--vertex-param"}}).find("--vertex-param gives values") != std::string::npos);
    CHECK(std::string(e.what()).find("vertex param gives values") != std::string::npos);
  }
}

TEST_CASE("a sequence whose counts disagree with the levels asked for is refused in each front-end's words") {
  RefineRequest r = request_for(test::cube(), "catmull-clark:1,loop:1", 3);
  r.levels_given = true;
  try {
    refine_mesh(r);
    FAIL("accepted");
  } catch (const OptionError& e) {
    CHECK(std::string(e.what()).find("scheme 'catmull-clark:1,loop:1' runs 2 level(s), but levels asks for 3") !=
          std::string::npos);
    CHECK(e.spelled({{"scheme", "--scheme"}, {"levels", "--levels"}}).find("--scheme 'catmull-clark:1,loop:1'") !=
          std::string::npos);
  }
}

TEST_CASE("a memory budget smaller than the refinement is refused before any work, with the request's advice") {
  RefineRequest r = request_for(test::cube(), "catmull-clark", 8);
  r.memory_budget = 1 << 20;
  r.memory_advice = "try fewer levels";
  CHECK_THROWS_WITH_AS(refine_mesh(r), doctest::Contains("try fewer levels"), Error);
}

TEST_CASE("spelling: placeholders become the front-end's words, other braces stay") {
  const OptionSpelling cli = {{"levels", "--levels"}};
  CHECK(spell_options("{levels} 40: give 0 to 30", cli) == "--levels 40: give 0 to 30");
  CHECK(spell_options("{start_level} 3", cli) == "start level 3");
  CHECK(spell_options("set {A}, {1} and {} as {levels", cli) == "set {A}, {1} and {} as {levels");
}

TEST_CASE("option names: every choice reads back, and a wrong one lists them in the caller's spelling") {
  for (const auto& c : boundary_choices()) CHECK(boundary_from_name(c.name) == c.value);
  for (const auto& c : crease_method_choices()) CHECK(crease_method_from_name(c.name) == c.value);
  for (const auto& c : face_varying_choices()) {
    CHECK(face_varying_from_name(c.name) == c.value);
    CHECK(std::string(face_varying_linear_name(c.value)) == c.name);  // OBJ output's names agree
  }
  CHECK_THROWS_WITH_AS(boundary_from_name("corners", "boundary="), doctest::Contains("boundary='corners': choose one of"),
                       Error);
  CHECK_THROWS_WITH_AS(crease_method_from_name("x", "--crease-method"),
                       doctest::Contains("--crease-method 'x': choose one of 'uniform'"), Error);
}

TEST_CASE("the thread limit is capped at the cores this process may use, and 0 means no limit") {
  CHECK(ThreadLimit(0).threads() == 0);
  CHECK(ThreadLimit(1).threads() == 1);
  const ThreadLimit many(1 << 30);
  CHECK(many.threads() == available_cores());
  CHECK(many.note().find("is more than the") != std::string::npos);
  CHECK_THROWS_AS(ThreadLimit(-1), Error);
}

TEST_CASE("described levels leave hole faces and their cell values out") {
  RefineRequest r = request_for(test::grid(4, 4), "catmull-clark", 1);
  r.shape.boundary = BoundaryInterpolation::None;  // every face at a boundary vertex is a hole
  r.mesh.cell_data.push_back({"id", 1, std::vector<double>(16, 0.0), false});
  for (int f = 0; f < 16; ++f) r.mesh.cell_data[0].values[size_t(f)] = f;
  RefineResult result = refine_mesh(r);
  std::vector<MeshData> meshes;
  const auto levels = describe_levels(result.hierarchy, std::move(result.levels), result.features, {}, meshes,
                                      ArraySelection::parse("none"));
  // The 4 inner faces of the 4 x 4 grid touch no boundary vertex: 16 children.
  CHECK(levels.back().mesh->face_count() == 16);
  REQUIRE(levels.back().cell_data.size() == 1);
  for (double id : levels.back().cell_data[0].values) CHECK((id == 5 || id == 6 || id == 9 || id == 10));
}

}  // namespace subdiv
