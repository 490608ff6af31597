// Scheme files a hostile or unlucky user gives the loader: JSON nested 10^5 deep,
// numbers beyond double's range, definitions that refer to themselves or each other,
// 200 KB formulas, and `subdiv validate` with valence ranges that are negative, huge or
// reversed. Each ends in a subdiv::Error naming the file and the place, quickly.
#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>

#include "framework/scheme/scheme_registry.h"
#include "framework/scheme/scheme_validator.h"
#include "framework/util/error.h"
#include "support/cli_runner.h"
#include "support/scheme_files.h"

using namespace subdiv;
using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

fs::path write_scheme(const std::string& name, const std::string& text) {
  return test::write_scheme_file("subdivkit-hostile-schemes", name, text);
}

std::string load_error(const fs::path& file) {
  try {
    load_scheme(file.string());
  } catch (const Error& e) {
    return e.what();
  }
  return "<no error>";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Loop's rules with the given definitions object.
std::string loop_with_definitions(const std::string& definitions) {
  return R"({"name": "t", "split": "triangle", "curve": "cubic-bspline", "faces": "triangles",
  "definitions": )" + definitions + R"(,
  "rules": {"edge": [{"sum": "ends", "w": "3/8"}, {"sum": "opposite", "w": "1/8"}],
            "vertex": [{"at": "self", "w": "1 - n*beta"}, {"sum": "ring", "w": "beta"}]}})";
}

}  // namespace

TEST_CASE("a scheme nested 10^5 deep is refused at its place, without a stack overflow") {
  const fs::path file = write_scheme("deep", "{\"name\": " + std::string(100000, '[') + std::string(100000, ']') + "}");
  const std::string m = load_error(file);
  CHECK(contains(m, file.string() + ":1:109: JSON nested deeper than 100 levels"));
  const CliResult r = run_subdiv("validate " + file.string());
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "nested deeper than 100 levels"));
}

TEST_CASE("numbers beyond double's range name the file, line and column") {
  const fs::path file = write_scheme("huge-number", R"({"name": "t", "split": "quad",
  "parameters": {"w": {"default": 1e400}}, "rules": {}})");
  CHECK(contains(load_error(file), file.string() + ":2:35: the number 1e400 is out of range"));
  const fs::path negative = write_scheme("huge-negative", R"({"name": "t", "split": -2e999})");
  CHECK(contains(load_error(negative), negative.string() + ":1:24: the number -2e999 is out of range"));
}

TEST_CASE("a key given twice in one object, and a NUL byte, are refused at their place") {
  // nlohmann keeps the last of two equal keys: "split": "quad" then "split": "triangle" was
  // read as a triangle scheme, and the message spoke of the rules; after a NUL byte the rest
  // of the file was ignored.
  const std::string rules = R"("rules": {"face": [{"sum": "vertices", "w": "1/k"}], "edge": [{"sum": "ends", "w": "1/2"}],
  "vertex": [{"at": "self", "w": "1"}]})";
  const fs::path twice = write_scheme("twice", R"({"name": "t", "split": "quad", "curve": "two-point",
  "split": "triangle", )" + rules + "}");
  CHECK(contains(load_error(twice), twice.string() + ":2:3: the key \"split\" appears twice in one object (first at "
                                                      "line 1, column 15); a JSON reader keeps only one of them"));
  // The same key in different objects is no duplicate.
  CHECK(load_error(write_scheme("nested", R"({"name": "t", "split": "quad", "curve": "two-point",
  "parameters": {"a": {"default": 1}, "b": {"default": 2}}, )" + rules + "}")) == "<no error>");
  const fs::path nul = write_scheme("nul", R"({"name": "t", "split": "quad", "curve": "two-point", )" + rules + "}" +
                                               std::string(1, '\0') + "garbage");
  const std::string at_nul = load_error(nul);
  CHECK(contains(at_nul, nul.string() + ":2:"));
  CHECK(contains(at_nul, ": a NUL byte; JSON text holds none"));
  const CliResult r = run_subdiv("validate " + twice.string());
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "appears twice"));
}

