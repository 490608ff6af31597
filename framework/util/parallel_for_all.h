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
#include <cstdint>
#include <exception>
#include <limits>
#include <mutex>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/util/step_progress.h"

namespace subdiv {

// Whether the loop tells the share of its indices done to the calling thread's
// StepProgressScope (a front-end's bar during a long evaluation): then it runs in 64 parts,
// one after the other, each in parallel. Off where the loop is part of a larger step that
// tells its own shares.
enum class LoopProgress { Silent, Told };

template <class I, class Body>
void parallel_for_all(I count, const Body& body, LoopProgress progress = LoopProgress::Silent) {
  std::atomic<I> first_failed{std::numeric_limits<I>::max()};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto failed = [&](I i) {  // called in a catch block
    std::lock_guard lock(error_mutex);
    if (i < first_failed.load(std::memory_order_relaxed)) {
      first_failed.store(i, std::memory_order_relaxed);
      error = std::current_exception();
    }
  };
  const auto run = [&](I begin, I end) {
    tbb::parallel_for(tbb::blocked_range<I>(begin, end), [&](const tbb::blocked_range<I>& range) {
      for (I i = range.begin(); i != range.end(); ++i) {
        if (i > first_failed.load(std::memory_order_relaxed)) return;
        try {
          body(i);
        } catch (...) {
          failed(i);
        }
      }
    });
  };
  if (progress == LoopProgress::Silent) {
    run(I(0), count);
  } else {
    // In parts, each told from the calling thread when it is done (whichever threads did its
    // work), so that the bar moves however the scheduler shares the indices. A report that
    // throws (a Python callback's exception) stops the loop as a body would.
    constexpr I kParts = 64;
    for (I part = 0; part < kParts && first_failed.load() == std::numeric_limits<I>::max(); ++part) {
      const auto share = [&](I k) { return I(std::uint64_t(count) * std::uint64_t(k) / kParts); };
      const I begin = share(part), end = share(part + 1);
      if (begin == end) continue;
      run(begin, end);
      try {
        StepProgressScope::tell(double(end) / double(count));
      } catch (...) {
        failed(end - 1);
      }
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace subdiv
