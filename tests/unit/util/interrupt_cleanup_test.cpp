// An interrupt (Ctrl-C, SIGTERM, SIGHUP) while a file is being written removes the hidden
// temporary and ends the process as the signal does; the target is not created.
#include <doctest/doctest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "framework/util/atomic_file.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

size_t entries(const fs::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST_CASE("a signal during a write removes the temporary and ends the process by that signal") {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    CAPTURE(sig);
    const fs::path dir = fs::temp_directory_path() / ("subdivkit-interrupt-" + std::to_string(sig));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {  // the writer: interrupted half-way through its file
      ::signal(sig, SIG_DFL);  // doctest watches some signals itself
      write_file_atomically(dir / "out.vtp", [&](const fs::path& tmp) {
        std::ofstream(tmp) << "half a file";
        ::raise(sig);
      });
      ::_exit(0);  // not reached: the signal ends the process
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK(entries(dir) == 0);  // no temporary, no out.vtp
  }
}

TEST_CASE("a signal with a handler of its own (Python's KeyboardInterrupt) is left to it") {
  const fs::path dir = fs::temp_directory_path() / "subdivkit-interrupt-handled";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    static volatile std::sig_atomic_t heard = 0;
    ::signal(SIGINT, [](int) { heard = 1; });
    write_file_atomically(dir / "out.vtp", [&](const fs::path& tmp) {
      std::ofstream(tmp) << "whole";
      ::raise(SIGINT);
    });
    ::_exit(heard == 1 ? 7 : 1);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 7);
  CHECK(fs::exists(dir / "out.vtp"));
  CHECK(entries(dir) == 1);
}
