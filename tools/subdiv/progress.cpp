#include "progress.h"
#include "safe_print.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
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

// A few redraws a second: enough to see it move, too few to cost anything. Tests set
// SUBDIV_PROGRESS_EVERY_STEP to see every step, however fast the work.
const auto kRedraw = std::chrono::milliseconds(std::getenv("SUBDIV_PROGRESS_EVERY_STEP") ? 0 : 200);

Progress::Progress(bool timings, bool quiet)
    : terminal_(isatty(fileno(stderr)) && !timings && !quiet), timings_(timings) {}
Progress::~Progress() { done(); }

void Progress::time_step() {
  const auto now = std::chrono::steady_clock::now();
  if (timings_ && !step_.empty())
    print_safe(stderr, "subdiv: {:8.3f} s  peak {:6.2f} GB  {}\n",
               std::chrono::duration<double>(now - started_).count(), peak_resident_bytes() / 1e9, step_);
  step_.clear();
  started_ = now;
}

std::string Progress::bar(double done, double elapsed) {
  constexpr int kWidth = 20;
  done = std::clamp(done, 0.0, 1.0);
  const int filled = int(done * kWidth + 0.5);
  std::string line = "[" + std::string(size_t(filled), '#') + std::string(size_t(kWidth - filled), ' ') +
                     fmt::format("] {:3.0f}%", 100 * done);
  // An estimate once there is something to go by: the rate so far, for the rest.
  if (done >= 0.02 && done < 1 && elapsed >= 0.5) {
    const double left = elapsed * (1 - done) / done;
    line += left < 60 ? fmt::format("  about {:.0f} s left", std::max(1.0, left))
                      : fmt::format("  about {} min {:02d} s left", int(left / 60), int(left) % 60);
  }
  return line;
}

void Progress::draw() {
  if (!terminal_) return;
  std::string line = step_;
  if (done_ >= 0)
    line += "  " + bar(done_, std::chrono::duration<double>(std::chrono::steady_clock::now() - bar_started_).count());
  fmt::print(stderr, "\r\033[K{}", terminal_safe(line));
  std::fflush(stderr);
  drawn_ = std::chrono::steady_clock::now();
  open_ = true;
}

void Progress::say(const std::string& message) {
  time_step();
  step_ = message;
  draw();
}

void Progress::fraction(double done) {
  const auto now = std::chrono::steady_clock::now();
  const bool starts = done_ < 0;
  if (starts) bar_started_ = now;
  const bool redraw = starts || done >= 1 || now - drawn_ >= kRedraw;
  done_ = done >= 1 ? -1 : std::max(done, std::max(done_, 0.0));  // never backwards
  if (redraw) draw();
}

void Progress::done() {
  time_step();
  done_ = -1;
  if (terminal_ && open_) print_safe(stderr, "\n");
  open_ = false;
}

}  // namespace subdiv::cli
