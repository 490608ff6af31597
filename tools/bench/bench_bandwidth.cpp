#include "bench_bandwidth.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>

namespace subdiv::bench {
namespace {

template <class F>
double best_seconds(int tries, F&& run) {
  double best = 1e30;
  for (int t = 0; t < tries; ++t) {
    const auto start = std::chrono::steady_clock::now();
    run();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

}  // namespace

Bandwidth measure_bandwidth(int megabytes, int tries) {
  const size_t bytes = size_t(megabytes) << 20;
  std::unique_ptr<char[]> a(new char[bytes]), b(new char[bytes]);
  std::memset(a.get(), 1, bytes);  // first touch, not timed
  std::memset(b.get(), 2, bytes);
  volatile char sink = 0;
  int fill = 0;
  const double write = best_seconds(tries, [&] {
    std::memset(a.get(), ++fill, bytes);
    sink = sink + a[bytes / 2];
  });
  const double copy = best_seconds(tries, [&] {
    std::memcpy(b.get(), a.get(), bytes);
    sink = sink + b[bytes / 3];
  });
  return {double(bytes) / write / 1e9, 2.0 * double(bytes) / copy / 1e9};
}

}  // namespace subdiv::bench
