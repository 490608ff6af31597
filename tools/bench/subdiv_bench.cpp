// subdiv-bench: SubdivKit against OpenSubdiv's Far on large generated meshes.
//
// For every scheme and level the parent process starts one worker process per library
// (this program again, with the hidden --worker option). A worker builds the mesh, marks
// its memory baseline, runs the refinement --repeat times and sends back the best times,
// its peak memory above the baseline, and origin-keyed positions for the correctness
// check. Separate processes keep the two libraries' memory peaks apart.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_common.h"

#ifdef SUBDIV_BENCH_HAVE_OPENSUBDIV
#include <opensubdiv/version.h>
#endif

namespace subdiv_bench {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;
constexpr double kTolerance = 1e-9;

// ---- worker <-> parent wire format (a pipe; both ends are this same binary) ----------

constexpr std::uint64_t kMagic = 0x53444b42454e4348ull;  // "SDKBENCH"

struct WireHeader {
  std::uint64_t magic;
  Timings best;
  double peak_mb;
  std::int64_t base_faces, vertices, faces;
  std::uint64_t digest, check_modulus, record_count;
};

void write_all(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error(std::string("worker: write to parent failed: ") + std::strerror(errno));
    p += n;
    size -= size_t(n);
  }
}

void send_report(int fd, const WorkerReport& r) {
  const WireHeader h{kMagic, r.best, r.peak_mb, r.base_faces, r.vertices, r.faces, r.digest, r.check_modulus, r.records.size()};
  write_all(fd, &h, sizeof h);
  if (!r.records.empty()) write_all(fd, r.records.data(), r.records.size() * sizeof(CheckRecord));
}

bool parse_report(const std::string& bytes, WorkerReport& r) {
  WireHeader h;
  if (bytes.size() < sizeof h) return false;
  std::memcpy(&h, bytes.data(), sizeof h);
  if (h.magic != kMagic || bytes.size() != sizeof h + h.record_count * sizeof(CheckRecord)) return false;
  r.best = h.best;
  r.peak_mb = h.peak_mb;
  r.base_faces = h.base_faces;
  r.vertices = h.vertices;
  r.faces = h.faces;
  r.digest = h.digest;
  r.check_modulus = h.check_modulus;
  r.records.resize(h.record_count);
  if (h.record_count) std::memcpy(r.records.data(), bytes.data() + sizeof h, h.record_count * sizeof(CheckRecord));
  return true;
}

// ---- worker ---------------------------------------------------------------------------

int worker_main(const Job& job, int fd) {
  try {
    const Mesh mesh = make_mesh(job.mesh, job.faces);
    // The mesh arrays are the input of both libraries: they are the baseline, not part
    // of either library's peak.
    reset_peak_rss();
    const std::int64_t baseline = current_rss_bytes();
    WorkerReport report;
    if (job.side == "subdivkit") {
      report = run_subdivkit(job, mesh);
    } else if (job.side == "osd") {
#ifdef SUBDIV_BENCH_HAVE_OPENSUBDIV
      report = run_osd(job, mesh);
#else
      throw std::runtime_error("built without OpenSubdiv");
#endif
    } else {
      throw std::runtime_error("unknown side " + job.side);
    }
    report.peak_mb = double(std::max<std::int64_t>(0, report.peak_rss_bytes - baseline)) / kMiB;
    report.base_faces = mesh.face_count();
    send_report(fd, report);
    ::close(fd);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "subdiv-bench worker (%s %s level %d): %s\n", job.side.c_str(), job.scheme.c_str(),
                 job.level, e.what());
    return 1;
  }
}

// ---- parent ---------------------------------------------------------------------------

struct RunResult {
  bool ok = false;
  std::string error;
  WorkerReport report;
};

