#pragma once
// How many new points of a step each path of the step evaluator computed
// (rules/step_evaluator.h): the compiled smooth kernels, learnt row plans, or the generic
// rule interpreter; `flat` counts the kernel points the flat kernels (flat_kernels.h) took.
// For benchmarks and tests; adding is thread-safe.
#include <atomic>
#include <cstdint>

namespace subdiv {

struct RowPaths {
  std::atomic<std::int64_t> kernel{0}, plan{0}, generic{0}, flat{0};
  struct Counts {
    std::int64_t kernel = 0, plan = 0, generic = 0, flat = 0;
  };
  void add(const Counts& c) { kernel += c.kernel, plan += c.plan, generic += c.generic, flat += c.flat; }
};

}  // namespace subdiv
