// Feature sidecar files and dihedral-angle detection, at the library level.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "framework/io/feature_angle.h"
#include "framework/io/feature_file.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

// The error message of `f`, or "" when it does not throw subdiv::Error.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("feature file: edges, paths, corners and sharpness defaults") {
  const FeatureTags t = parse_feature_json(R"({
    "description": "two creases and corners",
    "creases": [
      {"edge": [0, 1], "sharpness": 2.5},
      {"path": [4, 5, 7, 6, 4], "sharpness": "infinite"},
      {"path": [2, 6]}
    ],
    "corners": [
      {"vertex": 3, "sharpness": 0.5},
      {"vertices": [1, 7]}
    ]
  })", "f.json");
  REQUIRE(t.creases.size() == 1 + 4 + 1);
  CHECK(t.creases[0].v0 == 0);
  CHECK(t.creases[0].v1 == 1);
  CHECK(t.creases[0].sharpness == 2.5f);
  CHECK(t.creases[1].v0 == 4);
  CHECK(t.creases[4].v0 == 6);
  CHECK(t.creases[4].v1 == 4);
  CHECK(t.creases[4].sharpness == 10.f);
  CHECK(t.creases[4].where == "creases[1].path[3..4]");
  CHECK(t.creases[5].sharpness == 10.f);  // left out: infinitely sharp
  REQUIRE(t.corners.size() == 3);
  CHECK(t.corners[0].v == 3);
  CHECK(t.corners[0].sharpness == 0.5f);
  CHECK(t.corners[2].v == 7);
  CHECK(t.corners[2].sharpness == 10.f);

  // Applied to the cube: the tags land on the named edges and vertices.
  Level cube = test::cube().level();
  apply_feature_tags(t, cube);
  CHECK(cube.edge_sharp(find_edge(cube, 0, 1)) == 2.5f);
  CHECK(cube.edge_sharp(find_edge(cube, 7, 6)) == 10.f);
  CHECK(cube.edge_sharp(find_edge(cube, 2, 6)) == 10.f);
  CHECK(cube.edge_sharp(find_edge(cube, 1, 3)) == 0.f);
  CHECK(cube.vertex_sharp(3) == 0.5f);
  CHECK(cube.vertex_sharp(1) == 10.f);
  CHECK(cube.vertex_sharp(0) == 0.f);
}

TEST_CASE("feature file: a later tag replaces an earlier one on the same edge") {
  Level cube = test::cube().level();
  cube.edge_sharpness.assign(cube.edge_count(), 0.f);
  cube.edge_sharpness[find_edge(cube, 0, 1)] = 10.f;  // as if tagged in the mesh file
  apply_feature_tags(parse_feature_json(R"({"creases": [{"edge": [1, 0], "sharpness": 1}, {"edge": [3, 1], "sharpness": 0}]})", "f"), cube);
  CHECK(cube.edge_sharp(find_edge(cube, 0, 1)) == 1.f);
  CHECK(cube.edge_sharp(find_edge(cube, 1, 3)) == 0.f);
}

TEST_CASE("feature file errors name the file and the entry") {
  const auto parse = [](const std::string& text) { return error_of([&] { parse_feature_json(text, "f.json"); }); };
  SUBCASE("syntax errors give file:line:column") {
    const std::string e = parse("{\n  \"creases\": [\n    {\"edge\": [0, 1] \"sharpness\": 2}\n  ]\n}");
    CHECK_MESSAGE(e.rfind("f.json:3:", 0) == 0, e);
    CHECK(contains(e, "malformed JSON"));
    CHECK(contains(parse(""), "f.json:1:1:"));
  }
  SUBCASE("negative, non-numeric and non-finite sharpness") {
    const std::string e = parse(R"({"creases": [{"edge": [0, 1]}, {"edge": [1, 3], "sharpness": -1}]})");
    CHECK_MESSAGE(contains(e, "f.json: creases[1].sharpness: sharpness -1 is negative"), e);
    CHECK(contains(parse(R"({"corners": [{"vertex": 0, "sharpness": -0.5}]})"), "corners[0].sharpness"));
    CHECK(contains(parse(R"({"creases": [{"edge": [0, 1], "sharpness": "sharp"}]})"), "\"infinite\""));
    CHECK(contains(parse(R"({"creases": [{"edge": [0, 1], "sharpness": true}]})"), "creases[0].sharpness"));
  }
  SUBCASE("vertex indices, edges and paths") {
    CHECK(contains(parse(R"({"creases": [{"edge": [0, 1, 2]}]})"), "creases[0].edge: an edge has two end points"));
    CHECK(contains(parse(R"({"creases": [{"edge": [0, -1]}]})"), "creases[0].edge[1]: vertex index -1"));
    CHECK(contains(parse(R"({"creases": [{"edge": [0, 1.5]}]})"), "whole number"));
    CHECK(contains(parse(R"({"creases": [{"path": [3]}]})"), "at least two"));
    CHECK(contains(parse(R"({"creases": [{"path": [3, 3]}]})"), "joins vertex 3 to itself"));
    CHECK(contains(parse(R"({"creases": [{"edge": [0, 1], "path": [1, 2]}]})"), "either"));
    CHECK(contains(parse(R"({"corners": [{"vertex": "a"}]})"), "corners[0].vertex"));
  }
  SUBCASE("unknown keys and wrong shapes") {
    CHECK(contains(parse(R"({"creases": [{"edge": [0, 1], "sharpnes": 2}]})"), "unknown key \"sharpnes\""));
    CHECK(contains(parse(R"({"crease": []})"), "f.json: crease: unknown key"));
    CHECK(contains(parse(R"([1, 2])"), "JSON object"));
    CHECK(contains(parse(R"({"creases": {"edge": [0, 1]}})"), "expected a list"));
  }
  SUBCASE("creases that are not edges of the mesh, vertices that do not exist: the level is unchanged") {
    Level cube = test::cube().level();
    const auto apply = [&](const std::string& text) {
      return error_of([&] { apply_feature_tags(parse_feature_json(text, "f.json"), cube); });
    };
    const std::string e = apply(R"({"creases": [{"edge": [0, 1]}, {"path": [0, 1, 7]}]})");
    CHECK_MESSAGE(contains(e, "f.json: creases[1].path[1..2]: vertices 1 and 7 are not joined by an edge"), e);
    CHECK(contains(apply(R"({"creases": [{"edge": [0, 8]}]})"), "vertex 8 does not exist; the mesh has 8 vertices"));
    CHECK(contains(apply(R"({"corners": [{"vertex": 8}]})"), "corners[0].vertex: vertex 8 does not exist"));
    CHECK(cube.edge_sharpness.empty());
    CHECK(cube.vertex_sharpness.empty());
  }
  SUBCASE("a missing file") {
    CHECK(contains(error_of([] { read_feature_file("/nonexistent/features.json"); }), "/nonexistent/features.json"));
  }
}