// Runs `job` in a fresh process: this executable with the hidden worker options.
RunResult run_worker(const Job& job) {
  RunResult result;
  int fds[2];
  if (::pipe(fds) != 0) {
    result.error = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  std::vector<std::string> args = {"subdiv-bench",
                                   "--worker", job.side,
                                   "--worker-fd", "3",
                                   "--schemes", job.scheme,
                                   "--mesh", job.mesh,
                                   "--faces", std::to_string(job.faces),
                                   "--levels", std::to_string(job.level),
                                   "--threads", std::to_string(job.threads),
                                   "--repeat", std::to_string(job.repeat),
                                   "--check-max", std::to_string(job.check_max),
                                   "--clock", clock_name(job.clock),
                                   "--row-plans", job.row_plans ? "on" : "off",
                                   "--geometry", job.tables ? "tables" : "direct"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    result.error = std::string("fork: ") + std::strerror(errno);
    ::close(fds[0]);
    ::close(fds[1]);
    return result;
  }
  if (pid == 0) {
    ::close(fds[0]);
    if (fds[1] != 3) {
      ::dup2(fds[1], 3);
      ::close(fds[1]);
    }
    ::execv("/proc/self/exe", argv.data());
    std::fprintf(stderr, "subdiv-bench: cannot re-run itself: %s\n", std::strerror(errno));
    ::_exit(127);
  }
  ::close(fds[1]);
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.append(buffer, size_t(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    result.error = WIFSIGNALED(status) ? "worker killed by signal " + std::to_string(WTERMSIG(status)) +
                                             (WTERMSIG(status) == SIGKILL ? " (out of memory?)" : "")
                                       : "worker failed (exit " + std::to_string(WEXITSTATUS(status)) + ")";
    return result;
  }
  if (!parse_report(bytes, result.report)) {
    result.error = "worker sent a malformed report";
    return result;
  }
  result.ok = true;
  return result;
}

struct CheckResult {
  bool ok = false;
  std::int64_t compared = 0;
  double maxdiff = 0;
  std::string problem;
};

// Matches the two sides' vertices by origin key and compares positions.
CheckResult compare(WorkerReport& a, WorkerReport& b) {
  CheckResult c;
  if (a.vertices != b.vertices) {
    c.problem = "vertex counts differ (" + std::to_string(a.vertices) + " vs " + std::to_string(b.vertices) + ")";
    return c;
  }
  if (a.check_modulus != b.check_modulus) {
    c.problem = "internal: different check sampling";
    return c;
  }
  auto by_key = [](const CheckRecord& x, const CheckRecord& y) { return x.key < y.key; };
  std::sort(a.records.begin(), a.records.end(), by_key);
  std::sort(b.records.begin(), b.records.end(), by_key);
  auto has_duplicates = [](const std::vector<CheckRecord>& r) {
    return std::adjacent_find(r.begin(), r.end(), [](auto& x, auto& y) { return x.key == y.key; }) != r.end();
  };
  if (has_duplicates(a.records) || has_duplicates(b.records)) {
    c.problem = "two vertices with the same origin key";
    return c;
  }
  if (a.records.size() != b.records.size()) {
    c.problem = "different vertex origins (" + std::to_string(a.records.size()) + " vs " +
                std::to_string(b.records.size()) + " sampled)";
    return c;
  }
  for (size_t i = 0; i < a.records.size(); ++i) {
    if (a.records[i].key != b.records[i].key) {
      c.problem = "different vertex origins";
      return c;
    }
    for (int k = 0; k < 3; ++k) {
      const double d = std::abs(a.records[i].xyz[k] - b.records[i].xyz[k]);
      if (!(d <= c.maxdiff)) c.maxdiff = std::isnan(d) ? INFINITY : d;
    }
  }
  c.compared = std::int64_t(a.records.size());
  c.ok = c.maxdiff < kTolerance;
  return c;
}

std::vector<int> parse_levels(const std::string& text) {
  std::vector<int> levels;
  auto bad = [&] { return std::invalid_argument("--levels: expected N (1..N), A-B or a list A,B,C; got '" + text + "'"); };
  try {
    if (const auto dash = text.find('-'); dash != std::string::npos) {
      const int a = std::stoi(text.substr(0, dash)), b = std::stoi(text.substr(dash + 1));
      for (int l = a; l <= b; ++l) levels.push_back(l);
    } else if (text.find(',') != std::string::npos) {
      std::stringstream in(text);
      std::string item;
      while (std::getline(in, item, ',')) levels.push_back(std::stoi(item));
    } else {
      const int n = std::stoi(text);
      for (int l = 1; l <= n; ++l) levels.push_back(l);
    }
  } catch (const std::logic_error&) {
    throw bad();
  }
  if (levels.empty()) throw bad();
  for (int l : levels)
    if (l < 1 || l > 6) throw std::invalid_argument("--levels: each level must be between 1 and 6");
  return levels;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) items.push_back(item);
  return items;
}

std::string cpu_name() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

std::string fmt_ms(double ms) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", ms);
  return buf;
}

