// A full disk while writing any output format: subdiv::Error naming the target and saying
// the disk is full, and the directory as it was (no temporary, no level folder, an existing
// target untouched). VTK's XML writer crashed here (SIGSEGV, "free(): invalid pointer")
// when its stream failed. The disk is a small tmpfs where this process may mount one;
// elsewhere the test executable runs itself again as a child with a file size limit
// (RLIMIT_FSIZE, SIGXFSZ ignored, so writes fail with EFBIG instead of killing it).
#include <csignal>
#include <cstdlib>
#include <random>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "framework/io/mesh_write.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

constexpr long kDiskBytes = 64 * 1024;
const char* const kChildVariable = "SUBDIV_DISK_FULL_CHILD";  // "<target>" for the child run

// A grid of quads with coordinates that do not compress: every format needs several times
// the small disk.
MeshData large_mesh() {
  constexpr int n = 60;
  MeshData m;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.insert(m.positions.end(), {i + jitter(random), j + jitter(random), jitter(random)});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index v = Index(j * (n + 1) + i);
      m.face_vertices.insert(m.face_vertices.end(), {v, v + 1, v + n + 2, v + n + 1});
      m.face_offsets.push_back(Index(m.face_vertices.size()));
    }
  return m;
}

// The message of the failed write, from this process on a tmpfs or from a child under a
// file size limit; "<no error>" if the write succeeded.
std::string write_on_small_disk(const fs::path& dir, const fs::path& target) {
  if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, fmt::format("size={}", kDiskBytes).c_str()) == 0) {
    std::string message;
    write_text(dir / "keep.txt", "kept");
    message = error_of([&] { write_mesh(target, large_mesh()); });
    std::vector<std::string> after;
    for (const auto& e : fs::recursive_directory_iterator(dir)) after.push_back(e.path().filename().string());
    std::sort(after.begin(), after.end());
    message += "\nentries:";
    for (const std::string& e : after) message += " " + e;
    ::umount2(dir.c_str(), MNT_DETACH);
    return message;
  }
  const fs::path report = dir.parent_path() / (dir.filename().string() + ".message");
  const pid_t child = ::fork();
  if (child == 0) {  // only async-signal-safe calls until exec
    const rlimit limit{rlim_t(kDiskBytes), rlim_t(kDiskBytes)};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    ::signal(SIGXFSZ, SIG_IGN);
    ::setenv(kChildVariable, target.c_str(), 1);
    ::execl("/proc/self/exe", "test_io", "-tc=disk full: the child's write", "-nv", "-m", nullptr);
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  REQUIRE(WIFEXITED(status));
  return read_text(report);
}

}  // namespace

TEST_CASE("disk full: the child's write") {
  const char* target = std::getenv(kChildVariable);
  if (!target) return;  // only when the test below runs this executable as its child
  const fs::path t = target;
  const fs::path dir = t.parent_path();
  std::string message = error_of([&] { write_mesh(t, large_mesh()); });
  std::vector<std::string> after;
  for (const auto& e : fs::recursive_directory_iterator(dir)) after.push_back(e.path().filename().string());
  std::sort(after.begin(), after.end());
  message += "\nentries:";
  for (const std::string& e : after) message += " " + e;
  write_text(dir.parent_path() / (dir.filename().string() + ".message"), message);
}

TEST_CASE("disk full: every output format fails with a message and leaves the directory as it was") {
  for (const char* ext : {".obj", ".off", ".ply", ".stl", ".vtp", ".pvd"}) {
    const std::string format = ext;
    CAPTURE(format);
    TempDir scratch;
    const fs::path dir = scratch / "disk";
    fs::create_directory(dir);
    const fs::path target = dir / (std::string("out") + ext);
    const std::string message = write_on_small_disk(dir, target);
    CAPTURE(message);
    CHECK(contains(message, "cannot write '" + dir.string() + "/out"));
    CHECK((contains(message, "the disk is full") || contains(message, "larger than allowed")));
    // Only what was there before: the tmpfs run's kept file, nothing of the failed write.
    const std::string entries = message.substr(message.find("\nentries:") + 9);
    CHECK((entries == "" || entries == " keep.txt"));
  }
}

TEST_CASE("disk full: an existing target is left as it was (where a tmpfs can be mounted)") {
  TempDir scratch;
  const fs::path dir = scratch / "disk";
  fs::create_directory(dir);
  if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, fmt::format("size={}", kDiskBytes).c_str()) != 0) {
    MESSAGE("no tmpfs: write_errors_test.cpp covers an existing target on failure");
    return;
  }
  for (const char* ext : {".obj", ".vtp"}) {
    const std::string format = ext;
    CAPTURE(format);
    const fs::path target = dir / (std::string("kept") + ext);
    write_text(target, "old");
    CHECK(contains(error_of([&] { write_mesh(target, large_mesh()); }), "disk is full"));
    CHECK(read_text(target) == "old");
  }
  CHECK(scratch.entries() == std::vector<std::string>{"disk", "disk/kept.obj", "disk/kept.vtp"});
  ::umount2(dir.c_str(), MNT_DETACH);
}
