#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "framework/scheme/scheme_validator.h"
#include "support/cli_runner.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const auto dir = fs::temp_directory_path() / "subdivkit-validate";
  fs::create_directories(dir);
  const auto file = dir / (name + ".json");
  std::ofstream(file) << text;
  return file.string();
}

std::string quad_with_vertex(const std::string& vertex) {
  return "{\"name\": \"v\", \"split\": \"quad\", \"curve\": \"cubic-bspline\", \"rules\": {\n"
         "  \"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}],\n"
         "  \"edge\": [{\"sum\": \"ends\", \"w\": \"1/4\"}, {\"sum\": \"faces\", \"new\": \"face\", \"w\": \"1/4\"}],\n"
         "  \"vertex\": " + vertex + "\n}}\n";
}

}  // namespace

TEST_CASE("validate accepts every shipped scheme") {
  for (const auto& entry : fs::directory_iterator(test::source_path("schemes"))) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "scheme.schema.json") continue;
    const auto r = validate_scheme_file(entry.path().string());
    CHECK_MESSAGE(r.ok(), entry.path().string(), ": ", r.errors.empty() ? "" : r.errors[0].message);
    CHECK(r.checks > 0);
  }
}

TEST_CASE("validate notes a scheme without boundary or crease rules, and only that one") {
  // Valid rules, no "curve" and no crease rule: refine refuses boundaries, creases and UV
  // seams, so a scheme author hears it from validate (exit 0: nothing is wrong).
  std::string no_curve = quad_with_vertex(
      "[{\"at\": \"self\", \"w\": \"(n-2)/n\"}, {\"sum\": \"ring\", \"w\": \"1/n^2\"}, "
      "{\"sum\": \"faces\", \"new\": \"face\", \"w\": \"1/n^2\"}]");
  const std::string with_curve = no_curve;
  no_curve.erase(no_curve.find("\"curve\": \"cubic-bspline\", "), std::string("\"curve\": \"cubic-bspline\", ").size());
  const auto without = validate_scheme_file(write("no-curve", no_curve));
  CHECK(without.ok());
  REQUIRE(without.notes.size() == 1);
  CHECK(without.notes[0].find("no boundary or crease rules") != std::string::npos);
  CHECK(validate_scheme_file(write("with-curve", with_curve)).notes.empty());
  for (const char* shipped : {"catmull-clark", "loop", "doo-sabin", "sqrt3", "mid-edge", "loop-composite"})
    CHECK_MESSAGE(validate_scheme_file(shipped).notes.empty(), shipped);
  const test::CliResult cli = test::run_subdiv("validate " + write("no-curve", no_curve));
  CHECK(cli.exit_code == 0);
  CHECK(cli.output.find("  note: no boundary or crease rules") != std::string::npos);
}

TEST_CASE("validate: a rule that is affine only at n = 4 is caught at n = 3 with its line") {
  // Catmull-Clark's vertex rule with the self weight of the regular case only.
  const auto f = write("affine", quad_with_vertex(
      "[{\"at\": \"self\", \"w\": \"1/2\"}, {\"sum\": \"ring\", \"w\": \"1/16\"}, {\"sum\": \"faces\", \"new\": \"face\", \"w\": \"1/16\"}]"));
  const auto r = validate_scheme_file(f);
  REQUIRE(r.errors.size() == 1);
  CHECK(r.errors[0].message.find("affine.json:4: rules.vertex (smooth): weights sum to 0.875 at n=3") != std::string::npos);
}

TEST_CASE("validate: an asymmetric ring weight is caught") {
  const auto f = write("asym", quad_with_vertex(
      "[{\"at\": \"self\", \"w\": \"1/2\"}, {\"sum\": \"ring\", \"w\": \"j == 1 ? 1/(2*n) + 0.01 : (j == 2 ? 1/(2*n) - 0.01 : 1/(2*n))\"}]"));
  const auto r = validate_scheme_file(f);
  REQUIRE_FALSE(r.ok());
  CHECK(r.errors[0].message.find("not symmetric") != std::string::npos);
}

TEST_CASE("validate: structural errors come from the loader with their place") {
  const auto f = write("role", quad_with_vertex("[{\"sum\": \"neighbors\", \"w\": \"1\"}]"));
  const auto r = validate_scheme_file(f);
  REQUIRE_FALSE(r.ok());
  CHECK(r.errors[0].message.find("rules.vertex[0]: unknown role 'neighbors'") != std::string::npos);
  const auto c = write("curve", "{\"name\": \"c\", \"kind\": \"curve\", \"arity\": 2, \"rules\": "
                                 "[{\"start\": 0, \"w\": [\"1\"]}, {\"start\": 0, \"w\": [\"1/2\", \"1/4\"]}]}");
  const auto rc = validate_scheme_file(c);
  REQUIRE_FALSE(rc.ok());
  CHECK(rc.errors[0].message.find("rules[1]: weights sum to 0.75") != std::string::npos);
}

TEST_CASE("subdiv validate: exit code 0 on good files, non-zero with messages on bad ones") {
  CHECK(test::run_subdiv("validate " + test::source_path("schemes/loop.json")).exit_code == 0);
  const auto f = write("cli-bad", quad_with_vertex("[{\"at\": \"self\", \"w\": \"2\"}]"));
  const auto r = test::run_subdiv("validate " + f);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("weights sum to 2") != std::string::npos);
}

