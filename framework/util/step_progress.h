#pragma once
// Progress within one step's values, for a front-end's bar that should move during a long
// level and not only between levels: the engine's step_values tells the share of the step's
// passes done (the split's rows, then each smoothing pass), and each pass the share of its
// rows done after each group of them (face, edge, vertex points: rules/step_evaluator.cpp),
// to the report of the innermost StepProgressScope open on the calling thread. Without a
// scope nothing is told, and the cost is one thread-local pointer test per group (the same
// pattern as io/io_progress.h's reading scope).
#include <cstddef>
#include <functional>

namespace subdiv {

class StepProgressScope {
public:
  using Report = std::function<void(double done)>;

  // Reports to `report` until the scope ends (nothing when it is empty).
  // The scope keeps a pointer to `report`, which must outlive it (hence no temporaries).
  explicit StepProgressScope(const Report& report) : previous_(current()) { current() = report ? &report : nullptr; }
  explicit StepProgressScope(Report&&) = delete;
  ~StepProgressScope() { current() = previous_; }
  StepProgressScope(const StepProgressScope&) = delete;
  StepProgressScope& operator=(const StepProgressScope&) = delete;

  // The work in progress on this thread has done the share `done` (0 to 1).
  static void tell(double done) {
    if (const Report* report = current()) (*report)(done);
  }

  // A report for part `index` of `count` equal parts of the work in progress: a scope
  // opened with it maps the part's own shares into the whole (empty without a scope).
  static Report part(size_t index, size_t count) {
    return span(double(index) / double(count), double(index + 1) / double(count));
  }

  // A report for the share [begin, end] of the work in progress, for parts of unequal size.
  static Report span(double begin, double end) {
    const Report* whole = current();
    if (!whole) return {};
    return [whole, begin, end](double done) { (*whole)(begin + done * (end - begin)); };
  }

private:
  static const Report*& current() {
    thread_local const Report* report = nullptr;
    return report;
  }
  const Report* previous_;
};

}  // namespace subdiv
