// Plugin splitters and roles that return what the engine cannot use (issue 33): indices past
// the end or negative, arrays of the wrong size, throws of any type. Each must be refused
// with a message naming the plugin, its file and the function, never read.
#include <doctest/doctest.h>

#include <functional>
#include <string>

#include "framework/plugin/checked_topology.h"
#include "framework/plugin/plugin_api.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"
#include "support/test_meshes.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

CodeRules quad_rules() {
  CodeRules rules;
  rules.vertex = [](const CodeRuleInput&, Index v, Context, RowWriter& row) { row.add(v, 1.0); };
  rules.edge = [](const CodeRuleInput& in, Index e, int, Context, RowWriter& row) {
    row.add(in.parent.edge_vertices[2 * e], 0.5);
    row.add(in.parent.edge_vertices[2 * e + 1], 0.5);
  };
  rules.face = [](const CodeRuleInput& in, Index f, RowWriter& row) {
    for (Index v : in.parent.face(f)) row.add(v, 1.0 / in.parent.face_size(f));
  };
  rules.handles_features = true;
  return rules;
}

// Registers plugin NAME (file /plugins/NAME.so) with a splitter that is the quad split
// spoiled by `spoil`, and a scheme NAME-scheme using it; returns the scheme's name.
std::string register_splitter(const std::string& name, std::function<void(SplitResult&)> spoil) {
  PluginRegistry registry(name, "/plugins/" + name + ".so");
  SplitterInfo split;
  split.name = name + "-split";
  split.split = [spoil](const Level& parent, int) {
    SplitResult r = split_quad(parent);
    spoil(r);
    return r;
  };
  split.rule_elements = {OriginKind::Vertex, OriginKind::Edge, OriginKind::Face};
  registry.add_splitter(split);
  SurfaceSchemeSpec spec;
  spec.name = name + "-scheme";
  spec.split = split.name;
  spec.linear = [](const ParameterValues&) { return quad_rules(); };
  registry.add_surface_scheme(spec);
  registry.commit();
  return spec.name;
}

std::string refine_error(const std::string& scheme) {
  try {
    refine_mesh(cube(), scheme, 1);
  } catch (const Error& e) {
    return e.what();
  }
  return "<no error>";
}

// Registers plugin NAME with an edge role NAME-role whose functions are given, and a JSON
// scheme NAME-scheme whose edge rule sums it; returns the commit's error, or empty.
std::string register_role(const std::string& name,
                          std::function<void(const Level&, Index, int, std::vector<Index>&)> points,
                          std::function<int(int, int)> max_points) {
  PluginRegistry registry(name, "/plugins/" + name + ".so");
  RoleInfo role;
  role.name = name + "-role";
  role.element = Element::Edge;
  role.points = std::move(points);
  role.max_points = std::move(max_points);
  registry.add_role(role);
  registry.add_json_scheme(R"({"name": ")" + name + R"(-scheme", "split": "quad", "curve": "cubic-bspline",
    "rules": {"vertex": [{"at": "self", "w": "1"}], "edge": [{"sum": ")" +
                           name + R"(-role", "w": "1/2"}],
              "face": [{"sum": "vertices", "w": "1/k"}]}})");
  try {
    registry.commit();
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

void ends(const Level& L, Index e, int, std::vector<Index>& points) {
  points.push_back(L.edge_vertices[2 * e]);
  points.push_back(L.edge_vertices[2 * e + 1]);
}

}  // namespace

TEST_CASE("a plugin splitter that works passes the checks (the guard is not in the way)") {
  const std::string fine = register_splitter("split-fine", [](SplitResult&) {});
  const Refined r = refine_mesh(cube(), fine, 2);
  CHECK(r.hierarchy.levels.back().face_count() == 6 * 16);
  // Every built-in split's result passes the same checks.
  const Mesh g = grid(3, 2);
  for (const char* kind : {"quad", "sqrt3", "dual", "mid-edge"}) {
    CAPTURE(kind);
    const Level parent = std::string(kind) == "sqrt3" ? grid(3, 2, true).level() : g.level();
    const SplitKind k = split_kind_from_name(kind);
    CHECK(split_result_problem(parent, split(k, parent, 0), false, splitter_info(k).engine_propagates_tags).empty());
    CHECK(split_result_problem(parent, split(k, parent, 0, true), true, false).empty());
  }
}

TEST_CASE("a plugin splitter's child face past the child's vertices is refused, naming the plugin file and function") {
  const std::string scheme =
      register_splitter("split-past", [](SplitResult& r) { r.child.face_vertices[5] = 1000000; });
  const std::string message = refine_error(scheme);
  CHECK(contains(message, "plugin 'split-past' (/plugins/split-past.so), splitter 'split-past-split'"));
  CHECK(contains(message, "its split function (step 0)"));
  CHECK(contains(message, "face_vertices[5] is 1000000, but the level has 26 vertices"));
}

TEST_CASE("negative indices in a plugin split's result are refused") {
  CHECK(
      contains(refine_error(register_splitter("split-neg-face", [](SplitResult& r) { r.child.face_vertices[0] = -5; })),
               "face_vertices[0] is -5"));
  CHECK(contains(refine_error(register_splitter("split-neg-origin", [](SplitResult& r) { r.origins.parent[3] = -1; })),
                 "origins.parent[3] is -1"));
  CHECK(
      contains(refine_error(register_splitter("split-neg-ring", [](SplitResult& r) { r.child.vertex_edges[2] = -7; })),
               "vertex_edges[2] is -7"));
}

