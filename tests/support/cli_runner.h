#pragma once
// Runs the built `subdiv` tool for end-to-end tests and captures its exit code and output.
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>

namespace subdiv::test {

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline std::string subdiv_tool() { return std::string(SUBDIV_BINARY_DIR) + "/tools/subdiv/subdiv"; }
inline std::string source_path(const std::string& relative) { return std::string(SUBDIV_SOURCE_DIR) + "/" + relative; }

// `prefix` goes before the tool in the shell command: "timeout 60 ", "ulimit -v 400000; ".
inline CliResult run_subdiv_with_prefix(const std::string& prefix, const std::string& args) {
  CliResult r;
  const std::string command = prefix + subdiv_tool() + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer;
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) r.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline CliResult run_subdiv(const std::string& args) { return run_subdiv_with_prefix("", args); }

inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("subdivkit-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace subdiv::test