TEST_CASE("dihedral angles: the octahedron's normals meet at acos(1/3), the cube's at 90 degrees") {
  const test::Mesh oct = test::octahedron();
  const Level L = oct.level();
  const double expected = std::acos(1.0 / 3) * 180 / std::numbers::pi;  // 70.5288 degrees
  for (Index e = 0; e < L.edge_count(); ++e) CHECK(dihedral_angle_degrees(L, oct.positions, e) == doctest::Approx(expected).epsilon(1e-12));
  CHECK(edges_sharper_than(L, oct.positions, 70).size() == 12);
  CHECK(edges_sharper_than(L, oct.positions, 71).empty());

  test::Mesh cube = test::cube();
  Level C = cube.level();
  CHECK(edges_sharper_than(C, cube.positions, 89).size() == 12);
  CHECK(edges_sharper_than(C, cube.positions, 91).empty());
  CHECK(tag_edges_sharper_than(C, cube.positions, 30) == 12);
  for (Index e = 0; e < C.edge_count(); ++e) CHECK(C.edge_sharp(e) == 10.f);
}

TEST_CASE("dihedral angles: a flat grid has none, a folded one has exactly the fold, boundaries are skipped") {
  test::Mesh g = test::grid(4, 3);
  Level L = g.level();
  CHECK(edges_sharper_than(L, g.positions, 0.5).empty());
  // Fold along x = 2 by 60 degrees: points with x > 2 rise with slope tan 60.
  for (Index v = 0; v < g.vertex_count; ++v)
    if (g.positions[3 * v] > 2) g.positions[3 * v + 2] = (g.positions[3 * v] - 2) * std::tan(std::numbers::pi / 3);
  const auto sharp = edges_sharper_than(L, g.positions, 45);
  CHECK(sharp.size() == 3);  // the three interior edges on x = 2
  for (Index e : sharp) {
    CHECK(g.positions[3 * L.edge_vertices[2 * e]] == 2);
    CHECK(g.positions[3 * L.edge_vertices[2 * e + 1]] == 2);
    CHECK(dihedral_angle_degrees(L, g.positions, e) == doctest::Approx(60).epsilon(1e-12));
  }
  for (Index e = 0; e < L.edge_count(); ++e)
    if (L.edge_on_boundary(e)) CHECK(dihedral_angle_degrees(L, g.positions, e) < 0);
  CHECK(contains(error_of([&] { edges_sharper_than(L, g.positions, 181); }), "between 0 and 180"));
  CHECK(contains(error_of([&] { edges_sharper_than(L, g.positions, NAN); }), "between 0 and 180"));
}

TEST_CASE("feature file: holes name faces, 0-based; a face that does not exist is refused") {
  Level cube = test::cube().level();
  apply_feature_tags(parse_feature_json(R"({"holes": [2, 5]})", "f"), cube);
  REQUIRE(cube.face_hole.size() == size_t(cube.face_count()));
  for (Index f = 0; f < cube.face_count(); ++f) CHECK(cube.is_hole(f) == (f == 2 || f == 5));
  Level other = test::cube().level();
  CHECK_THROWS_WITH_AS(apply_feature_tags(parse_feature_json(R"({"holes": [6]})", "f.json"), other),
                       doctest::Contains("f.json: holes[0]: face 6 does not exist"), Error);
  CHECK(other.face_hole.empty());  // refused before anything changed
  CHECK_THROWS_WITH_AS(parse_feature_json(R"({"holes": [-1]})", "f.json"), doctest::Contains("holes[0]"), Error);
}
