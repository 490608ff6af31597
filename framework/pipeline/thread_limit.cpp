#include "framework/pipeline/thread_limit.h"

#include <tbb/global_control.h>

namespace subdiv {

struct ThreadLimit::Control {
  tbb::global_control control;
};

ThreadLimit::ThreadLimit(long long threads, const std::string& option)
    : count_(capped_thread_count(threads, option)) {
  if (count_.threads > 0)
    control_.reset(
        new Control{tbb::global_control(tbb::global_control::max_allowed_parallelism, size_t(count_.threads))});
}

ThreadLimit::~ThreadLimit() = default;

}  // namespace subdiv
