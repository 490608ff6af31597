// Every mistake in a scheme file is reported at its place: FILE:LINE: json.path: ... —
// references to other schemes (a "curve" name, a part of a scheme sequence), a definition
// holding an unknown name (named, with the fix), JSON values of the wrong type
// (said in words), and rules that are not affine at the valence a mesh asks for (named as
// `subdiv validate` names them).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "framework/util/json_path_line.h"
#include "support/refine_helpers.h"
#include "support/scheme_files.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

fs::path write_scheme(const std::string& name, const std::string& text) {
  return test::write_scheme_file("subdivkit-error-places", name, text);
}

template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "<no error>";
}

std::string load_error(const fs::path& file) {
  return error_of([&] { load_scheme(file.string()); });
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A quad scheme (Catmull & Clark 1978's face and edge points) with the given lines
// spliced in before "rules" and the given vertex rule; line numbers count from 1.
std::string quad_scheme(const std::string& before_rules, const std::string& vertex_rule) {
  return "{\n\"name\": \"t\",\n\"split\": \"quad\",\n" + before_rules +
         "\"rules\": {\n"
         "  \"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}],\n"
         "  \"edge\": [{\"sum\": \"ends\", \"w\": \"1/4\"}, {\"sum\": \"faces\", \"new\": \"face\", \"w\": \"1/4\"}],\n"
         "  \"vertex\": " + vertex_rule + "\n}}\n";
}

const std::string kCatmullClarkVertex =
    R"([{"at": "self", "w": "(n-3)/n"}, {"sum": "faces", "new": "face", "w": "1/n^2"}, {"sum": "edges", "new": "edge", "w": "2/n^2"}])";

}  // namespace

TEST_CASE("json_path_line finds keys and array elements, and nothing that is not there") {
  const std::string text = "{\n \"a\": {\"b\": [1,\n  {\"c\": \"x, ]}\"},\n  3]},\n \"d\": 2}";
  CHECK(json_path_line(text, "a") == 2);
  CHECK(json_path_line(text, "a.b[1].c") == 3);
  CHECK(json_path_line(text, "a.b[2]") == 4);
  CHECK(json_path_line(text, "d") == 5);
  CHECK(json_path_line(text, "a.b[3]") == 0);
  CHECK(json_path_line(text, "e") == 0);
  CHECK(json_path_line(text, "not a path") == 0);
  CHECK(with_json_line("f.json: d: bad", "f.json", text) == "f.json:5: d: bad");
  CHECK(with_json_line("f.json: missing \"x\"", "f.json", text) == "f.json: missing \"x\"");
}

TEST_CASE("json_path_line on every truncation of a text stays inside it (a file changed after loading)") {
  const std::string text = quad_scheme("\"curve\": \"cubic-bspline\",\n\"parameters\": {\"t\": {\"default\": 1}},\n",
                                       kCatmullClarkVertex);
  const int lines = 1 + int(std::count(text.begin(), text.end(), '\n'));
  for (size_t n = 0; n <= text.size(); ++n)
    for (const char* path : {"rules.vertex[2].w", "parameters.t.default", "curve", "rules.edge[9]"}) {
      const int line = json_path_line(std::string_view(text).substr(0, n), path);
      CHECK((line >= 0 && line <= lines));
    }
  CHECK(json_path_line(text, "rules.vertex[2].w") == 9);
}

TEST_CASE("an unknown curve scheme is reported at the \"curve\" that names it") {
  const fs::path file = write_scheme("curve-typo", quad_scheme("\"curve\": \"cubic-bspilne\",\n", kCatmullClarkVertex));
  const std::string m = load_error(file);
  CHECK(contains(m, file.string() + ":4: curve: unknown scheme 'cubic-bspilne'"));

  const fs::path surface = write_scheme("curve-is-surface", quad_scheme("\"curve\": \"loop\",\n", kCatmullClarkVertex));
  CHECK(contains(load_error(surface), surface.string() + ":4: curve: 'loop' is a surface scheme; name a curve scheme"));

  const fs::path in_step = write_scheme("step-curve-typo", R"({"name": "t", "steps": [
  {"split": "quad", "curve": "chaikn", "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
   "edge": [{"sum": "ends", "w": "1/2"}], "vertex": [{"at": "self", "w": "1"}]}}]})");
  CHECK(contains(load_error(in_step), in_step.string() + ":2: steps[0].curve: unknown scheme 'chaikn'"));
}

