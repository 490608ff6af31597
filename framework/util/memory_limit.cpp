#include "framework/util/memory_limit.h"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

#include "framework/util/byte_size_text.h"

namespace subdiv {
namespace fs = std::filesystem;

namespace {

// cgroup v1 writes "no limit" as a huge number (LONG_MAX rounded to pages).
constexpr double kNoLimit = double(1ull << 60);

std::optional<double> read_number(const fs::path& file) {
  std::ifstream in(file);
  std::string word;
  if (!(in >> word) || word == "max") return std::nullopt;
  try {
    size_t used = 0;
    const double value = std::stod(word, &used);
    if (used != word.size() || value < 0 || value >= kNoLimit) return std::nullopt;
    return value;
  } catch (const std::exception&) {
    return std::nullopt;  // not a number: treat as unknown rather than refuse
  }
}

// Page cache the kernel reclaims before it refuses memory: the group's usage counts it,
// and after a big build it can fill the group up to its limit without being in anyone's way.
double reclaimable_cache(const fs::path& dir) {
  std::ifstream stat(dir / "memory.stat");
  std::string key;
  double value = 0, own = 0, total = 0;  // v1 also gives total_* (with the child groups), v2 does not
  while (stat >> key >> value) {
    if (key == "inactive_file" || key == "active_file") own += value;
    if (key == "total_inactive_file" || key == "total_active_file") total += value;
  }
  return total > 0 ? total : own;
}

void keep_least(std::optional<MemoryBudget>& best, double bytes, std::string source) {
  if (bytes < 0) bytes = 0;
  if (!best || bytes < best->bytes) best = MemoryBudget{bytes, std::move(source)};
}

// From the group's own folder up to the mount point: a parent's limit binds its children.
// In a container with its own cgroup namespace the path is "/" and the mount point is
// the container's group itself.
void walk_up(const fs::path& root, const fs::path& path, const char* limit_file, const char* usage_file,
             std::optional<MemoryBudget>& best) {
  for (fs::path relative = path.relative_path();; relative = relative.parent_path()) {
    const fs::path dir = relative.empty() ? root : root / relative;
    if (const auto limit = read_number(dir / limit_file)) {
      const double used = std::max(0.0, read_number(dir / usage_file).value_or(0.0) - reclaimable_cache(dir));
      keep_least(best, *limit - used,
                 fmt::format("the cgroup limit {} = {}", (dir / limit_file).string(), byte_size_text(*limit)));
    }
    if (relative.empty()) return;
  }
}

}  // namespace

std::optional<double> meminfo_available(const fs::path& meminfo) {
  std::ifstream in(meminfo);
  std::string key;
  double kb = 0;
  while (in >> key >> kb) {
    if (key == "MemAvailable:") return kb * 1024.0;
    in.ignore(256, '\n');
  }
  return std::nullopt;
}

std::optional<MemoryBudget> cgroup_remaining(const fs::path& cgroup_root, const fs::path& self_cgroup) {
  std::optional<MemoryBudget> best;
  std::ifstream in(self_cgroup);
  std::string line;
  while (std::getline(in, line)) {
    // "hierarchy-id:controllers:path"; v2 is "0::/path", v1's memory line names "memory".
    const size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const fs::path path = line.substr(second + 1);
    if (controllers.empty()) {
      walk_up(cgroup_root, path, "memory.max", "memory.current", best);
      continue;
    }
    std::stringstream names(controllers);
    for (std::string name; std::getline(names, name, ',');)
      if (name == "memory")
        walk_up(cgroup_root / "memory", path, "memory.limit_in_bytes", "memory.usage_in_bytes", best);
  }
  return best;
}

std::optional<MemoryBudget> rlimit_remaining() {
  std::optional<MemoryBudget> best;
  // /proc/self/statm: total program size and data + stack, in pages.
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0, shared = 0, text = 0, lib = 0, data = 0;
  statm >> size >> resident >> shared >> text >> lib >> data;
  const double page = double(sysconf(_SC_PAGESIZE));
  struct Limit {
    int resource;
    double used;
    const char* name;
  };
  for (const Limit& l : {Limit{RLIMIT_AS, size * page, "RLIMIT_AS (ulimit -v)"},
                         Limit{RLIMIT_DATA, data * page, "RLIMIT_DATA (ulimit -d)"}}) {
    rlimit r{};
    if (getrlimit(l.resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) continue;
    keep_least(best, double(r.rlim_cur) - l.used,
               fmt::format("the process limit {} = {}", l.name, byte_size_text(double(r.rlim_cur))));
  }
  return best;
}

MemoryBudget available_memory() {
  MemoryBudget budget;
  if (const auto machine = meminfo_available()) budget = {*machine, "MemAvailable in /proc/meminfo"};
  for (const auto& limit : {cgroup_remaining(), rlimit_remaining()})
    if (limit && limit->bytes < budget.bytes) budget = *limit;
  return budget;
}

std::string out_of_memory_message(const std::string& during, const std::string& fix) {
  const MemoryBudget budget = available_memory();
  const std::string have =
      budget.bytes >= 1e17 ? std::string("no limit is known")
                           : fmt::format("about {} was still available, limited by {}",
                                         byte_size_text(budget.bytes), budget.source);
  return fmt::format("out of memory while {} ({}); {}, or raise the limit", during, have, fix);
}

MemoryBudget memory_budget(double limit) {
  MemoryBudget have = available_memory();
  if (limit > 0 && limit < have.bytes) have = {limit, "the memory budget asked for"};
  return have;
}

}  // namespace subdiv
