#pragma once
// How many worker threads the library may use while one of these lives: the front-ends'
// `--threads`, `threads=` and the filter's Threads. Results are the same bits for any count.
#include <memory>
#include <string>

#include "framework/util/thread_count.h"

namespace subdiv {

class ThreadLimit {
public:
  // 0: no limit, every core. A count above the cores this process may use is capped at them
  // (util/thread_count.h: more threads than cores only cost memory), with a note saying so;
  // a negative count throws subdiv::Error naming `option` as the caller's user spells it.
  explicit ThreadLimit(long long threads, const std::string& option = "threads");
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

  // The number of threads in force (the cap applied), or 0 for no limit.
  int threads() const { return count_.threads; }
  // Non-empty when the request was capped: say it to the user.
  const std::string& note() const { return count_.note; }

private:
  struct Control;
  std::unique_ptr<Control> control_;
  ThreadCount count_;
};

}  // namespace subdiv
