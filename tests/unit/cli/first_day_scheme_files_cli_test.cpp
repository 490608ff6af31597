// Scheme files as a first-day author writes them, through `subdiv refine`, `validate` and
// `analyze`: each mistake is refused with the file, the line and the fix, a non-zero exit and
// no output file.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

const std::string kCube = source_path("examples/meshes/cube.obj");

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A Catmull-Clark copy, one part per line, with `vertex` as its vertex rule and `after_face`
// written after the face rule's term (line 5).
std::string quad_scheme(const std::string& vertex, const std::string& after_face = "") {
  return "{\"name\": \"mine\", \"split\": \"quad\", \"curve\": \"cubic-bspline\",\n"   // 1
         "\"rules\": {\n"                                                               // 2
         "  \"edge\": [{\"sum\": \"ends\", \"w\": \"1/4\"},\n"                          // 3
         "           {\"sum\": \"faces\", \"new\": \"face\", \"w\": \"1/4\"}],\n"       // 4
         "  \"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}" + after_face + "],\n"   // 5
         "  \"vertex\": " + vertex + "\n"                                               // 6
         "}}\n";
}

const std::string kVertex =
    R"([{"at": "self", "w": "(n-2)/n"}, {"sum": "ring", "w": "1/n^2"}, {"sum": "faces", "new": "face", "w": "1/n^2"}])";

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

// The three commands on one file: each refuses with `expected`, exit 1, no file written.
void all_refuse(const fs::path& dir, const fs::path& scheme, const std::string& expected) {
  const fs::path out = dir / "out.vtp", json = dir / "report.json";
  for (const std::string& command : {"refine " + kCube + " -l 1 -o " + out.string() + " -s ",
                                     std::string("validate "), "analyze --json " + json.string() + " "}) {
    CAPTURE(command);
    const CliResult r = run_subdiv(command + scheme.string());
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.output, expected), r.output);
  }
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(fs::exists(json));
}

}  // namespace

TEST_CASE("a comma after the last member, a comment, single quotes: the fix with the place") {
  const auto dir = fresh_dir("first-day-json-syntax");
  all_refuse(dir, write(dir, "comma.json", quad_scheme(kVertex, ",\n")),
             "comma.json:6:1: malformed JSON: syntax error while parsing value - unexpected ']'; expected '[', '{', "
             "or a literal; the comma at line 5, column 43 follows the last element of the array, and JSON allows "
             "none there: remove it");
  std::string object = quad_scheme(kVertex);
  object.replace(object.rfind("}}"), 2, "},\n}");
  all_refuse(dir, write(dir, "object.json", object),
             "object.json:8:1: malformed JSON: syntax error while parsing object key - unexpected '}'; expected "
             "string literal; the comma at line 7, column 2 follows the last member of the object");
  all_refuse(dir, write(dir, "comment.json", "// my scheme\n" + quad_scheme(kVertex)),
             "comment.json:1:1: malformed JSON: syntax error while parsing value - invalid literal; last read: '/'; "
             "JSON has no comments: remove it");
  all_refuse(dir, write(dir, "quotes.json", "{'name': 'mine'}"), "JSON strings take double quotes");
}

TEST_CASE("formula and value mistakes name their place once, with the fix") {
  const auto dir = fresh_dir("first-day-values");
  // muParser reads a number beyond a double as a name: it was "not defined".
  const std::string huge = R"([{"at": "self", "w": "1e400"}])";
  all_refuse(dir, write(dir, "huge.json", quad_scheme(huge)),
             "huge.json:6: rules.vertex[0]: formula '1e400' has the number '1e400', which a double cannot hold");
  std::string split = quad_scheme(kVertex);
  split.replace(split.find("\"quad\""), 6, "4");
  all_refuse(dir, write(dir, "split.json", split), "split.json:1: split: must be a string, got the number 4");
  CHECK_FALSE(contains(run_subdiv("validate " + (dir / "split.json").string()).output, "split: " +
                                                                                        (dir / "split.json").string()));
}

TEST_CASE("validate names the rule's own line and refuses a scheme without the rules its split needs") {
  const auto dir = fresh_dir("first-day-validate");
  // "1/4" is the edge rule's text too (line 3); the vertex rule that sums to 1/4 is on line 6.
  const CliResult quarter =
      run_subdiv("validate " + write(dir, "quarter.json", quad_scheme(R"([{"at": "self", "w": "1/4"}])")).string());
  CHECK(quarter.exit_code == 1);
  CHECK_MESSAGE(contains(quarter.output, "quarter.json:6: rules.vertex (smooth): weights sum to 0.25"), quarter.output);
  // An empty rule has no formula to find: the line was 0.
  const CliResult empty = run_subdiv("validate " + write(dir, "empty.json", quad_scheme("[]")).string());
  CHECK(empty.exit_code == 1);
  CHECK_MESSAGE(contains(empty.output, "empty.json:6: rules.vertex (smooth): weights sum to 0"), empty.output);
  // No rules at all: "ok (..., 0 checks)", while refine refused every mesh.
  const fs::path none = write(dir, "none.json", R"({"name": "none", "split": "quad", "rules": {}})");
  const CliResult validated = run_subdiv("validate " + none.string());
  CHECK(validated.exit_code == 1);
  CHECK_MESSAGE(contains(validated.output, "none.json:1: rules: no rules, so the quad split's new points have no "
                                           "positions; add rules.vertex, rules.edge, rules.face"),
                validated.output);
}

TEST_CASE("analyze: rules that refine no neighbourhood are an error, not a verdict") {
  const auto dir = fresh_dir("first-day-analyze");
  // 1/(k-4) divides by zero on quads: every valence's analysis fails to refine.
  const fs::path scheme =
      write(dir, "div0.json", quad_scheme(kVertex).replace(quad_scheme(kVertex).find("1/k"), 3, "1/(k-4)"));
  const fs::path json = dir / "report.json";
  const CliResult r = run_subdiv("analyze " + scheme.string() + " --valence 3..5 --json " + json.string());
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(contains(r.output, "subdiv: error: scheme 'mine' could not be analysed at any valence: "), r.output);
  CHECK(contains(r.output, "check its rules with `subdiv validate " + scheme.string() + "`"));
  CHECK_FALSE(fs::exists(json));
  // A scheme that is merely not C1 is a verdict: exit 0.
  const fs::path stiff = write(
      dir, "stiff.json",
      quad_scheme(R"([{"at": "self", "w": "0.9"}, {"sum": "ring", "w": "0.05/n"}, {"sum": "faces", "new": "face", "w": "0.05/n"}])"));
  const CliResult verdict = run_subdiv("analyze " + stiff.string() + " --valence 3..5");
  CHECK_MESSAGE(verdict.exit_code == 0, verdict.output);
  CHECK(contains(verdict.output, "0 of 3 valences C1"));
}
