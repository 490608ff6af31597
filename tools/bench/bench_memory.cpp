#include "bench_memory.h"

#include <malloc.h>

#include "framework/util/bulk_memory.h"

namespace subdiv_bench {
namespace {

// The heap keeps what is freed, and SubdivKit's bulk arrays use the heap: see the header.
void keep_memory_in_process() {
  mallopt(M_MMAP_MAX, 0);
  // -1: never trim (mallopt(3)). INT_MAX, the largest positive value, stopped holding the
  // memory once the heap passed 2 GiB (level 2 at 16M faces faulted fresh pages each time).
  mallopt(M_TRIM_THRESHOLD, -1);
  mallopt(M_TOP_PAD, 64 << 20);
  subdiv::reuse_bulk_memory(true);
}

}  // namespace

WorkerReport repeat_cold_and_warm(const Job& job, const Repetition& once) {
  WorkerReport report;
  const std::uint64_t cold_digest = once(report.cold, &report);

  keep_memory_in_process();
  Timings unmeasured;
  report.warm_digest_same = once(unmeasured, nullptr) == cold_digest;
  for (int rep = 0; rep < job.repeat; ++rep) {
    Timings t;
    report.warm_digest_same &= once(t, nullptr) == cold_digest;
    if (rep == 0 || t.total().wall_ms < report.warm.total().wall_ms) report.warm = t;
  }
  return report;
}

}  // namespace subdiv_bench