TEST_CASE("definitions that refer to themselves or to each other are reported as a cycle") {
  CHECK(load_error(write_scheme("fine", loop_with_definitions(R"({"c": "3/8", "beta": "c / n"})"))) == "<no error>");
  const fs::path self = write_scheme("self", loop_with_definitions(R"({"beta": "beta + 1"})"));
  const std::string m = load_error(self);
  CHECK(contains(m, "definitions.beta: definition 'beta' refers to itself (a cycle: beta -> beta)"));
  CHECK_FALSE(contains(m, "Unexpected token"));

  const fs::path pair = write_scheme("pair", loop_with_definitions(R"({"a": "b / 2", "b": "a * 2", "beta": "a"})"));
  CHECK(contains(load_error(pair), "definitions refer to each other in a cycle: a -> b -> a"));

  const fs::path later = write_scheme("later", loop_with_definitions(R"({"beta": "c / n", "c": "3/8"})"));
  CHECK(contains(load_error(later), "definition 'beta' uses 'c', which is defined after it; move 'c' before 'beta'"));
}

TEST_CASE("a 200 KB formula is quoted shortened in the message") {
  std::string formula = "1";
  while (formula.size() < 200000) formula += " + 1";
  formula += " +";  // does not parse
  const fs::path file = write_scheme("long-formula", loop_with_definitions("{\"beta\": \"" + formula + "\"}"));
  const std::string m = load_error(file);
  CHECK(contains(m, "does not parse"));
  CHECK(contains(m, "... (200003 characters)"));
  CHECK(m.size() < 1000);
}

TEST_CASE("subdiv validate: valence ranges are checked before any work") {
  CHECK(run_subdiv("validate loop --min-valence 3 --max-valence 12").exit_code == 0);
  const auto t0 = std::chrono::steady_clock::now();
  for (const std::string args : {"--min-valence -5", "--max-valence 100000", "--min-valence 2147483647",
                                 "--max-valence -2147483648", "--min-valence 0"}) {
    const CliResult r = run_subdiv("validate loop " + args);
    INFO(args, r.output);
    CHECK(r.exit_code != 0);
    CHECK_FALSE(contains(r.output, "internal error"));
    CHECK(contains(r.output, "valence"));
  }
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(20));  // no quadratic hang
  const CliResult reversed = run_subdiv("validate loop --min-valence 9 --max-valence 4");
  CHECK(reversed.exit_code == 1);
  CHECK(contains(reversed.output, "--min-valence 9 is larger than --max-valence 4"));
  CHECK_THROWS_AS(validate_scheme_file("loop", 9, 4), Error);
  CHECK_THROWS_AS(validate_scheme_file("loop", -1, 4), Error);
  CHECK_THROWS_AS(validate_scheme_file("loop", 3, 1000000), Error);
}

TEST_CASE("a first-day author's mistakes: a name never declared, a formula undefined at one valence") {
  // A parameter used but not declared: refused when the file loads, at the formula's line, with the fix.
  const fs::path undeclared = write_scheme("undeclared", loop_with_definitions(R"x({"beta": "3/(8*n) + tau"})x"));
  const std::string m = load_error(undeclared);
  CHECK(contains(m, undeclared.string() + ":2: definitions.beta: formula '3/(8*n) + tau' uses 'tau', which is not "
                    "defined: declare it under \"parameters\" (with a default) or \"definitions\""));
  CHECK_FALSE(contains(m, "Unexpected token"));
  const CliResult r = run_subdiv("validate " + undeclared.string());
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "uses 'tau', which is not defined"));

  // 1/(n-6) - 1/(n-6) is 0 everywhere but at n = 6, where it is NaN: validate names the
  // valence and the cause, not a weight sum of "-nan".
  const fs::path pole = write_scheme("pole", loop_with_definitions(R"x({"beta": "3/(8*n) + 1/(n-6) - 1/(n-6)"})x"));
  const CliResult v = run_subdiv("validate " + pole.string());
  CHECK(v.exit_code == 1);
  CHECK_MESSAGE(contains(v.output, pole.string() + ":4: rules.vertex (smooth): the weights at n=6 are not finite "
                                   "numbers (they sum to NaN): a formula divides by zero or leaves its domain there"),
                v.output);
  CHECK_FALSE(contains(v.output, "nan,"));
}

TEST_CASE("a level of 2^31 for a scheme with state is refused at once, not followed level by level") {
  // tension-bspline's alpha_k is a recurrence from l = 0; following it to 2^31 took minutes
  // and gigabytes (it was stopped after 100 s); `timeout` turns a return of that into a failure.
  const CliResult r = run_subdiv_with_prefix("timeout 60 ", "analyze tension-bspline --level 2147483647");
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(contains(r.output, "tension-bspline.json: state.alpha.initial: state variable 'alpha' is followed level "
                                   "by level from l = 0, and level 2147483647 is beyond the 1000000 levels"),
                r.output);
  CHECK(contains(r.output, "ask for a level up to 1000000"));
  // The largest level followed still works.
  CHECK(run_subdiv("analyze tension-bspline --level 1000000").exit_code == 0);
}
