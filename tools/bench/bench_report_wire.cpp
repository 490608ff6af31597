#include "bench_report_wire.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace subdiv_bench {
namespace {

constexpr std::uint64_t kMagic = 0x53444b42454e4348ull;  // "SDKBENCH"

struct WireHeader {
  std::uint64_t magic;
  Timings cold, warm;
  bool warm_digest_same;
  double peak_mb;
  std::int64_t base_faces, vertices, faces;
  std::uint64_t digest, check_modulus, record_count;
  std::int64_t kernel_points, plan_points, generic_points, flat_points;
};

void write_all(int fd, const void* data, size_t size) {
  for (const char* p = static_cast<const char*>(data); size > 0;) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error(std::string("worker: write to parent failed: ") + std::strerror(errno));
    p += n, size -= size_t(n);
  }
}

std::string describe_exit(int status) {
  if (WIFSIGNALED(status))
    return "worker killed by signal " + std::to_string(WTERMSIG(status)) +
           (WTERMSIG(status) == SIGKILL ? " (out of memory?)" : "");
  return "worker failed (exit " + std::to_string(WEXITSTATUS(status)) + ")";
}

}  // namespace

void send_report(int fd, const WorkerReport& r) {
  const WireHeader h{kMagic,   r.cold,          r.warm,           r.warm_digest_same, r.peak_mb,
                     r.base_faces, r.vertices,  r.faces,          r.digest,           r.check_modulus,
                     r.records.size(), r.kernel_points, r.plan_points, r.generic_points, r.flat_points};
  write_all(fd, &h, sizeof h);
  if (!r.records.empty()) write_all(fd, r.records.data(), r.records.size() * sizeof(CheckRecord));
}

std::string read_until_closed(int fd) {
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return bytes;
    bytes.append(buffer, size_t(n));
  }
}

bool parse_report(const std::string& bytes, WorkerReport& r) {
  WireHeader h;
  if (bytes.size() < sizeof h) return false;
  std::memcpy(&h, bytes.data(), sizeof h);
  if (h.magic != kMagic || bytes.size() != sizeof h + h.record_count * sizeof(CheckRecord)) return false;
  r.cold = h.cold, r.warm = h.warm, r.warm_digest_same = h.warm_digest_same, r.peak_mb = h.peak_mb;
  r.base_faces = h.base_faces, r.vertices = h.vertices, r.faces = h.faces;
  r.digest = h.digest, r.check_modulus = h.check_modulus;
  r.kernel_points = h.kernel_points, r.plan_points = h.plan_points, r.generic_points = h.generic_points;
  r.flat_points = h.flat_points;
  r.records.resize(h.record_count);
  if (h.record_count) std::memcpy(r.records.data(), bytes.data() + sizeof h, h.record_count * sizeof(CheckRecord));
  return true;
}

std::string run_self_as_worker(std::vector<std::string> args, WorkerReport& report) {
  int fds[2];
  if (::pipe(fds) != 0) return std::string("pipe: ") + std::strerror(errno);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {  // the child: the report goes to fd 3
    ::close(fds[0]);
    if (fds[1] != 3) ::dup2(fds[1], 3), ::close(fds[1]);
    ::execv("/proc/self/exe", argv.data());
    std::fprintf(stderr, "%s: cannot run itself: %s\n", args[0].c_str(), std::strerror(errno));
    ::_exit(127);
  }
  ::close(fds[1]);
  if (pid < 0) {
    ::close(fds[0]);
    return std::string("fork: ") + std::strerror(errno);
  }
  const std::string bytes = read_until_closed(fds[0]);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return describe_exit(status);
  if (!parse_report(bytes, report)) return "worker sent a malformed report";
  return "";
}

}  // namespace subdiv_bench
