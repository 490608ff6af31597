// Per-vertex scheme parameters ("per_vertex": true; framework/engine/vertex_parameters.h):
// a vertex rule reads the value at its own vertex, so each vertex point must be exactly
// what a refinement with that one value gives; the other points do not read it; later
// levels carry the values linearly (an edge point takes the mean of its ends); the loader
// keeps per-vertex parameters out of rules that have no single vertex.
#include <algorithm>
#include <cmath>
#include <doctest/doctest.h>
#include <fmt/format.h>

#include "framework/engine/evaluator.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

const char* kShape = "catmull-clark-shape";

std::vector<double> varying_lambda(Index count) {
  std::vector<double> lambda(static_cast<size_t>(count), 0.0);
  for (Index v = 0; v < count; ++v) lambda[v] = 0.4 + 0.6 * double((v * 5) % 9) / 8.0;
  return lambda;
}

std::vector<double> refined_with(const Mesh& mesh, int levels, const RefineOptions& o, const ParameterOverrides& p) {
  return refine_mesh(mesh, kShape, levels, o, p).positions;
}

std::string text_of(double x) { return fmt::format("{:.17g}", x); }

}  // namespace

TEST_CASE("one value at every vertex gives the same bits as the scheme parameter, in tables and in step_values") {
  const Mesh mesh = torus(6, 5);
  RefineOptions per_vertex;
  per_vertex.vertex_parameters["lambda"] = std::vector<double>(size_t(mesh.level().vertex_count), 0.7);
  const std::vector<double> scalar = refined_with(mesh, 2, {}, {{"lambda", "0.7"}});
  CHECK(refined_with(mesh, 2, per_vertex, {}) == scalar);
  // step_values, level by level, from refine_topology's hierarchy (it reads new face points
  // back rather than expanding them, so it is compared with itself at the scalar value).
  auto stepped = [&](const std::shared_ptr<const Scheme>& scheme, const RefineOptions& o) {
    const Hierarchy topology = refine_topology(*scheme, mesh.level(), o);
    std::vector<double> values = mesh.positions;
    for (int l = 0; l < o.levels; ++l) values = step_values(*scheme, topology, l, values, 3, o);
    return values;
  };
  per_vertex.levels = 2;
  RefineOptions plain;
  plain.levels = 2;
  CHECK(stepped(load_scheme(kShape), per_vertex) == stepped(load_scheme(kShape, {{"lambda", "0.7"}}), plain));
}

TEST_CASE("each vertex point is the refinement with its own vertex's value; edge and face points read none") {
  for (const Mesh& mesh : {torus(6, 5), grid(4, 3)}) {
    const Level base = mesh.level();
    const std::vector<double> lambda = varying_lambda(base.vertex_count);
    RefineOptions o;
    o.vertex_parameters["lambda"] = lambda;
    const Refined got = refine_mesh(mesh, kShape, 1, o);
    const ChildOrigins& origins = got.hierarchy.origins[0];
    const std::vector<double> any = refined_with(mesh, 1, {}, {{"lambda", "0.9"}});
    for (size_t c = 0; c < origins.kind.size(); ++c) {
      CAPTURE(c);
      std::vector<double> expected = any;
      if (origins.kind[c] == OriginKind::Vertex)
        expected = refined_with(mesh, 1, {}, {{"lambda", text_of(lambda[origins.parent[c]])}});
      for (int k = 0; k < 3; ++k) CHECK(got.positions[3 * c + k] == doctest::Approx(expected[3 * c + k]).epsilon(1e-15));
    }
  }
}

TEST_CASE("on the next level an edge point's vertex point reads the mean of the edge's ends' values") {
  const Mesh mesh = torus(6, 5);
  const Level base = mesh.level();
  const std::vector<double> lambda = varying_lambda(base.vertex_count);
  RefineOptions o;
  o.vertex_parameters["lambda"] = lambda;
  const Refined two = refine_mesh(mesh, kShape, 2, o);
  const Refined one = refine_mesh(mesh, kShape, 1, o);
  const Level& level1 = one.hierarchy.levels[1];
  const ChildOrigins& first = one.hierarchy.origins[0];
  const ChildOrigins& second = two.hierarchy.origins[1];
  Mesh middle;  // level 1 as a mesh, to refine it once more with one value
  middle.positions = one.positions;
  middle.vertex_count = level1.vertex_count;
  for (Index f = 0; f < level1.face_count(); ++f) {
    for (Index v : level1.face(f)) middle.corners.push_back(v);
    middle.offsets.push_back(Index(middle.corners.size()));
  }
  int checked = 0;
  for (size_t c = 0; c < second.kind.size() && checked < 6; ++c) {
    const Index parent = second.parent[c];
    if (second.kind[c] != OriginKind::Vertex || first.kind[parent] != OriginKind::Edge) continue;
    const Index e = first.parent[parent];
    const double mean = 0.5 * (lambda[base.edge_vertices[2 * e]] + lambda[base.edge_vertices[2 * e + 1]]);
    const std::vector<double> expected = refined_with(middle, 1, {}, {{"lambda", text_of(mean)}});
    CAPTURE(c);
    for (int k = 0; k < 3; ++k) CHECK(two.positions[3 * c + k] == doctest::Approx(expected[3 * c + k]).epsilon(1e-14));
    ++checked;
  }
  CHECK(checked == 6);
}

