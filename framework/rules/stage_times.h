#pragma once
// Where a refinement's time goes, stage by stage, for benchmarks that attribute it
// (tools/bench's subdiv-bench-stages): wall-clock and process CPU time added up per named
// stage. With two threads, a stage whose CPU time is close to its wall time ran on one
// core: the serial part of a step. Reached through EvaluationSwitches::stage_times
// (engine/refiner.h); null there, nothing is timed. Adding is thread-safe.
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace subdiv {

class StageTimes {
public:
  struct Entry {
    std::string name;
    double wall_ms = 0, cpu_ms = 0;  // summed over every time the stage ran
    int count = 0;
  };
  void add(std::string_view name, double wall_ms, double cpu_ms);
  // In the order the stages first ran.
  std::vector<Entry> entries() const;
  void clear();

private:
  mutable std::mutex mutex_;
  std::vector<Entry> entries_;
};

// Times its scope into `times` as `name` (nothing when `times` is null).
class StageTimer {
public:
  StageTimer(StageTimes* times, std::string name);
  ~StageTimer();
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

private:
  StageTimes* times_;
  std::string name_;
  double wall0_ = 0, cpu0_ = 0;
};

}  // namespace subdiv