class Progress {
public:
  explicit Progress(int total) : total_(total), tty_(::isatty(2) != 0) {}
  void show(int index, const std::string& what) {
    if (!tty_) return;
    std::fprintf(stderr, "\r\033[K[%d/%d] %s", index, total_, what.c_str());
    std::fflush(stderr);
  }
  void clear() {
    if (tty_) std::fprintf(stderr, "\r\033[K");
  }

private:
  int total_;
  bool tty_;
};

// The base face count for `level`: --faces, reduced so the refined mesh has at most
// `max_refined` faces (both schemes quadruple the face count per level).
std::int64_t base_faces_for(std::int64_t faces, int level, std::int64_t max_refined) {
  if (max_refined <= 0) return faces;
  return std::max<std::int64_t>(1, std::min(faces, max_refined >> (2 * level)));
}

int parent_main(const std::vector<std::string>& schemes, const std::vector<std::string>& meshes,
                const std::vector<int>& levels, Job base, const std::string& sides, bool check,
                std::int64_t max_refined) {
  const bool want_subdivkit = sides == "both" || sides == "subdivkit";
  bool want_osd = sides == "both" || sides == "osd";
#ifndef SUBDIV_BENCH_HAVE_OPENSUBDIV
  if (want_osd) {
    std::fprintf(stderr, "subdiv-bench: built without OpenSubdiv (install libosd-dev and rebuild); "
                         "timing SubdivKit only\n");
    want_osd = false;
  }
  const char* osd_version = "none";
#else
  const std::string osd_version_text = std::to_string(OPENSUBDIV_VERSION_MAJOR) + "." +
                                       std::to_string(OPENSUBDIV_VERSION_MINOR) + "." +
                                       std::to_string(OPENSUBDIV_VERSION_PATCH);
  const char* osd_version = osd_version_text.c_str();
#endif
  if (!want_subdivkit && !want_osd) return 1;
  if (!want_subdivkit || !want_osd) check = false;  // nothing to compare with

  double load[3] = {0, 0, 0};
  if (::getloadavg(load, 3) < 0) load[0] = -1;
  std::printf("# subdiv-bench: cpu=\"%s\" hardware_threads=%u threads=%d repeat=%d clock=%s opensubdiv=%s "
              "loadavg=%.2f\n",
              cpu_name().c_str(), std::thread::hardware_concurrency(), base.threads, base.repeat,
              clock_name(base.clock), osd_version, load[0]);
  std::fflush(stdout);

  struct Case {
    std::string scheme, mesh;
    int level;
  };
  std::vector<Case> cases;
  for (const auto& s : schemes) {
    if (s == "loop") {
      for (int l : levels) cases.push_back({s, "tri-torus", l});
    } else {
      for (const auto& m : meshes)
        for (int l : levels) cases.push_back({s, m, l});
    }
  }

  const int steps = int(cases.size()) * (int(want_subdivkit) + int(want_osd));
  Progress progress(steps);
  int step = 0, failures = 0;
  for (const auto& c : cases) {
    Job job = base;
    job.scheme = c.scheme;
    job.mesh = c.mesh;
    job.level = c.level;
    job.faces = base_faces_for(base.faces, c.level, max_refined);
    if (!check) job.check_max = -1;  // the workers send no positions back
    RunResult ours, theirs;
    if (want_subdivkit) {
      progress.show(++step, c.scheme + " " + c.mesh + " level " + std::to_string(c.level) + ": SubdivKit");
      job.side = "subdivkit";
      ours = run_worker(job);
    }
    if (want_osd) {
      progress.show(++step, c.scheme + " " + c.mesh + " level " + std::to_string(c.level) + ": OpenSubdiv");
      job.side = "osd";
      theirs = run_worker(job);
    }
    progress.clear();

    const RunResult* any = ours.ok ? &ours : (theirs.ok ? &theirs : nullptr);
    std::string line = c.scheme + " level=" + std::to_string(c.level) +
                       " faces=" + std::to_string(any ? any->report.base_faces : job.faces);
    auto field = [&](const std::string& name, const std::string& value) { line += " " + name + "=" + value; };
    if (any) field("refined_faces", std::to_string(any->report.faces));
    const auto& a = ours.report.best;
    const auto& b = theirs.report.best;
    auto na = [](bool ok, double v) { return ok ? fmt_ms(v) : std::string("n/a"); };
    field("subdivkit_ms", na(ours.ok, a.total_ms()));
    field("osd_ms", na(theirs.ok, b.total_ms()));
    field("topo_ms", na(ours.ok, a.topo_ms));
    field("osd_topo_ms", na(theirs.ok, b.topo_ms));
    field("geom_ms", na(ours.ok, a.geom_ms()));
    field("osd_geom_ms", na(theirs.ok, b.geom_ms()));
    field("subdivkit_peak_mb", na(ours.ok, ours.report.peak_mb));
    field("osd_peak_mb", na(theirs.ok, theirs.report.peak_mb));
    field("setup_ms", na(ours.ok, a.setup_ms));
    field("osd_setup_ms", na(theirs.ok, b.setup_ms));
    field("stencil_ms", na(ours.ok, a.stencil_ms));
    field("apply_ms", na(ours.ok, a.apply_ms));
    field("mesh", c.mesh);
    field("threads", std::to_string(base.threads));
    if (ours.ok) {
      char digest[24];
      std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(ours.report.digest));
      field("digest", digest);
    }
    if (!ours.ok && want_subdivkit) field("subdivkit_error", "\"" + ours.error + "\""), ++failures;
    if (!theirs.ok && want_osd) field("osd_error", "\"" + theirs.error + "\""), ++failures;
    if (ours.ok && theirs.ok && check) {
      const CheckResult r = compare(ours.report, theirs.report);
      char diff[32];
      std::snprintf(diff, sizeof diff, "%.3g", r.maxdiff);
      if (r.ok) {
        field("check", "ok");
        field("maxdiff", diff);
        field("checked", std::to_string(r.compared) + "/" + std::to_string(ours.report.vertices));
      } else {
        ++failures;
        field("check", "FAIL");
        if (r.problem.empty()) field("maxdiff", diff);
        else field("reason", "\"" + r.problem + "\"");
      }
    } else if (ours.ok && theirs.ok) {
      field("check", "off");
    }
    if (ours.ok && theirs.ok) {
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%.2f", a.total_ms() / b.total_ms());
      field("ratio", ratio);
    } else {
      field("ratio", "n/a");
    }
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  }
  return failures ? 1 : 0;
}

}  // namespace
}  // namespace subdiv_bench

