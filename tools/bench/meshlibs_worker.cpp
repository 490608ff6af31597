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

std::string describe_exit(int status) {
  if (WIFSIGNALED(status))
    return "worker killed by signal " + std::to_string(WTERMSIG(status)) +
           (WTERMSIG(status) == SIGKILL ? " (out of memory?)" : "");
  return "worker failed (exit " + std::to_string(WEXITSTATUS(status)) + ")";
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
        cold->generic_points = refined.generic_points;
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
  int fds[2];
  if (::pipe(fds) != 0) {
    outcome.error = std::string("pipe: ") + std::strerror(errno);
    return outcome;
  }
  std::vector<std::string> args = job.worker_args();
  args.insert(args.begin(), "subdiv-bench-meshlibs");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {  // the child: the report goes to fd 3
    ::close(fds[0]);
    if (fds[1] != 3) ::dup2(fds[1], 3), ::close(fds[1]);
    ::execv("/proc/self/exe", argv.data());
    std::fprintf(stderr, "subdiv-bench-meshlibs: cannot run itself: %s\n", std::strerror(errno));
    ::_exit(127);
  }
  ::close(fds[1]);
  if (pid < 0) {
    outcome.error = std::string("fork: ") + std::strerror(errno);
    ::close(fds[0]);
    return outcome;
  }
  const std::string bytes = read_until_closed(fds[0]);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) outcome.error = describe_exit(status);
  else if (!parse_report(bytes, outcome.report)) outcome.error = "worker sent a malformed report";
  else outcome.ok = true;
  return outcome;
}

}  // namespace subdiv_bench
