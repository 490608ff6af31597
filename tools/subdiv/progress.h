#pragma once
// One-line progress on a terminal (stderr), silent when stderr is not a terminal; with
// `timings`, every step's wall time as a line of its own instead (refine --timings).
#include <chrono>
#include <string>

namespace subdiv::cli {

class Progress {
public:
  explicit Progress(bool timings = false);
  ~Progress();
  void say(const std::string& message);  // replaces the current line; a step starts
  void done();                            // ends the line and the last step

private:
  void time_step();
  bool terminal_;
  bool timings_;
  bool open_ = false;
  std::string step_;  // the step running, for timings
  std::chrono::steady_clock::time_point started_;
};

}  // namespace subdiv::cli