TEST_CASE("a part of a scheme sequence that fails is named within the sequence") {
  const std::string m = error_of([] { load_scheme_sequence("loop:1,catmul-clark", 2, {}); });
  CHECK(contains(m, "scheme sequence 'loop:1,catmul-clark', part 'catmul-clark': unknown scheme 'catmul-clark'"));
}

TEST_CASE("an unknown name in a definition is blamed on the definition, with the fix") {
  const fs::path file = write_scheme(
      "definition-typo",
      quad_scheme("\"curve\": \"cubic-bspline\",\n\"definitions\": {\n  \"c\": \"tt\",\n  \"a\": \"1 - c/n\"},\n",
                  R"([{"at": "self", "w": "a"}, {"sum": "ring", "w": "c/n^2"}])"));
  const std::string m = load_error(file);
  INFO(m);
  CHECK(contains(m, file.string() + ":6: definitions.c: formula 'tt' uses 'tt', which is not defined: declare it "
                   "under \"parameters\" (with a default) or \"definitions\""));
  // A typo that muParser finds while compiling is placed the same way.
  const fs::path compiled = write_scheme(
      "definition-syntax",
      quad_scheme("\"curve\": \"cubic-bspline\",\n\"definitions\": {\n  \"c\": \"3/8 tt\"},\n", kCatmullClarkVertex));
  CHECK(contains(load_error(compiled), compiled.string() + ":6: definitions.c: formula '3/8 tt' does not parse"));
}

TEST_CASE("JSON values of the wrong type are said in words at their place") {
  const fs::path min = write_scheme("min-string", quad_scheme("\"curve\": \"cubic-bspline\",\n\"parameters\": {\"t\": {\"default\": 1, \"min\": \"0\"}},\n", kCatmullClarkVertex));
  CHECK(contains(load_error(min), min.string() + ":5: parameters.t.min: must be a number, got the string \"0\""));

  const fs::path term = write_scheme("term-string", quad_scheme("\"curve\": \"cubic-bspline\",\n",
                                                                R"([{"at": "self", "w": "1/2"}, "1/2"])"));
  const std::string m = load_error(term);
  CHECK(contains(m, term.string() + ":8: rules.vertex[1]: must be a JSON object {...}, got the string \"1/2\""));
  CHECK_FALSE(contains(m, "iterator"));

  const fs::path flag = write_scheme("exclusive-number", quad_scheme("\"curve\": \"cubic-bspline\",\n\"parameters\": {\"t\": {\"default\": 1, \"min_exclusive\": 1}},\n", kCatmullClarkVertex));
  CHECK(contains(load_error(flag), "parameters.t.min_exclusive: must be true or false, got the number 1"));

  const fs::path weight = write_scheme("weight-array", quad_scheme("\"curve\": \"cubic-bspline\",\n",
                                                                   R"([{"at": "self", "w": [1]}])"));
  CHECK(contains(load_error(weight), "rules.vertex[0].w: must be a number or a formula string, got an array [1]"));
}

TEST_CASE("a rule that is not affine at the mesh's valence is named at its place when refining") {
  // Catmull-Clark's vertex rule sums to 1 at every valence; this one only at valence 4
  // (the loader's sample), so the cube's valence-3 corners are the first to fail.
  const fs::path file = write_scheme(
      "affine-at-4", quad_scheme("\"curve\": \"cubic-bspline\",\n",
                                 R"([{"at": "self", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/16"},
  {"sum": "edges", "new": "edge", "w": "1/8"}])"));
  auto scheme = load_scheme(file.string());
  RefineOptions o;
  o.levels = 1;
  const test::Mesh cube = test::cube();
  const std::string m = error_of([&] { refine(*scheme, cube.level(), o); });
  CHECK(contains(m, "(valence 3)"));
  CHECK(contains(m, file.string() + ":8: rules.vertex (smooth)"));
}
