// The memory budget honours the process's cgroup (v2 and v1, up the hierarchy) and its
// rlimits as well as MemAvailable, read from fake /sys/fs/cgroup trees here.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sys/resource.h>

#include "framework/util/memory_limit.h"
#include "support/sanitizers.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("subdivkit-memory-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

constexpr double GiB = double(1 << 30);

}  // namespace

TEST_CASE("cgroup v2: the least of limit minus usage over the group and its parents") {
  const fs::path root = fresh("v2");
  write(root / "self", "0::/user.slice/job\n");
  write(root / "fs/memory.max", "max\n");
  write(root / "fs/user.slice/memory.max", std::to_string(3 * (1ull << 30)) + "\n");
  write(root / "fs/user.slice/memory.current", std::to_string(1ull << 30) + "\n");
  write(root / "fs/user.slice/job/memory.max", "max\n");
  const auto budget = cgroup_remaining(root / "fs", root / "self");
  REQUIRE(budget);
  CHECK(budget->bytes == doctest::Approx(2 * GiB));
  CHECK(budget->source.find("user.slice/memory.max") != std::string::npos);

  write(root / "fs/user.slice/job/memory.max", std::to_string(1ull << 29) + "\n");
  CHECK(cgroup_remaining(root / "fs", root / "self")->bytes == doctest::Approx(0.5 * GiB));

  // Page cache counts in memory.current but the kernel reclaims it first: not in the way.
  write(root / "fs/user.slice/memory.stat", "anon 1000\nfile 1073741824\nactive_file 536870912\ninactive_file 536870912\n");
  write(root / "fs/user.slice/job/memory.max", "max\n");
  CHECK(cgroup_remaining(root / "fs", root / "self")->bytes == doctest::Approx(3 * GiB));
}

TEST_CASE("cgroup v1: memory.limit_in_bytes, with the huge 'unlimited' value ignored") {
  const fs::path root = fresh("v1");
  write(root / "self", "12:cpu,cpuacct:/\n7:memory:/docker/abc\n");
  write(root / "fs/memory/docker/abc/memory.limit_in_bytes", "9223372036854771712\n");
  CHECK_FALSE(cgroup_remaining(root / "fs", root / "self"));
  write(root / "fs/memory/docker/abc/memory.limit_in_bytes", std::to_string(1ull << 31) + "\n");
  write(root / "fs/memory/docker/abc/memory.usage_in_bytes", std::to_string(1ull << 30) + "\n");
  CHECK(cgroup_remaining(root / "fs", root / "self")->bytes == doctest::Approx(1 * GiB));
}

TEST_CASE("no cgroup files: no limit; MemAvailable parsed from meminfo") {
  const fs::path root = fresh("none");
  CHECK_FALSE(cgroup_remaining(root / "missing", root / "missing-self"));
  write(root / "meminfo", "MemTotal:       16000000 kB\nMemFree:  100 kB\nMemAvailable:    2097152 kB\n");
  CHECK(*meminfo_available(root / "meminfo") == doctest::Approx(2 * GiB));
}

TEST_CASE("RLIMIT_DATA lowers the budget below what the machine has") {
#if SUBDIV_TEST_ASAN
  MESSAGE("skipped: AddressSanitizer's shadow memory counts as data, far beyond any test limit");
#else
  rlimit old{};
  REQUIRE(getrlimit(RLIMIT_DATA, &old) == 0);
  rlimit lower = old;
  lower.rlim_cur = rlim_t(64) << 30;  // 64 GiB: above what this process uses, below "unlimited"
  if (old.rlim_max != RLIM_INFINITY && old.rlim_max < lower.rlim_cur) lower.rlim_cur = old.rlim_max;
  REQUIRE(setrlimit(RLIMIT_DATA, &lower) == 0);
  const auto limited = rlimit_remaining();
  setrlimit(RLIMIT_DATA, &old);
  REQUIRE(limited);
  CHECK(limited->bytes <= double(lower.rlim_cur));
  CHECK(limited->bytes > 0);
  CHECK(limited->source.find("RLIMIT_") != std::string::npos);
#endif
}

TEST_CASE("the out-of-memory message says what ran out and the fix") {
  const std::string m = out_of_memory_message("refining level 7");
  CHECK(m.find("out of memory while refining level 7") == 0);
  CHECK(m.find("ask for fewer levels") != std::string::npos);
  const std::string s = out_of_memory_message("sampling", "ask for fewer {samples}");
  CHECK(s.find("; ask for fewer {samples}, or raise the limit") != std::string::npos);
  CHECK(s.find("levels") == std::string::npos);
}

TEST_CASE("an allocation failure is told with the fix for what the outermost caller asked") {
  // --samples ran out of memory and was told to ask for fewer levels, which it has none of.
  const auto fail = []() -> int { throw std::bad_alloc(); };
  try {
    advising_when_out_of_memory("sampling", "ask for fewer {samples}", fail);
    FAIL("no exception");
  } catch (const OutOfMemoryError& e) {
    CHECK(std::string(e.what()).find("out of memory while sampling") == 0);
    CHECK(e.spelled({{"samples", "--samples"}}).find("ask for fewer --samples, or raise the limit") != std::string::npos);
  }
  // Points evaluated for a sampled mesh: the sampling's words, not the points'.
  try {
    advising_when_out_of_memory("sampling", "ask for fewer {samples}",
                                [&] { return advising_when_out_of_memory("evaluating 5 points", "evaluate fewer", fail); });
    FAIL("no exception");
  } catch (const OutOfMemoryError& e) {
    CHECK(std::string(e.what()).find("out of memory while sampling") == 0);
    CHECK(std::string(e.what()).find("evaluate fewer") == std::string::npos);
  }
  CHECK(advising_when_out_of_memory("x", "y", [] { return 7; }) == 7);
}
