// A hostile file name cannot drive the terminal through subdiv's messages (issue 33): its
// ESC sequences, bell and invalid UTF-8 are printed escaped (framework/util/quoted_text.h).
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "support/cli_runner.h"

using namespace subdiv::test;

namespace {
bool has_raw_escape(const std::string& s) {
  for (char c : s)
    if (c == '\x1b' || c == '\x07' || static_cast<unsigned char>(c) == 0x9b) return true;
  return false;
}
}  // namespace

TEST_CASE("subdiv refine: a file name holding terminal escapes is shown escaped in the error") {
  const auto dir = fresh_dir("hostile-names");
  const std::string name = "mesh\x1b]0;pwned\x07\x1b[2J\x9b" "31m.obj";
  std::ofstream(dir / name) << "v 0 0 0\nv 1 0 0\nf 1 2 9\n";  // face past the vertices: refused
  const CliResult r = run_subdiv("refine '" + (dir / name).string() + "' -o '" + (dir / "out.obj").string() + "'");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_FALSE(has_raw_escape(r.output));
  CHECK(r.output.find("mesh\\x1b]0;pwned\\x07\\x1b[2J\\x9b31m.obj") != std::string::npos);
  const CliResult missing = run_subdiv("refine '" + (dir / "no\x1b[1Ahere.obj").string() + "' -o '" +
                                       (dir / "out.obj").string() + "'");
  INFO(missing.output);
  CHECK(missing.exit_code == 1);
  CHECK_FALSE(has_raw_escape(missing.output));
  CHECK(missing.output.find("no\\x1b[1Ahere.obj") != std::string::npos);
}

// The reports a successful run prints name the input and output files too: every command's
// stdout and stderr go through the same escaping (tools/subdiv/safe_print.h).
TEST_CASE("subdiv: a hostile file name is shown escaped in the reports of successful runs") {
  const auto dir = fresh_dir("hostile-names-reports");
  const std::string stem = "m\x1b[31mX";
  const auto mesh = (dir / (stem + ".obj")).string();
  std::ofstream(mesh) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                         "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  const std::string out = (dir / (stem + ".out")).string();
  for (const std::string& command :
       {"refine '" + mesh + "' -o '" + out + ".obj' -l 1", "refine '" + mesh + "' -o '" + out + ".obj' -l 1 --timings",
        "refine '" + mesh + "' -o '" + out + ".obj' --adaptive 2",
        "interpolate '" + mesh + "' -o '" + out + ".i.obj'",
        "evaluate '" + mesh + "' --samples 2 -o '" + out + ".s.obj'"}) {
    const CliResult r = run_subdiv(command);
    INFO(command, "\n", r.output);
    CHECK(r.exit_code == 0);
    CHECK_FALSE(has_raw_escape(r.output));
    CHECK(r.output.find("m\\x1b[31mX") != std::string::npos);  // each says what it read and wrote
  }
}
