#pragma once
// Usage errors in the tool's own voice: `subdiv: error: ...` with a suggestion for a
// mistyped command or option, and one set of exit codes for every command.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace subdiv::cli {

// Exit codes (the convention of argparse and most Unix tools; listed in `subdiv --help`).
constexpr int kExitRefused = 1;   // the input or a value was refused (the message says why)
constexpr int kExitUsage = 2;     // the command line itself is wrong (unknown option, missing value)
constexpr int kExitInternal = 3;  // a bug: please report it

// The footer of `subdiv --help` that lists them.
std::string exit_code_help();

// Prints a CLI11 parse error as `subdiv: error: ...` (help and --version print as usual)
// and returns the exit code.
int report_parse_error(const CLI::App& app, const CLI::ParseError& e, int argc, char** argv);

// The candidate closest to `word` if it is close enough to be a typo ("refin" -> "refine",
// "--levles" -> "--levels"), else "".
std::string closest_spelling(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace subdiv::cli