int main(int argc, char** argv) {
  using namespace subdiv_bench;
  CLI::App app{
      "subdiv-bench: times SubdivKit against OpenSubdiv (Far uniform refinement + primvar interpolation)\n"
      "on large generated meshes, per scheme and level, with each library's peak memory measured in its\n"
      "own process and the two results checked against each other. Prints one line per scheme and level,\n"
      "ending in ratio=R (SubdivKit time / OpenSubdiv time)."};
  Job job;
  job.faces = 1'000'000;
  job.threads = 1;
  job.repeat = 1;
  job.check_max = 4'000'000;
  std::string levels_text = "1-3", schemes_text = "catmull-clark,loop", mesh_text = "torus", sides = "both";
  std::string check_mode = "sample", clock = "wall";
  std::string worker_side;
  int worker_fd = -1;
  std::int64_t max_refined = 16'000'000;

  app.add_option("--faces", job.faces, "approximate face count of the generated base mesh")
      ->capture_default_str()
      ->check(CLI::Range(std::int64_t(1), std::int64_t(50'000'000)));
  app.add_option("--max-refined-faces", max_refined,
                 "memory guard: for a level whose refined mesh would exceed this many faces, the base "
                 "mesh is made smaller to fit (0: no limit; 1M faces at level 3 needs about 20 GB "
                 "in OpenSubdiv)")
      ->capture_default_str();
  app.add_option("--levels", levels_text, "levels to time: N (1..N), A-B, or A,B,C")->capture_default_str();
  app.add_option("--schemes", schemes_text, "comma list of catmull-clark, loop")->capture_default_str();
  app.add_option("--mesh", mesh_text,
                 "Catmull-Clark base mesh(es), comma list: torus (regular quads), torus-ev (valence 3, 4 "
                 "and 6 vertices), cube-sphere (eight valence-3 vertices). Loop always uses tri-torus")
      ->capture_default_str();
  app.add_option("--threads", job.threads, "SubdivKit threads (OpenSubdiv Far is single-threaded)")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  app.add_option("--repeat", job.repeat, "repetitions per measurement; the best is reported")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--side", sides, "both, subdivkit or osd")
      ->capture_default_str()
      ->check(CLI::IsMember({"both", "subdivkit", "osd"}));
  app.add_option("--check", check_mode,
                 "compare the two libraries' positions: sample (at most --check-max vertices, chosen by "
                 "origin), full, or off")
      ->capture_default_str()
      ->check(CLI::IsMember({"sample", "full", "off"}));
  app.add_option("--check-max", job.check_max, "vertices compared per level with --check sample")
      ->capture_default_str();
  app.add_option("--clock", clock,
                 "wall: elapsed time; cpu: process CPU time (user + system), steadier on a shared "
                 "machine, comparable only with --threads 1; user: user time only (leaves out the kernel's "
                 "page zeroing, whose cost on a virtual machine depends on the host)")
      ->capture_default_str()
      ->check(CLI::IsMember({"wall", "cpu", "user"}));
  std::string row_plans = "on";
  app.add_option("--row-plans", row_plans, "SubdivKit: replay learnt stencil rows for smooth interior elements (off: "
                                           "the generic rule interpreter for every row, to measure what plans give)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  std::string geometry = "direct";
  app.add_option("--geometry", geometry,
                 "SubdivKit: direct (each level's positions straight from the rules, step_values) or tables "
                 "(build the stencil tables, then apply them)")
      ->check(CLI::IsMember({"direct", "tables"}))
      ->capture_default_str();
  app.add_option("--worker", worker_side)->group("");  // internal: run one measurement
  app.add_option("--worker-fd", worker_fd)->group("");
  CLI11_PARSE(app, argc, argv);
  job.clock = clock == "cpu" ? Clock::Cpu : clock == "user" ? Clock::User : Clock::Wall;
  job.row_plans = row_plans == "on";
  job.tables = geometry == "tables";
  if (job.clock != Clock::Wall && job.threads > 1 && worker_side.empty())
    std::fprintf(stderr, "subdiv-bench: note: --clock %s adds up the CPU time of all %d threads\n", clock.c_str(), job.threads);

  try {
    if (!worker_side.empty()) {
      job.side = worker_side;
      job.scheme = schemes_text;
      job.mesh = mesh_text;
      job.level = std::stoi(levels_text);
      return worker_main(job, worker_fd);
    }
    const auto schemes = split_list(schemes_text);
    for (const auto& s : schemes)
      if (s != "catmull-clark" && s != "loop")
        throw std::invalid_argument("--schemes: unknown scheme '" + s + "' (catmull-clark, loop)");
    const auto meshes = split_list(mesh_text);
    for (const auto& m : meshes)
      if (m != "torus" && m != "torus-ev" && m != "cube-sphere")
        throw std::invalid_argument("--mesh: unknown mesh '" + m + "' (torus, torus-ev, cube-sphere)");
    if (check_mode == "full") job.check_max = 0;
    return parent_main(schemes, meshes, parse_levels(levels_text), job, sides, check_mode != "off",
                       max_refined);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "subdiv-bench: %s\n", e.what());
    return 2;
  }
}
