#pragma once
// A parallel loop whose bodies run the engine (whose own loops are parallel) and may throw.
//
// When a body of tbb::parallel_for throws, TBB cancels the loop's task group, and every
// parallel algorithm nested in a body still running belongs to that group: it returns at
// once without doing its work. A sibling body half-way through a refinement would then go
// on with arrays that were never filled (a crash instead of the first body's message).
// Here no exception leaves a body: each body runs to its end or to its own exception, and
// after the loop the exception of the lowest index that threw is rethrown — the same one
// for any thread count, since bodies after a failed index are skipped and those before it
// always run. The indices run in ranges, each in order.
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/util/step_progress.h"

namespace subdiv {

// Whether the loop tells the share of its indices done to the calling thread's
// StepProgressScope (a front-end's bar during a long evaluation). Off where the loop is
// part of a larger step that tells its own shares.
enum class LoopProgress { Silent, Told };

template <class I, class Body>
void parallel_for_all(I count, const Body& body, LoopProgress progress = LoopProgress::Silent) {
  std::atomic<I> first_failed{std::numeric_limits<I>::max()};
  std::atomic<I> done{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto failed = [&](I i) {  // called in a catch block
    std::lock_guard lock(error_mutex);
    if (i < first_failed.load(std::memory_order_relaxed)) {
      first_failed.store(i, std::memory_order_relaxed);
      error = std::current_exception();
    }
  };
  tbb::parallel_for(tbb::blocked_range<I>(I(0), count), [&](const tbb::blocked_range<I>& range) {
    for (I i = range.begin(); i != range.end(); ++i) {
      if (i > first_failed.load(std::memory_order_relaxed)) return;
      try {
        body(i);
      } catch (...) {
        failed(i);
      }
    }
    // Counted on every thread, told on the calling one only (the others have no scope). A
    // report that throws (a Python callback's exception) stops the loop as a body would.
    if (progress == LoopProgress::Silent) return;
    try {
      const I now = done.fetch_add(I(range.size()), std::memory_order_relaxed) + I(range.size());
      StepProgressScope::tell(double(now) / double(count));
    } catch (...) {
      failed(range.end() - 1);
    }
  });
  if (error) std::rethrow_exception(error);
}

}  // namespace subdiv
