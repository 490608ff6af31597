#pragma once
// Assertions shared by the end-to-end CLI tests.
#include <doctest/doctest.h>
#include <filesystem>
#include <string>

#include "support/cli_runner.h"

namespace subdiv::test {

// A refused run: non-zero exit, a message naming the problem, and no output written.
inline void check_refused(const std::string& args, const std::filesystem::path& out, const std::string& message) {
  const CliResult r = run_subdiv(args + " -o " + out.string());
  CHECK(r.exit_code != 0);
  CHECK_MESSAGE(r.output.find(message) != std::string::npos, r.output);
  CHECK_FALSE(std::filesystem::exists(out));
}

}  // namespace subdiv::test
