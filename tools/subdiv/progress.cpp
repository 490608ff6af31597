#include "progress.h"

#include <cstdio>
#include <fmt/format.h>
#include <unistd.h>

namespace subdiv::cli {

Progress::Progress() : terminal_(isatty(fileno(stderr))) {}
Progress::~Progress() { done(); }

void Progress::say(const std::string& message) {
  if (!terminal_) return;
  fmt::print(stderr, "\r\033[K{}", message);
  std::fflush(stderr);
  open_ = true;
}

void Progress::done() {
  if (terminal_ && open_) fmt::print(stderr, "\n");
  open_ = false;
}

}  // namespace subdiv::cli
