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
