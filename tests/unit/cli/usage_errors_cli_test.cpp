// One voice on the command line: usage errors print `subdiv: error: ...` with a suggestion
// for a mistyped command or option and exit 2 (argparse's convention); refused input exits
// 1; help and --version exit 0; `subdiv --help` lists the codes.
#include <doctest/doctest.h>

#include <filesystem>
#include <vector>

#include "support/cli_runner.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Usage {
  std::string args, says;
};

}  // namespace

TEST_CASE("usage errors exit 2 in the tool's voice, with a suggestion where a word is mistyped") {
  const fs::path dir = fresh_dir("usage-errors");
  const std::string cube = source_path("examples/meshes/cube.obj");
  const std::string out = " -o " + (dir / "out.obj").string();
  const std::vector<Usage> cases{
      {"refin " + cube + out, "unknown command 'refin'; did you mean `refine`?"},
      {"scheems", "unknown command 'scheems'; did you mean `schemes`?"},
      {"", "no command given; the commands are: refine"},
      {"refine " + cube + " --levles 2" + out, "unknown option '--levles' for `subdiv refine`; did you mean `--levels`?"},
      {"refine " + cube + " --sheme loop" + out, "did you mean `--scheme`?"},
      {"validate loop --max-valence 1000000", "--max-valence: Value 1000000 not in range"},
      {"refine " + cube + out + " -l", "--levels needs a value"},
      {"refine " + cube + out + " -l 31", "--levels"},
      // CLI11 printed the largest double in full as the upper end of "0 or more".
      {"refine " + cube + out + " -j -1", "--threads: Value -1 is negative; give 0 or more\n"},
      {"analyze loop --level -2", "--level: Value -2 is negative; give 0 or more\n"},
      // A value that is no number was "negative" too; one the type cannot hold was CLI11's
      // "Could not convert: --threads = 1e3".
      {"refine " + cube + out + " -j abc", "--threads: 'abc' is not a number; give a whole number, 0 or more\n"},
      {"refine " + cube + out + " -j 1e3", "--threads: '1e3' is not a value of its type"},
  };
  for (const Usage& u : cases) {
    CAPTURE(u.args);
    const CliResult r = run_subdiv(u.args);
    CAPTURE(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.rfind("subdiv: error: ", 0) == 0);
    CHECK(contains(r.output, u.says));
    CHECK(contains(r.output, "--help` for the options"));
    CHECK_FALSE(contains(r.output, "The following argument"));  // CLI11's words stay inside
    CHECK_FALSE(contains(r.output, "A subcommand is required"));
  }
  CHECK(fs::is_empty(dir));
}

TEST_CASE("a word far from every command or option gets no suggestion") {
  const CliResult r = run_subdiv("frobnicate");
  CHECK(r.exit_code == 2);
  CHECK(contains(r.output, "unknown command 'frobnicate'. The commands are:"));
  CHECK_FALSE(contains(r.output, "did you mean"));
  const CliResult o = run_subdiv("schemes --xyzzy");
  CHECK(o.exit_code == 2);
  CHECK(contains(o.output, "unknown option '--xyzzy' for `subdiv schemes`"));
  CHECK_FALSE(contains(o.output, "did you mean"));
}

TEST_CASE("refused input exits 1; help and version exit 0 and list the exit codes") {
  const CliResult refused = run_subdiv("refine " + source_path("examples/meshes/does-not-exist.obj") + " -o " +
                                       (fresh_dir("usage-refused") / "x.obj").string());
  CHECK(refused.exit_code == 1);
  CHECK(refused.output.rfind("subdiv: error: ", 0) == 0);
  const CliResult help = run_subdiv("--help");
  CHECK(help.exit_code == 0);
  CHECK(contains(help.output, "Exit codes: 0 done; 1 input or a value refused"));
  CHECK(contains(help.output, "2 usage error"));
  CHECK(contains(help.output, "3 internal error"));
  CHECK(run_subdiv("refine --help").exit_code == 0);
  CHECK(run_subdiv("--version").exit_code == 0);
}