TEST_CASE("validate: a triangle-only role in a quad scheme is refused with its place") {
  // Loop's edge rule (3/8 ends, 1/8 opposite) on the quad split: every level after the first
  // is made of quads, where 'opposite' does not exist.
  const auto g = write("wrong-role",
                       "{\"name\": \"v\", \"split\": \"quad\", \"curve\": \"cubic-bspline\", \"rules\": {\n"
                       "  \"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}],\n"
                       "  \"edge\": [{\"sum\": \"ends\", \"w\": \"3/8\"}, {\"sum\": \"opposite\", \"w\": \"1/8\"}],\n"
                       "  \"vertex\": [{\"at\": \"self\", \"w\": \"1\"}]\n}}\n");
  const auto r = validate_scheme_file(g);
  REQUIRE_FALSE(r.ok());
  CHECK(r.errors[0].message.find("wrong-role.json:3: rules.edge[1] (smooth): role 'opposite' needs triangles, but "
                                 "the quad split makes quads") != std::string::npos);
}

TEST_CASE("validate: 'diagonals' needs a base mesh of quads under the quad split") {
  const auto g = write("diagonals",
                       "{\"name\": \"v\", \"split\": \"quad\", \"curve\": \"cubic-bspline\", \"rules\": {\n"
                       "  \"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}],\n"
                       "  \"edge\": [{\"sum\": \"ends\", \"w\": \"1/2\"}],\n"
                       "  \"vertex\": [{\"at\": \"self\", \"w\": \"1/2\"}, {\"sum\": \"diagonals\", \"w\": \"1/(2*n)\"}]\n}}\n");
  const auto r = validate_scheme_file(g);
  REQUIRE_FALSE(r.ok());
  CHECK(r.errors[0].message.find("role 'diagonals' needs quads, but the base mesh may have any polygons") !=
        std::string::npos);
  // With "faces": "quads" every level the rule sees is made of quads.
  std::string text = "{\"name\": \"v\", \"split\": \"quad\", \"faces\": \"quads\", \"curve\": \"cubic-bspline\", \"rules\": {\n"
                     "  \"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}],\n"
                     "  \"edge\": [{\"sum\": \"ends\", \"w\": \"1/2\"}],\n"
                     "  \"vertex\": [{\"at\": \"self\", \"w\": \"1/2\"}, {\"sum\": \"diagonals\", \"w\": \"1/(2*n)\"}]\n}}\n";
  CHECK(validate_scheme_file(write("diagonals-quads", text)).ok());
}

TEST_CASE("validate: rules are checked over each parameter's declared range, not only at the default") {
  // Affine at the default t = 0.5 and everywhere inside [0, 1], but at the edge t = 1 the
  // self weight t/(1 - t) is infinite: refused, naming the value.
  const auto f = write("edge-of-range",
                       "{\"name\": \"v\", \"split\": \"quad\", \"curve\": \"cubic-bspline\",\n"
                       "  \"parameters\": {\"t\": {\"default\": 0.5, \"min\": 0, \"max\": 1}},\n"
                       "  \"rules\": {\n"
                       "  \"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}],\n"
                       "  \"edge\": [{\"sum\": \"ends\", \"w\": \"1/2\"}],\n"
                       "  \"vertex\": [{\"at\": \"self\", \"w\": \"t/(1 - t) - t/(1 - t) + 1\"}]\n}}\n");
  const auto r = validate_scheme_file(f);
  REQUIRE_FALSE(r.ok());
  CHECK(r.errors[0].message.find("edge-of-range.json:6: rules.vertex (smooth): the weights at n=3 with t=1 are not "
                                 "finite numbers") != std::string::npos);
  CHECK(r.errors[0].message.find("or leave the parameter's value out of its range") != std::string::npos);
  // The same scheme with the edge left out of the range passes.
  std::string text = "{\"name\": \"v\", \"split\": \"quad\", \"curve\": \"cubic-bspline\",\n"
                     "  \"parameters\": {\"t\": {\"default\": 0.5, \"min\": 0, \"max\": 1, \"max_exclusive\": true}},\n"
                     "  \"rules\": {\n"
                     "  \"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}],\n"
                     "  \"edge\": [{\"sum\": \"ends\", \"w\": \"1/2\"}],\n"
                     "  \"vertex\": [{\"at\": \"self\", \"w\": \"t/(1 - t) - t/(1 - t) + 1\"}]\n}}\n";
  const auto ok = validate_scheme_file(write("inside-range", text));
  CHECK_MESSAGE(ok.ok(), (ok.errors.empty() ? std::string() : ok.errors[0].message));
}

TEST_CASE("validate: an edge rule over its ends' sectors is checked with either end, or both, on a boundary") {
  auto scheme = [](const std::string& sector1) {
    return "{\"name\": \"s\", \"split\": \"triangle\", \"faces\": \"triangles\", \"curve\": \"four-point\", \"rules\": {\n"
           "  \"edge\": [{\"sum\": \"ends\", \"w\": \"b0 + b1 > 0 ? 0 : 1/2\"},\n"
           "            {\"sum\": \"end-sector-0\", \"w\": \"b0 ? (b1 ? 1/2 : 1) / (m0 + 1) : 0\"}" + sector1 + "],\n"
           "  \"vertex\": [{\"at\": \"self\", \"w\": \"1\"}]\n}}\n";
  };
  // Only end 0's sector: affine while end 0 is the boundary end, not when end 1 is.
  const auto one = validate_scheme_file(write("one-sector", scheme("")));
  REQUIRE(one.errors.size() == 1);
  CHECK(one.errors[0].message.find("weights sum to 0 at end 0 interior valence 3, end 1 boundary valence 3 (sector of "
                                   "2 faces, edge 1)") != std::string::npos);
  const auto both = validate_scheme_file(write(
      "both-sectors", scheme(",\n            {\"sum\": \"end-sector-1\", \"w\": \"b1 ? (b0 ? 1/2 : 1) / (m1 + 1) : 0\"}")));
  CHECK(both.ok());
}
