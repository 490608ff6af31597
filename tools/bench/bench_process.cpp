// Memory figures and small helpers shared by the sides.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "bench_common.h"

namespace subdiv_bench {
namespace {

std::int64_t status_field_bytes(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const size_t n = std::strlen(field);
  while (std::getline(in, line))
    if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':')
      return std::stoll(line.substr(n + 1)) * 1024;  // "VmHWM:   123456 kB"
  return 0;
}

}  // namespace

namespace {

Clocks read_clocks() {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const double user = double(usage.ru_utime.tv_sec) * 1e3 + double(usage.ru_utime.tv_usec) * 1e-3;
  const double wall =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
  return {wall, user};
}

}  // namespace

Stopwatch::Stopwatch() : last_(read_clocks()) {}

Clocks Stopwatch::lap() {
  const Clocks now = read_clocks();
  const Clocks since{now.wall_ms - last_.wall_ms, now.user_ms - last_.user_ms};
  last_ = now;
  return since;
}

std::int64_t current_rss_bytes() { return status_field_bytes("VmRSS"); }
std::int64_t peak_rss_bytes() { return status_field_bytes("VmHWM"); }

bool reset_peak_rss() {
  // Writing 5 to clear_refs resets VmHWM to the current RSS (Linux >= 4.0).
  std::FILE* f = std::fopen("/proc/self/clear_refs", "w");
  if (!f) return false;
  const bool ok = std::fputs("5", f) >= 0;
  return std::fclose(f) == 0 && ok;
}

std::uint64_t check_modulus_for(std::int64_t count, std::int64_t check_max) {
  if (check_max < 0) return 0;  // no check
  if (check_max == 0 || count <= check_max) return 1;
  return std::uint64_t((count + check_max - 1) / check_max);
}

}  // namespace subdiv_bench
