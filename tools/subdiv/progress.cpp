#include "progress.h"

#include <cstdio>
#include <fmt/format.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace {

// The process's peak resident set so far (VmHWM in /proc/self/status), in bytes; 0 where unknown.
double peak_resident_bytes() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024;  // "VmHWM:  123 kB"
  return 0;
}

}  // namespace

namespace subdiv::cli {

Progress::Progress(bool timings) : terminal_(isatty(fileno(stderr)) && !timings), timings_(timings) {}
Progress::~Progress() { done(); }

void Progress::time_step() {
  const auto now = std::chrono::steady_clock::now();
  if (timings_ && !step_.empty())
    fmt::print(stderr, "subdiv: {:8.3f} s  peak {:6.2f} GB  {}\n",
               std::chrono::duration<double>(now - started_).count(), peak_resident_bytes() / 1e9, step_);
  step_.clear();
  started_ = now;
}

void Progress::say(const std::string& message) {
  time_step();
  step_ = message;
  if (!terminal_) return;
  fmt::print(stderr, "\r\033[K{}", message);
  std::fflush(stderr);
  open_ = true;
}

void Progress::done() {
  time_step();
  if (terminal_ && open_) fmt::print(stderr, "\n");
  open_ = false;
}

}  // namespace subdiv::cli
