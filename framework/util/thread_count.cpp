#include "framework/util/thread_count.h"

#include <sched.h>
#include <thread>

#include <fmt/format.h>

#include "framework/util/error.h"

namespace subdiv {

int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? int(hardware) : 1;
}

ThreadCount capped_thread_count(long long requested, const std::string& option) {
  if (requested < 0)
    throw Error(fmt::format("{} {}: the number of threads must be 0 (all cores) or more", option, requested));
  if (requested == 0) return {0, ""};
  const int cores = available_cores();
  if (requested <= cores) return {int(requested), ""};
  return {cores, fmt::format("{} {} is more than the {} core{} this process may use; using {}", option, requested,
                             cores, cores == 1 ? "" : "s", cores)};
}

}  // namespace subdiv
