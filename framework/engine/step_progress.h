#pragma once
// Progress within one step's values, for a front-end's bar that should move during a long
// level and not only between levels (issue 31): step_values tells the share of the step's
// passes done (the split's rows, then each smoothing pass) to the report of the innermost
// StepProgressScope open on the calling thread. Without a scope nothing is told, and the
// cost is one thread-local pointer test per pass (the same pattern as io/io_progress.h's
// reading scope).
#include <functional>

namespace subdiv {

class StepProgressScope {
public:
  using Report = std::function<void(double done)>;

  // Reports to `report` until the scope ends (nothing when it is empty).
  explicit StepProgressScope(const Report& report) : previous_(current()) { current() = report ? &report : nullptr; }
  ~StepProgressScope() { current() = previous_; }
  StepProgressScope(const StepProgressScope&) = delete;
  StepProgressScope& operator=(const StepProgressScope&) = delete;

  // The step in progress on this thread has done the share `done` (0 to 1) of its passes.
  static void tell(double done) {
    if (const Report* report = current()) (*report)(done);
  }

private:
  static const Report*& current() {
    thread_local const Report* report = nullptr;
    return report;
  }
  const Report* previous_;
};

}  // namespace subdiv