TEST_CASE("a plugin split's arrays of the wrong size are refused") {
  CHECK(contains(
      refine_error(register_splitter("split-short-origins", [](SplitResult& r) { r.origins.kind.pop_back(); })),
      "origins.kind has 25 entries, not 26"));
  CHECK(contains(
      refine_error(register_splitter("split-offsets", [](SplitResult& r) { r.child.face_offsets.back() += 4; })),
      "face_offsets ends at"));
  CHECK(contains(
      refine_error(register_splitter("split-rings", [](SplitResult& r) { r.child.vertex_ring_offsets.pop_back(); })),
      "vertex_ring_offsets has 26 entries, not 27"));
  CHECK(contains(refine_error(register_splitter("split-tags", [](SplitResult& r) { r.child.edge_sharpness = {1.f}; })),
                 "edge_sharpness has 1 entries, not 48 (or none)"));
  CHECK(contains(refine_error(register_splitter("split-vc", [](SplitResult& r) { r.child.vertex_count += 3; })),
                 "origins.kind has 26 entries, not 29"));
}

TEST_CASE("a plugin split whose topology contradicts itself is refused") {
  // A face's edge that does not join its corners (reads edge 0's vertices as this corner's).
  CHECK(contains(refine_error(register_splitter("split-edge", [](SplitResult& r) { r.child.face_edges[0] = 47; })),
                 "face 0 corner 0 runs from vertex"));
  // Runs that say child 0 comes from parent vertex 1.
  CHECK(contains(refine_error(register_splitter("split-runs", [](SplitResult& r) { r.origins.parent[0] = 1; })),
                 "origins.runs says child vertex 0"));
}

TEST_CASE("whatever a plugin split throws becomes an Error naming the plugin and the function") {
  const std::string odd = register_splitter("split-throws", [](SplitResult&) { throw 7; });
  CHECK(contains(refine_error(odd),
                 "plugin 'split-throws' (/plugins/split-throws.so), splitter 'split-throws-split': "
                 "its split function (step 0) threw something that is not a std::exception"));
  const std::string std_error =
      register_splitter("split-throws-std", [](SplitResult&) { throw std::length_error("vector::reserve"); });
  CHECK(contains(refine_error(std_error), "threw an exception: vector::reserve"));
}

TEST_CASE("a plugin splitter with a scale the analysis cannot use is refused when the plugin loads") {
  PluginRegistry registry("split-scale", "/plugins/split-scale.so");
  SplitterInfo split;
  split.name = "split-scale-split";
  split.split = [](const Level& parent, int) { return split_quad(parent); };
  split.scale = 0.5;
  registry.add_splitter(split);
  CHECK_THROWS_WITH_AS(registry.commit(),
                       doctest::Contains("splitter 'split-scale-split': scale must be finite and above 1"), Error);
  CHECK_THROWS_AS(split_kind_from_name("split-scale-split"), Error);  // nothing of it stays
}

TEST_CASE("a plugin role's points out of range or thrown are refused naming the plugin file and the role") {
  const auto max4 = [](int, int) { return 4; };
  REQUIRE(register_role(
              "role-past", [](const Level& L, Index, int, std::vector<Index>& p) { p.push_back(L.vertex_count); },
              max4) == "");
  CHECK(contains(refine_error("role-past-scheme"),
                 "plugin 'role-past' (/plugins/role-past.so), role 'role-past-role': "
                 "its points function gives element 0 the point 8, but the level "
                 "has 8 vertices (0 to 7)"));
  REQUIRE(register_role(
              "role-neg", [](const Level&, Index, int, std::vector<Index>& p) { p.push_back(-3); }, max4) == "");
  CHECK(contains(refine_error("role-neg-scheme"), "gives element 0 the point -3"));
  REQUIRE(register_role(
              "role-throws", [](const Level&, Index, int, std::vector<Index>&) { throw "text"; }, max4) == "");
  CHECK(contains(refine_error("role-throws-scheme"),
                 "role 'role-throws-role': its points function (element 0) threw "
                 "something that is not a std::exception"));
  // More points than max_points says: the weight tables have no room for them.
  REQUIRE(register_role(
              "role-many", [](const Level&, Index, int, std::vector<Index>& p) { p.assign(9, 0); }, max4) == "");
  CHECK(contains(refine_error("role-many-scheme"), "gave 9 points, more than its max_points"));
}

TEST_CASE("a plugin role's max_points out of range or thrown is refused, naming the plugin file and the role") {
  REQUIRE(register_role("role-max-neg", ends, [](int, int) { return -1; }) == "");
  CHECK(contains(refine_error("role-max-neg-scheme"),
                 "plugin 'role-max-neg' (/plugins/role-max-neg.so), role "
                 "'role-max-neg-role': its max_points function gives -1"));
  REQUIRE(register_role("role-max-huge", ends, [](int, int) { return 1 << 30; }) == "");
  CHECK(contains(refine_error("role-max-huge-scheme"), "it must be 0 to 65536"));
  REQUIRE(register_role("role-max-throws", ends, [](int, int) -> int { throw 1.5; }) == "");
  const std::string thrown = refine_error("role-max-throws-scheme");
  CHECK(contains(thrown, "role 'role-max-throws-role': its max_points function (n = "));
  CHECK(contains(thrown, "not a std::exception"));
}
