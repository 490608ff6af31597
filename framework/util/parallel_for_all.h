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
// always run.
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <tbb/parallel_for.h>

namespace subdiv {

template <class I, class Body>
void parallel_for_all(I count, const Body& body) {
  std::atomic<I> first_failed{std::numeric_limits<I>::max()};
  std::exception_ptr error;
  std::mutex error_mutex;
  tbb::parallel_for(I(0), count, [&](I i) {
    if (i > first_failed.load(std::memory_order_relaxed)) return;
    try {
      body(i);
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (i < first_failed.load(std::memory_order_relaxed)) {
        first_failed.store(i, std::memory_order_relaxed);
        error = std::current_exception();
      }
    }
  });
  if (error) std::rethrow_exception(error);
}

}  // namespace subdiv
