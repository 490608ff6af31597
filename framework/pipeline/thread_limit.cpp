#include "framework/pipeline/thread_limit.h"

#include <algorithm>
#include <sched.h>
#include <tbb/global_control.h>
#include <thread>

namespace subdiv {

struct ThreadLimit::Control {
  tbb::global_control control;
};

int available_cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, int(std::thread::hardware_concurrency()));
}

ThreadLimit::ThreadLimit(int threads) {
  if (threads <= 0) return;
  threads_ = std::min(threads, available_cores());
  control_.reset(new Control{tbb::global_control(tbb::global_control::max_allowed_parallelism, size_t(threads_))});
}

ThreadLimit::~ThreadLimit() = default;

}  // namespace subdiv
