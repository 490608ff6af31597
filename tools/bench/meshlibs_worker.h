#pragma once
// subdiv-bench-meshlibs runs every measurement in a fresh process (this program again,
// with hidden --worker options), so that each library starts on fresh memory and its peak
// is its own: the worker builds the mesh, marks its memory baseline, runs the library once
// cold and --repeat times warm (bench_memory.h), and sends back the times, its peak above
// the baseline, the counts and the sampled points (meshlibs_check.h) through a pipe.
#include <cstdint>
#include <string>
#include <vector>

#include "bench_common.h"

namespace subdiv_bench {

struct MeshlibsJob {
  std::string library;  // subdivkit, openmesh or cgal
  std::string scheme;   // a SubdivKit scheme name (meshlibs_sides.h)
  std::string mesh;     // a mesh kind (meshlibs_mesh.h)
  std::int64_t faces = 0;
  int level = 1;
  int repeat = 2;
  std::int64_t check_max = 0;  // check_modulus_for's argument: -1 sends no points
  bool last_level_full = true;

  // The hidden options that make the child process run this job.
  std::vector<std::string> worker_args() const;
};

// In the child: runs the job and writes the report to `fd`. Returns the exit code.
int meshlibs_worker_main(const MeshlibsJob& job, int fd);

struct WorkerOutcome {
  bool ok = false;
  std::string error;
  WorkerReport report;
};

// In the parent: runs the job in a child process and reads its report.
WorkerOutcome run_meshlibs_worker(const MeshlibsJob& job);

}  // namespace subdiv_bench
