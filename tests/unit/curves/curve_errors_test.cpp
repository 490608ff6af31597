// Bad curve input: malformed curve scheme files, a curve scheme on a surface and a surface
// scheme on polylines, polylines the refiner cannot take. Each error names the place.
#include <doctest/doctest.h>

#include "curve_test_support.h"
#include "framework/curve/curve_level.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// A curve scheme file with `body` spliced into a valid two-point scheme's fields.
std::string load_error(const std::string& name, const std::string& text) {
  const auto file = write_temp_scheme(name, text);
  try {
    load_curve(file.string());
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

const char* kRules = R"("rules": [{"start": 0, "w": ["1"]}, {"start": 0, "w": ["1/2", "1/2"]}])";

std::string curve_file(const std::string& fields) {
  return std::string(R"({"name": "bad", "kind": "curve", )") + fields + "}";
}

}  // namespace

TEST_CASE("malformed curve scheme files: each message names the file and the place") {
  CHECK_MESSAGE(load_error("syntax", "{\"name\": \"bad\", \"kind\": \"curve\",\n \"rules\": [}").find("syntax.json:2:") !=
                    std::string::npos,
                "JSON syntax errors give line and column");
  CHECK(load_error("neither", curve_file(R"("arity": 2)")).find("exactly one of \"rules\"") != std::string::npos);
  CHECK(load_error("both", curve_file(std::string(kRules) + R"(, "mask": {"first": -1, "a": [0.5, 1, 0.5]})"))
            .find("exactly one of") != std::string::npos);
  CHECK(load_error("arity", curve_file(std::string(R"("arity": 4, )") + kRules)).find("arity: arity must be 2 or 3") !=
        std::string::npos);
  CHECK(load_error("arity-text", curve_file(std::string(R"("arity": "two", )") + kRules)).find("arity: expected 2 or 3") !=
        std::string::npos);
  CHECK(load_error("count", curve_file(R"("arity": 3, "rules": [{"start": 0, "w": ["1"]}])")).find("needs 3 rules") !=
        std::string::npos);
  CHECK(load_error("start", curve_file(R"("rules": [{"start": 0.5, "w": ["1"]}, {"start": 0, "w": ["1/2", "1/2"]}])"))
            .find("rules[0].start: expected a whole number") != std::string::npos);
  CHECK(load_error("empty", curve_file(R"("rules": [{"start": 0, "w": []}, {"start": 0, "w": ["1/2", "1/2"]}])"))
            .find("rules[0].w: expected a non-empty array") != std::string::npos);
  CHECK(load_error("sum", curve_file(R"("rules": [{"start": 0, "w": ["1"]}, {"start": -1, "w": ["-1/16", "9/16", "9/16", "1/16"]}])"))
            .find("rules[1]: weights sum to 1.125 at level 0, not 1") != std::string::npos);
  CHECK(load_error("parse", curve_file(R"("rules": [{"start": 0, "w": ["1"]}, {"start": 0, "w": ["1/2", "(1/2"]}])"))
            .find("rules[1].w[1]: formula '(1/2' does not parse") != std::string::npos);
  CHECK(load_error("uses-n", curve_file(R"("rules": [{"start": 0, "w": ["1"]}, {"start": 0, "w": ["1/n", "1 - 1/n"]}])"))
            .find("uses n; curve formulas may use j") != std::string::npos);
  CHECK(load_error("unknown-key", curve_file(std::string(kRules) + R"(, "split": "quad")")).find("unknown key \"split\"") !=
        std::string::npos);
  CHECK(load_error("ends", curve_file(std::string(kRules) + R"(, "ends": "clamped")"))
            .find("ends: 'clamped' is not one of: interpolate, uniform") != std::string::npos);
  CHECK(load_error("end-rules", curve_file(std::string(kRules) + R"(, "ends": {"rules": [{"w": ["1", "1"]}]})"))
            .find("ends.rules[0]: weights sum to 2") != std::string::npos);
  CHECK(load_error("state-next", curve_file(std::string(kRules) + R"(, "state": {"x": {"initial": "1"}})"))
            .find("state.x: missing \"next\"") != std::string::npos);
  CHECK(load_error("state-j", curve_file(std::string(kRules) + R"(, "state": {"x": {"initial": "1", "next": "x + j"}})"))
            .find("state.x.next: state variable 'x' depends on j") != std::string::npos);
  CHECK(load_error("mask-size", curve_file(R"("parameters": {"d": {"default": 2.5}}, "mask": {"first": -1, "size": "d + 2", "a": "binom(3, j)/4"})"))
            .find("mask.size: the number of coefficients evaluates to 4.5, not a whole number (parameters: d = 2.5)") !=
        std::string::npos);
  CHECK(load_error("mask-level", curve_file(R"("mask": {"first": -1, "a": ["1/2", "1 + 0*l", "1/2"]})"))
            .find("mask coefficients are stationary") != std::string::npos);
  CHECK(load_error("mask-gap", curve_file(R"("mask": {"first": 0, "a": [2]})")).find("no non-zero coefficient") !=
        std::string::npos);
  // A level-dependent scheme whose weights turn NaN at a later level fails when refining,
  // naming the state variable and the level.
  const auto late = write_temp_scheme("late-nan", curve_file(R"J("state": {"x": {"initial": "0.25", "next": "x - 1"}},
      "rules": [{"start": -1, "w": ["x", "1 - 2*x", "x"]}, {"start": 0, "w": ["sqrt(x) + 1/2", "1/2 - sqrt(x)"]}])J"));
  const auto scheme = load_curve(late.string());
  CHECK_THROWS_WITH_AS(refine_curves(*scheme, single_polyline(4, true), 3), doctest::Contains("rules[1].w[0]: weight"),
                       Error);
}

TEST_CASE("scheme kinds: a curve scheme is not a surface scheme and the reverse") {
  CHECK_THROWS_WITH_AS(load_scheme("chaikin"), doctest::Contains("is a curve scheme"), Error);
  CHECK_THROWS_WITH_AS(load_curve("loop"), doctest::Contains("is a surface scheme; polylines need a curve scheme"), Error);
  CHECK(scheme_kind("four-point") == "curve");
  CHECK(scheme_kind("catmull-clark") == "surface");
}

TEST_CASE("polylines the refiner refuses") {
  MeshData faces;
  faces.positions = wiggly_points(3);
  faces.face_vertices = {0, 1, 2};
  faces.face_offsets = {0, 3};
  CHECK_THROWS_WITH_AS(curve_level_from_mesh(faces, "tri.obj"),
                       doctest::Contains("tri.obj: the mesh has 1 faces, but a curve scheme refines polylines only"),
                       Error);
  MeshData empty;
  empty.positions = wiggly_points(3);
  CHECK_THROWS_WITH_AS(curve_level_from_mesh(empty, "points.obj"), doctest::Contains("no polylines"), Error);
  MeshData two_gon;
  two_gon.positions = wiggly_points(2);
  two_gon.line_vertices = {0, 1, 0};
  two_gon.line_offsets = {0, 3};
  CHECK_THROWS_WITH_AS(curve_level_from_mesh(two_gon, "l.obj"), doctest::Contains("closed polygon needs at least 3"), Error);
}
