#include "meshlibs_worker.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <oneapi/tbb/global_control.h>

#include "bench_memory.h"
#include "bench_report_wire.h"
#include "meshlibs_check.h"
#include "meshlibs_mesh.h"
#include "meshlibs_sides.h"

namespace subdiv_bench {
namespace {

SideRun side_for(const MeshlibsJob& job) {
  const SideRequest request{job.scheme, job.level, job.last_level_full};
  SideRun run = job.library == "subdivkit" ? subdivkit_side(request)
                : job.library == "openmesh" ? openmesh_side(request)
                : job.library == "cgal"     ? cgal_side(request)
                                            : SideRun{};
  if (!run) throw std::runtime_error(job.library + " has no " + job.scheme + " here");
  return run;
}

}  // namespace

std::vector<std::string> MeshlibsJob::worker_args() const {
  return {"--worker", library, "--worker-fd", "3", "--schemes", scheme, "--worker-mesh", mesh,
          "--faces", std::to_string(faces), "--levels", std::to_string(level), "--repeat", std::to_string(repeat),
          "--check-max", std::to_string(check_max), "--last-level", last_level_full ? "full" : "faces"};
}

int meshlibs_worker_main(const MeshlibsJob& job, int fd) {
  try {
    // Single-threaded, every library: OpenMesh and CGAL do not thread their subdividers.
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const SideRun run = side_for(job);
    const Mesh mesh = make_meshlibs_mesh(job.mesh, job.faces);
    // The generated mesh is every library's input: the baseline, not part of a peak.
    reset_peak_rss();
    const std::int64_t baseline = current_rss_bytes();
    Job repetitions;
    repetitions.repeat = job.repeat;
    WorkerReport report = repeat_cold_and_warm(repetitions, [&](Timings& t, WorkerReport* cold) {
      Refined refined;
      run(mesh, t, refined);
      const std::uint64_t digest = digest_of(refined.xyz);
      if (cold) {
        cold->peak_rss_bytes = refined.peak_rss_bytes;
        cold->vertices = std::int64_t(refined.xyz.size() / 3);
        cold->faces = refined.faces;
        cold->digest = digest;
        cold->check_modulus = check_modulus_for(cold->vertices, job.check_max);
        cold->records = sample_points(refined.xyz, cold->check_modulus);
        cold->kernel_points = refined.kernel_points, cold->plan_points = refined.plan_points;
        cold->generic_points = refined.generic_points, cold->flat_points = refined.flat_points;
      }
      return digest;
    });
    report.peak_mb = double(std::max<std::int64_t>(0, report.peak_rss_bytes - baseline)) / (1024.0 * 1024.0);
    report.base_faces = mesh.face_count();
    send_report(fd, report);
    ::close(fd);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "subdiv-bench-meshlibs worker (%s %s level %d): %s\n", job.library.c_str(),
                 job.scheme.c_str(), job.level, e.what());
    return 1;
  }
}

WorkerOutcome run_meshlibs_worker(const MeshlibsJob& job) {
  WorkerOutcome outcome;
  std::vector<std::string> args = job.worker_args();
  args.insert(args.begin(), "subdiv-bench-meshlibs");
  outcome.error = run_self_as_worker(std::move(args), outcome.report);
  outcome.ok = outcome.error.empty();
  return outcome;
}

}  // namespace subdiv_bench
