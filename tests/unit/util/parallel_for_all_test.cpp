// parallel_for_all: a body that throws must not cancel the parallel work nested in the other
// bodies (TBB cancels the whole task group of a loop whose body throws, nested algorithms
// included), and the exception reported is the lowest failing index's, for any thread count.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "framework/util/parallel_for_all.h"

using subdiv::parallel_for_all;

namespace {

// Body i: i in `failing` throws "failed i" after a short wait (so that the other bodies are
// inside their nested loops); every other body runs a nested parallel loop of `inner` items
// and records whether all of them ran.
struct Probe {
  std::vector<int> failing;
  int inner = 2000;
  std::vector<std::atomic<int>> complete;
  explicit Probe(int count, std::vector<int> fail) : failing(std::move(fail)), complete(size_t(count)) {}
  void operator()(int i) {
    for (int f : failing)
      if (f == i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        throw std::runtime_error("failed " + std::to_string(i));
      }
    std::atomic<int> done{0};
    tbb::parallel_for(0, inner, [&](int) {
      volatile double x = 1;
      for (int k = 0; k < 200; ++k) x = x * 1.0000001;
      done.fetch_add(1, std::memory_order_relaxed);
    });
    complete[size_t(i)] = done.load() == inner ? 1 : -1;
  }
};

}  // namespace

TEST_CASE("A throwing body leaves the nested work of the others whole, and the lowest failure is reported") {
  for (int threads : {1, 2, 4}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    for (int round = 0; round < 20; ++round) {
      Probe probe(64, {5, 40});
      std::string what;
      try {
        parallel_for_all(64, [&](int i) { probe(i); });
      } catch (const std::runtime_error& e) {
        what = e.what();
      }
      CHECK(what == "failed 5");
      int started = 0;
      for (int i = 0; i < 64; ++i) {
        CHECK(probe.complete[size_t(i)] != -1);  // a body that ran did all its nested work
        started += probe.complete[size_t(i)] == 1;
      }
      // Every index below the first failure ran (and so was not skipped).
      for (int i = 0; i < 5; ++i) CHECK(probe.complete[size_t(i)] == 1);
      CHECK(started >= 5);
    }
  }
}

TEST_CASE("Without failures every body runs once") {
  std::vector<std::atomic<int>> runs(1000);
  parallel_for_all(size_t(1000), [&](size_t i) { runs[i].fetch_add(1); });
  for (auto& r : runs) CHECK(r.load() == 1);
}
