#include <doctest/doctest.h>

#include <filesystem>

#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"
#include "support/scheme_files.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

fs::path write_scheme(const std::string& name, const std::string& text) {
  return test::write_scheme_file("subdivkit-scheme-tests", name, text);
}

std::string quad_scheme(const std::string& vertex_rule) {
  return R"({"name": "t", "split": "quad", "curve": "cubic-bspline", "rules": {
    "face": [{"sum": "vertices", "w": "1/k"}],
    "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
    "vertex": )" + vertex_rule + "}}";
}

}  // namespace

TEST_CASE("malformed JSON names the file, line and column") {
  const auto f = write_scheme("malformed", "{\n  \"name\": \"x\",\n  \"split\": \"quad\"\n  \"rules\": {}\n}");
  CHECK_THROWS_WITH_AS(load_scheme(f.string()), doctest::Contains("malformed.json:4:"), Error);
}

TEST_CASE("unknown role names the place and lists the roles") {
  const auto f = write_scheme("role", quad_scheme(R"J([{"sum": "neighbours", "w": "1"}])J"));
  CHECK_THROWS_WITH_AS(load_scheme(f.string()), doctest::Contains("rules.vertex[0]: unknown role 'neighbours'"), Error);
}

TEST_CASE("a formula that does not parse names its place") {
  const auto f = write_scheme("formula", quad_scheme(R"J([{"at": "self", "w": "(n-2/n"}])J"));
  CHECK_THROWS_WITH_AS(load_scheme(f.string()), doctest::Contains("rules.vertex[0]: formula '(n-2/n' does not parse"), Error);
}

TEST_CASE("weights that do not sum to one are refused when refining, with the valence") {
  const auto f = write_scheme("affine", quad_scheme(R"J([{"at": "self", "w": "(n-2)/n"}, {"sum": "ring", "w": "1/n^2"}])J"));
  auto scheme = load_scheme(f.string());
  CHECK_THROWS_WITH_AS(refine(*scheme, test::cube().level(), {}), doctest::Contains("summing to"), Error);
}

TEST_CASE("a formula giving NaN is refused") {
  const auto f = write_scheme("nan", quad_scheme(R"J([{"at": "self", "w": "sqrt(-n)"}, {"sum": "ring", "w": "0"}])J"));
  auto scheme = load_scheme(f.string());
  CHECK_THROWS_AS(refine(*scheme, test::cube().level(), {}), Error);
}

TEST_CASE("parameters: unknown names, bad choices and out-of-range values are refused") {
  CHECK_THROWS_WITH_AS(load_scheme("loop", {{"gamma", "1"}}), doctest::Contains("no parameter 'gamma'"), Error);
  CHECK_THROWS_WITH_AS(load_scheme("loop", {{"beta", "stam"}}), doctest::Contains("choose one of: loop, warren"), Error);
  const auto f = write_scheme("range", R"({"name": "r", "split": "quad", "curve": "cubic-bspline",
    "parameters": {"a": {"default": 0.5, "min": 0, "max": 1}},
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}], "edge": [{"sum": "ends", "w": "1/2"}],
              "vertex": [{"at": "self", "w": "a"}, {"sum": "ring", "w": "(1-a)/n"}]}})");
  CHECK_NOTHROW(load_scheme(f.string(), {{"a", "0.25"}}));
  CHECK_THROWS_WITH_AS(load_scheme(f.string(), {{"a", "2"}}), doctest::Contains("outside its range [0, 1]"), Error);
}

TEST_CASE("unknown scheme names list the known ones; missing files are named") {
  CHECK_THROWS_WITH_AS(load_scheme("catmul-clark"), doctest::Contains("catmull-clark"), Error);
  CHECK_THROWS_WITH_AS(load_scheme("/nonexistent/x.json"), doctest::Contains("does not exist"), Error);
  // A name longer than a file name may be (fuzz_scheme_sequence): the file system's error
  // escaped as an internal one.
  const std::string too_long = "doo-sabin" + std::string(300, 'x');
  CHECK_THROWS_WITH_AS(load_scheme(too_long), doctest::Contains("unknown scheme"), Error);
  CHECK_THROWS_WITH_AS(load_scheme(too_long + ".json"), doctest::Contains("does not exist"), Error);
  CHECK_THROWS_WITH_AS(load_scheme_sequence(too_long + ":1", 1, {}), doctest::Contains("unknown scheme"), Error);
}

TEST_CASE("load-time checks: unknown names in formulas, reserved names, wrong JSON types") {
  const auto unknown = write_scheme("unknown-name", quad_scheme(R"J([{"at": "self", "w": "1 - alpha"}, {"sum": "ring", "w": "alpha/n"}])J"));
  CHECK_THROWS_WITH_AS(load_scheme(unknown.string()), doctest::Contains("rules.vertex[0]"), Error);
  const auto reserved = write_scheme("reserved", R"J({"name": "r", "split": "quad", "curve": "cubic-bspline",
    "parameters": {"n": {"default": 1}},
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}], "edge": [{"sum": "ends", "w": "1/2"}], "vertex": [{"at": "self", "w": "1"}]}})J");
  CHECK_THROWS_WITH_AS(load_scheme(reserved.string()), doctest::Contains("'n' is a reserved name"), Error);
  const auto typed = write_scheme("typed", R"J({"name": "t", "split": "quad", "curve": "cubic-bspline",
    "parameters": {"a": {"default": 0.5, "min": "zero"}},
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}], "edge": [{"sum": "ends", "w": "1/2"}], "vertex": [{"at": "self", "w": "1"}]}})J");
  CHECK_THROWS_WITH_AS(load_scheme(typed.string()), doctest::Contains("parameters.a.min: must be a number, got the string \"zero\""), Error);
  const auto bare = write_scheme("bare", R"J({"name": "t", "split": "quad", "curve": "cubic-bspline",
    "parameters": {"a": 0.5},
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}], "edge": [{"sum": "ends", "w": "1/2"}], "vertex": [{"at": "self", "w": "1"}]}})J");
  CHECK_THROWS_WITH_AS(load_scheme(bare.string()), doctest::Contains("a parameter is an object"), Error);
}

TEST_CASE("weights that do not sum to one are refused the same way without stencil tables") {
  const auto f = write_scheme("affine-direct", quad_scheme(R"J([{"at": "self", "w": "(n-2)/n"}, {"sum": "ring", "w": "1/n^2"}])J"));
  auto scheme = load_scheme(f.string());
  RefineOptions o;
  o.levels = 1;
  const test::Mesh cube = test::cube();
  const Hierarchy h = refine_topology(*scheme, cube.level(), o);
  std::string with_tables;
  try {
    refine(*scheme, cube.level(), o);
  } catch (const Error& e) {
    with_tables = e.what();
  }
  REQUIRE(with_tables.find("summing to") != std::string::npos);
  for (bool plans : {true, false}) {
    o.evaluation.use_row_plans = plans;
    CHECK_THROWS_WITH_AS(step_values(*scheme, h, 0, cube.positions, 3, o), with_tables.c_str(), Error);
  }
}