TEST_CASE("per-vertex values are checked: count, range (naming the vertex), and a scheme that reads them") {
  const Mesh mesh = torus(4, 4);
  RefineOptions o;
  o.vertex_parameters["lambda"] = {0.5, 0.5};
  CHECK_THROWS_WITH_AS(refine_mesh(mesh, kShape, 1, o), doctest::Contains("2 values for a mesh of 16 vertices"), Error);
  o.vertex_parameters["lambda"] = std::vector<double>(16, 0.5);
  o.vertex_parameters["lambda"][9] = 1.5;
  CHECK_THROWS_WITH_AS(refine_mesh(mesh, kShape, 1, o),
                       doctest::Contains("'lambda' (vertex 9): lambda = 1.5 is outside its range (0.35, 1]"), Error);
  o.vertex_parameters["lambda"][9] = std::nan("");
  CHECK_THROWS_WITH_AS(refine_mesh(mesh, kShape, 1, o), doctest::Contains("(vertex 9)"), Error);
  RefineOptions other;
  other.vertex_parameters["lambda"] = std::vector<double>(16, 0.5);
  CHECK_THROWS_WITH_AS(refine_mesh(mesh, "catmull-clark", 1, other),
                       doctest::Contains("no scheme of the run reads it per vertex"), Error);
}

TEST_CASE("the loader keeps per-vertex parameters to vertex rules") {
  const std::string head = R"({"name": "t", "split": "quad", "curve": "cubic-bspline",
    "parameters": {"a": {"default": 0.5, "per_vertex": true}, "c": {"default": "x", "choices": ["x"]}},)";
  const std::string vertex_ok = R"("vertex": [{"at": "self", "w": "a"}, {"sum": "ring", "w": "(1 - a)/n"}])";
  auto scheme = [&](const std::string& edge, const std::string& extra = "") {
    return head + extra + R"("rules": {"face": [{"sum": "vertices", "w": "1/k"}], "edge": [)" + edge + "], " +
           vertex_ok + "}}";
  };
  CHECK_NOTHROW(load_scheme_text(scheme(R"({"sum": "ends", "w": "1/2"})"), "t.json"));
  CHECK_THROWS_WITH_AS(load_scheme_text(scheme(R"({"sum": "ends", "w": "a/2 + (1 - a)/2"})"), "t.json"),
                       doctest::Contains("rules.edge[0]: reads parameter 'a', which is per vertex"), Error);
  // Through a definition too.
  CHECK_THROWS_WITH_AS(load_scheme_text(scheme(R"({"sum": "ends", "w": "h"})", R"("definitions": {"h": "a - a + 1/2"},)"),
                                        "t.json"),
                       doctest::Contains("which is per vertex"), Error);
  const std::string choice = R"({"name": "t", "split": "quad", "parameters": {"c": {"default": "x", "choices": ["x"],
    "per_vertex": true}}, "rules": {"face": [{"sum": "vertices", "w": "1/k"}]}})";
  CHECK_THROWS_WITH_AS(load_scheme_text(choice, "t.json"), doctest::Contains("only numeric parameters can be per vertex"),
                       Error);
}

// refine_topology carries the values down once (Hierarchy::vertex_parameters); step_values
// must read the values of the options it is given, whether the hierarchy holds them, holds
// other values, or holds none: the carried values are a linear function of the base ones,
// so each route gives the same bits as a hierarchy refined with exactly those values.
TEST_CASE("step_values reads the options' per-vertex values, whatever the hierarchy carried") {
  const Mesh mesh = torus(6, 5);
  const auto scheme = load_scheme(kShape);
  RefineOptions with, other;
  with.levels = other.levels = 3;
  with.vertex_parameters["lambda"] = varying_lambda(mesh.level().vertex_count);
  std::vector<double> reversed = with.vertex_parameters["lambda"];
  std::reverse(reversed.begin(), reversed.end());
  other.vertex_parameters["lambda"] = reversed;
  const Hierarchy carried = refine_topology(*scheme, mesh.level(), with);
  REQUIRE(carried.vertex_parameters.size() == carried.levels.size());
  Hierarchy bare = carried;  // as a hierarchy built by hand: no carried values
  bare.vertex_parameters.clear();
  const Hierarchy for_other = refine_topology(*scheme, mesh.level(), other);
  auto stepped = [&](const Hierarchy& h, const RefineOptions& o) {
    std::vector<double> values = mesh.positions;
    for (int l = 0; l < o.levels; ++l) values = step_values(*scheme, h, l, values, 3, o);
    return values;
  };
  const std::vector<double> reference = stepped(carried, with);
  CHECK(stepped(bare, with) == reference);
  CHECK(stepped(carried, other) == stepped(for_other, other));
  CHECK(stepped(carried, other) != reference);
  // The Evaluator takes the same values.
  CHECK(Evaluator(*scheme, carried, other).evaluate(mesh.positions, 3) == stepped(for_other, other));
}
