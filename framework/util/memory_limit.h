#pragma once
// How much more memory this process may use: the least of the machine's MemAvailable, the
// process's own limits (ulimit -v / -d: RLIMIT_AS, RLIMIT_DATA) and its cgroup's memory
// limit (v2 memory.max, v1 memory.limit_in_bytes, each minus what the group already uses).
// A run that fits the machine but not its container or ulimit would otherwise end in
// std::bad_alloc, or in the kernel's OOM killer, half-way through.
#include <filesystem>
#include <new>
#include <optional>
#include <string>
#include <utility>

#include "framework/util/option_spelling.h"

namespace subdiv {

struct MemoryBudget {
  double bytes = 1e18;             // very large when nothing is known: never refuse then
  std::string source = "unknown";  // which limit is the tightest, for messages
};

MemoryBudget available_memory();

// What a request may take: available_memory(), or `limit` bytes when that is positive and
// smaller (the request's own budget, e.g. --max-memory).
MemoryBudget memory_budget(double limit);

// Needs below this are not checked against available_memory(): reading the limits (/proc and
// cgroup files) costs 0.2-0.3 ms, more than making something this small, and a process left
// with less than this has failed long before.
constexpr double kUncheckedBytes = 16 << 20;

// The parts, separately, with their files as parameters so that tests can give fakes.
// MemAvailable from a /proc/meminfo-format file.
std::optional<double> meminfo_available(const std::filesystem::path& meminfo = "/proc/meminfo");
// What the process's cgroup (and its ancestors) still allow: limit minus usage, the least
// over the hierarchy; nullopt when no limit is set or the files are not there.
// `self_cgroup` is a /proc/self/cgroup-format file, `cgroup_root` the cgroup mount point.
std::optional<MemoryBudget> cgroup_remaining(const std::filesystem::path& cgroup_root = "/sys/fs/cgroup",
                                             const std::filesystem::path& self_cgroup = "/proc/self/cgroup");
// What RLIMIT_AS and RLIMIT_DATA still allow, from the process's current sizes.
std::optional<MemoryBudget> rlimit_remaining();

// The message for a std::bad_alloc: what ran out while doing `during`, the budget and
// `fix`, the advice for what was asked (naming the option the user gave: "ask for fewer
// --samples", not levels for a command that has none). Every allocation failure the tool
// reports says this, never "internal error".
std::string out_of_memory_message(const std::string& during,
                                  const std::string& fix = "ask for fewer levels or a smaller input");

// Running out of memory, told with out_of_memory_message's words.
class OutOfMemoryError : public OptionError {
public:
  using OptionError::OptionError;
};

// `work()`, with a std::bad_alloc it throws turned into an OutOfMemoryError with
// out_of_memory_message(during, fix); `fix` may name options as the front-ends' placeholders
// ("ask for fewer {samples}", util/option_spelling.h). The outermost call names the work and
// the fix, as it knows what the user asked for: an OutOfMemoryError from a nested call
// (points evaluated for a sampled mesh) is told again in its words. The memory `work` held
// is freed by then, so the message's budget is what a retry would have.
template <class Work>
auto advising_when_out_of_memory(const std::string& during, const std::string& fix, Work&& work) -> decltype(work()) {
  try {
    return std::forward<Work>(work)();
  } catch (const std::bad_alloc&) {
    throw OutOfMemoryError(out_of_memory_message(during, fix));
  } catch (const OutOfMemoryError&) {
    throw OutOfMemoryError(out_of_memory_message(during, fix));
  }
}

}  // namespace subdiv
