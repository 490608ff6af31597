#pragma once
// Cold and warm repetitions, the same way for both libraries.
//
// Cold: the first repetition in a fresh worker process, with the C library's default
// allocation (large blocks mmap'ed and returned on free), so every array lands on pages
// the process has never touched. On a virtual machine the first touch of a page is the
// dearest part of the work (docs/benchmarks.md), and the library with the larger
// footprint pays more of it.
//
// Warm: the same work repeated in the same process with its memory kept, as in any program
// that refines more than once: the heap stops returning memory to the system
// (mallopt M_MMAP_MAX = 0 and M_TRIM_THRESHOLD = unlimited) and SubdivKit's bulk arrays
// come from that heap (subdiv::reuse_bulk_memory), so each repetition allocates on pages
// an earlier one touched. One unmeasured repetition switches over, then job.repeat measured
// ones; the best (smallest wall-clock total) is reported.
#include <functional>

#include "bench_common.h"

namespace subdiv_bench {

// One complete refinement, its stages timed into `t`. With `report` non-null (the cold
// repetition) the side also fills in its results: peak memory first, then counts, digest
// and check records. Returns the digest of the refined positions.
using Repetition = std::function<std::uint64_t(Timings& t, WorkerReport* report)>;

WorkerReport repeat_cold_and_warm(const Job& job, const Repetition& once);

}  // namespace subdiv_bench
