#pragma once
// Progress on a terminal (stderr): the phase running, and for long work (the levels'
// values, writing files) a bar with the share done and an estimate of the time left,
// redrawn a few times a second. Nothing when stderr is not a terminal or with -q; with
// `timings`, every step's wall time as a line of its own instead (refine --timings).
#include <chrono>
#include <functional>
#include <string>

namespace subdiv::cli {

// Wall seconds since t0, for the commands' summary lines ("... in 0.099 s -> OUT").
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

class Progress {
public:
  explicit Progress(bool timings = false, bool quiet = false);
  ~Progress();
  void say(const std::string& message);  // replaces the current line; a step starts
  // The share of the long work in progress done, 0 to 1 (the pipeline's progress_fraction,
  // a writer's progress); 0 starts a new bar and its clock, 1 ends it.
  void fraction(double done);
  void done();  // ends the line and the last step

  // say and fraction as a request's callbacks (framework/pipeline: progress, progress_fraction).
  std::function<void(const std::string&)> phase_callback() {
    return [this](const std::string& phase) { say(phase); };
  }
  std::function<void(double)> fraction_callback() {
    return [this](double done) { fraction(done); };
  }

  // The bar and estimate drawn after a phase: "[######              ]  30%  about 12 s left".
  static std::string bar(double done, double elapsed_seconds);

private:
  void time_step();
  void draw();
  bool terminal_;
  bool timings_;
  bool open_ = false;
  std::string step_;  // the step running, for timings and the line
  std::chrono::steady_clock::time_point started_;
  double done_ = -1;  // the bar's share; -1: no bar
  std::chrono::steady_clock::time_point bar_started_, drawn_;
};

}  // namespace subdiv::cli
