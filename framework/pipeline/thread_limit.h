#pragma once
// How many worker threads the library may use while one of these lives: the front-ends'
// `--threads`, `threads=` and the filter's Threads. Results are the same bits for any count.
#include <memory>

namespace subdiv {

class ThreadLimit {
public:
  // 0 (or less): no limit, every core. A count above the machine's cores is capped at them:
  // more threads than cores only cost memory and switching.
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

  // The number of threads in force (the cap applied), or 0 for no limit.
  int threads() const { return threads_; }

private:
  struct Control;
  std::unique_ptr<Control> control_;
  int threads_ = 0;
};

// The cores this process may use (its affinity mask, at least 1).
int available_cores();

}  // namespace subdiv
