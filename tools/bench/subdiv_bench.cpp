// subdiv-bench: SubdivKit against OpenSubdiv's Far on large generated meshes.
//
// For every scheme and level the parent process starts one worker process per library
// (this program again, with the hidden --worker option). A worker builds the mesh, marks
// its memory baseline, runs the refinement once cold and --repeat times warm
// (bench_memory.h) and sends back both times, its peak memory above the baseline, and
// origin-keyed positions for the correctness check. Separate processes keep the two
// libraries' memory peaks apart.
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

#include "bench_bandwidth.h"
#include "bench_common.h"
#include "bench_report_wire.h"

#ifdef SUBDIV_BENCH_HAVE_OPENSUBDIV
#include <opensubdiv/version.h>
#endif

namespace subdiv_bench {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;
constexpr double kTolerance = 1e-9;

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
  std::vector<double> round_warm_ms;  // each round's best warm wall ms (total; update: one re-evaluation)
};

// Runs `job` in a fresh process: this executable with the hidden worker options.
RunResult run_worker(const Job& job) {
  RunResult result;
  result.error = run_self_as_worker({"subdiv-bench",
                                     "--worker", job.side,
                                     "--worker-fd", "3",
                                     "--schemes", job.scheme,
                                     "--mesh", job.mesh,
                                     "--faces", std::to_string(job.faces),
                                     "--levels", std::to_string(job.level),
                                     "--threads", std::to_string(job.threads),
                                     "--repeat", std::to_string(job.repeat),
                                     "--check-max", std::to_string(job.check_max),
                                     "--osd-topology", job.osd_full_topology ? "full" : "default",
                                     "--row-plans", job.row_plans ? "on" : "off",
                                     "--kernels", job.kernels ? "on" : "off",
                                     "--geometry", job.tables ? "tables" : "direct",
                                     "--mode", job.update ? "update" : "refine"},
                                    result.report);
  result.ok = result.error.empty();
  return result;
}

// One more round of a side's worker folded into `best` (the first round's result): the
// faster warm and the faster cold repetition are kept apart, by wall-clock total (update:
// one re-evaluation); peak, digest, counts and check records stay the first round's, and
// every round must give its digest.
void fold_round(RunResult& best, RunResult next, bool update) {
  const auto measure = [update](const Timings& t) { return update ? t.apply.wall_ms : t.total().wall_ms; };
  if (best.round_warm_ms.empty()) {
    best = std::move(next);
    best.round_warm_ms = {measure(best.report.warm)};
    return;
  }
  if (!best.ok) return;
  if (!next.ok) {
    best.ok = false, best.error = next.error;
    return;
  }
  if (next.report.digest != best.report.digest) {
    best.ok = false, best.error = "round " + std::to_string(best.round_warm_ms.size() + 1) + " gave other positions";
    return;
  }
  best.report.warm_digest_same &= next.report.warm_digest_same;
  best.round_warm_ms.push_back(measure(next.report.warm));
  if (measure(next.report.warm) < measure(best.report.warm)) best.report.warm = next.report.warm;
  if (measure(next.report.cold) < measure(best.report.cold)) best.report.cold = next.report.cold;
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

// "a/b/c": each round's best warm wall ms.
std::string round_list(const RunResult& r) {
  std::string out;
  for (double ms : r.round_warm_ms) out += (out.empty() ? "" : "/") + fmt_ms(ms);
  return out;
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

// One clock's times of one repetition kind: totals, stages and ratios (SubdivKit / OSD).
std::string timing_fields(const RunResult& ours, const RunResult& theirs, bool warm, bool user, bool update) {
  auto pick = [&](const Clocks& c) { return user ? c.user_ms : c.wall_ms; };
  const Timings& a = warm ? ours.report.warm : ours.report.cold;
  const Timings& b = warm ? theirs.report.warm : theirs.report.cold;
  std::string out;
  auto field = [&](const std::string& name, bool ok, double ms) { out += " " + name + "=" + (ok ? fmt_ms(ms) : "n/a"); };
  auto ratio = [&](const std::string& name, double x, double y) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", x / y);
    out += " " + name + "=" + (ours.ok && theirs.ok && y > 0 ? std::string(text) : "n/a");
  };
  field("subdivkit_ms", ours.ok, pick(a.total()));
  field("osd_ms", theirs.ok, pick(b.total()));
  ratio("ratio", pick(a.total()), pick(b.total()));
  field("setup_ms", ours.ok, pick(a.setup));
  field("osd_setup_ms", theirs.ok, pick(b.setup));
  field("topo_ms", ours.ok, pick(a.topo));
  field("osd_topo_ms", theirs.ok, pick(b.topo));
  ratio("topo_ratio", pick(a.topo), pick(b.topo));
  field("geom_ms", ours.ok, pick(a.geom()));
  field("osd_geom_ms", theirs.ok, pick(b.geom()));
  ratio("geom_ratio", pick(a.geom()), pick(b.geom()));
  if (ours.ok && pick(a.stencil) > 0) field("stencil_ms", true, pick(a.stencil));
  if (theirs.ok && pick(b.stencil) > 0) field("osd_stencil_ms", true, pick(b.stencil));
  if (update) {  // one re-evaluation of the positions, the topology and tables already made
    field("update_ms", ours.ok, pick(a.apply));
    field("osd_update_ms", theirs.ok, pick(b.apply));
    ratio("update_ratio", pick(a.apply), pick(b.apply));
  }
  return out;
}

// The machine's memory bandwidth in this run (one core), at its start and end: each level's
// line then says how far it is from the bound, the bytes its levels must write over it.
subdiv::bench::Bandwidth g_bandwidth;

void print_bandwidth(const char* when) {
  const subdiv::bench::Bandwidth b = subdiv::bench::measure_bandwidth();
  if (g_bandwidth.write_gbs == 0) g_bandwidth = b;
  std::printf("# bandwidth at=%s memset_gbs=%.2f memcpy_gbs=%.2f (one core, 512 MB, best of 5; memcpy counts bytes "
              "read and written)\n",
              when, b.write_gbs, b.copy_gbs);
  std::fflush(stdout);
}

// Bytes the refinement must write: every level's positions (3 doubles a vertex) and face
// vertex indices (4 bytes each), levels 1..L, each a quarter of the next (quads and
// triangles split in four). A lower bound on the traffic: the reads are not counted.
double written_bytes(const WorkerReport& r, int level, int face_size) {
  double bytes = 24.0 * double(r.vertices) + 4.0 * face_size * double(r.faces), all = 0;
  for (int l = level; l >= 1; --l, bytes /= 4) all += bytes;
  return all;
}

int parent_main(const std::vector<std::string>& schemes, const std::vector<std::string>& meshes,
                const std::vector<int>& levels, Job base, const std::string& sides, bool check,
                std::int64_t max_refined, const std::vector<bool>& osd_topologies, int rounds) {
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
  std::printf("# subdiv-bench: cpu=\"%s\" hardware_threads=%u threads=%d warm_repeat=%d rounds=%d opensubdiv=%s "
              "loadavg=%.2f %.2f %.2f\n",
              cpu_name().c_str(), std::thread::hardware_concurrency(), base.threads, base.repeat, rounds,
              osd_version, load[0], load[1], load[2]);
  print_bandwidth("start");

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

  const int osd_variants = int(osd_topologies.size());
  const int steps = int(cases.size()) * osd_variants * (int(want_subdivkit) + int(want_osd)) * rounds;
  Progress progress(steps);
  int step = 0, failures = 0;
  for (const auto& c : cases) {
    Job job = base;
    job.scheme = c.scheme;
    job.mesh = c.mesh;
    job.level = c.level;
    job.faces = base_faces_for(base.faces, c.level, max_refined);
    if (!check) job.check_max = -1;  // the workers send no positions back
    const std::string what = c.scheme + " " + c.mesh + " level " + std::to_string(c.level);
    // Per topology variant (the last level's faces only as OpenSubdiv's default, and full
    // topology with --osd-topology full or both, on both sides), --rounds runs of each side,
    // alternating, so that both see the same moments of a noisy machine.
    std::vector<RunResult> ours(want_subdivkit ? osd_topologies.size() : 0);
    std::vector<RunResult> theirs(want_osd ? osd_topologies.size() : 0);
    for (size_t v = 0; v < osd_topologies.size(); ++v) {
      const std::string variant = osd_topologies[v] ? " (full topology)" : "";
      job.osd_full_topology = osd_topologies[v];
      for (int round = 1; round <= rounds; ++round) {
        const std::string which = rounds > 1 ? ", round " + std::to_string(round) : "";
        if (want_subdivkit) {
          progress.show(++step, what + ": SubdivKit" + variant + which);
          job.side = "subdivkit";
          fold_round(ours[v], run_worker(job), job.update);
        }
        if (want_osd) {
          progress.show(++step, what + ": OpenSubdiv" + variant + which);
          job.side = "osd";
          fold_round(theirs[v], run_worker(job), job.update);
        }
      }
    }
    progress.clear();

    const std::string head = c.scheme + " mesh=" + c.mesh + " level=" + std::to_string(c.level);
    RunResult none;
    for (size_t v = 0; v < osd_topologies.size(); ++v)
      for (bool warm : {false, true})
        for (bool user : {false, true}) {
          std::string line = head + " memory=" + (warm ? "warm" : "cold") + " clock=" + (user ? "user" : "wall");
          line += std::string(" topology=") + (osd_topologies[v] ? "full" : "default");
          if (job.update) line += " mode=update";
          line += timing_fields(want_subdivkit ? ours[v] : none, want_osd ? theirs[v] : none, warm, user, job.update);
          std::printf("%s\n", line.c_str());
        }

    RunResult& first = want_subdivkit ? ours[0] : none;  // the headline variant
    std::string line = head + " faces=" + std::to_string(first.ok ? first.report.base_faces : job.faces);
    auto field = [&](const std::string& name, const std::string& value) { line += " " + name + "=" + value; };
    const RunResult* any = first.ok ? &first : nullptr;
    for (const auto& t : theirs) any = any ? any : (t.ok ? &t : nullptr);
    if (any) {
      field("refined_faces", std::to_string(any->report.faces));
      field("refined_vertices", std::to_string(any->report.vertices));
      const double bytes = written_bytes(any->report, c.level, c.scheme == "loop" ? 3 : 4);
      const double bound_ms = bytes / (g_bandwidth.write_gbs * 1e9) * 1e3;
      char text[64];
      std::snprintf(text, sizeof text, "%.1f", bytes / 1e6);
      field("written_mb", text);
      std::snprintf(text, sizeof text, "%.1f", bound_ms);
      field("bound_ms", text);
      if (!job.update && first.ok) {
        std::snprintf(text, sizeof text, "%.2f", first.report.warm.total().user_ms / bound_ms);
        field("x_bound", text);
      }
      if (!job.update && !theirs.empty() && theirs[0].ok) {
        std::snprintf(text, sizeof text, "%.2f", theirs[0].report.warm.total().user_ms / bound_ms);
        field("osd_x_bound", text);
      }
    }
    field("threads", std::to_string(base.threads));
    if (rounds > 1) {
      if (first.ok) field("subdivkit_round_ms", round_list(first));
      if (!theirs.empty() && theirs[0].ok) field("osd_round_ms", round_list(theirs[0]));
    }
    for (size_t v = 0; v < ours.size(); ++v)
      field(osd_topologies[v] ? "subdivkit_full_peak_mb" : "subdivkit_peak_mb", ours[v].ok ? fmt_ms(ours[v].report.peak_mb) : "n/a");
    for (size_t v = 0; v < theirs.size(); ++v)
      field(osd_topologies[v] ? "osd_full_peak_mb" : "osd_peak_mb", theirs[v].ok ? fmt_ms(theirs[v].report.peak_mb) : "n/a");
    if (first.ok) {
      char digest[24];
      std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(first.report.digest));
      field("digest", digest);
      field("warm_bits", first.report.warm_digest_same ? "same" : "DIFFERENT");
      if (!job.tables) {
        field("kernel_points", std::to_string(first.report.kernel_points));
        field("flat_points", std::to_string(first.report.flat_points));
        field("plan_points", std::to_string(first.report.plan_points));
        field("generic_points", std::to_string(first.report.generic_points));
      }
      if (!first.report.warm_digest_same) ++failures;
    }
    for (const auto& r : ours)
      if (!r.ok) field("subdivkit_error", "\"" + r.error + "\""), ++failures;
    for (const auto& t : theirs)
      if (!t.ok) field("osd_error", "\"" + t.error + "\""), ++failures;
    if (check && first.ok && !theirs.empty() && theirs[0].ok) {
      const CheckResult r = compare(first.report, theirs[0].report);
      char diff[32];
      std::snprintf(diff, sizeof diff, "%.3g", r.maxdiff);
      if (r.ok) {
        field("check", "ok");
        field("maxdiff", diff);
        field("checked", std::to_string(r.compared) + "/" + std::to_string(first.report.vertices));
      } else {
        ++failures;
        field("check", "FAIL");
        if (r.problem.empty()) field("maxdiff", diff);
        else field("reason", "\"" + r.problem + "\"");
      }
    } else {
      field("check", "off");
    }
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  }
  print_bandwidth("end");
  return failures ? 1 : 0;
}

}  // namespace
}  // namespace subdiv_bench

int main(int argc, char** argv) {
  using namespace subdiv_bench;
  CLI::App app{
      "subdiv-bench: times SubdivKit against OpenSubdiv (Far uniform refinement + primvar interpolation)\n"
      "on large generated meshes, per scheme and level, with each library's peak memory measured in its\n"
      "own process and the two results checked against each other. Each library runs once cold (fresh\n"
      "memory) and --repeat times warm (memory kept); both wall and user time are printed, one line\n"
      "per scheme, level, memory and clock with ratio=R (SubdivKit time / OpenSubdiv time), then one\n"
      "line of memory peaks and the check."};
  Job job;
  job.faces = 1'000'000;
  job.threads = 1;
  job.repeat = 2;
  job.check_max = 4'000'000;
  std::string levels_text = "1-3", schemes_text = "catmull-clark,loop", mesh_text = "torus", sides = "both";
  std::string check_mode = "sample", osd_topology = "default";
  std::string worker_side;
  int worker_fd = -1;
  std::int64_t max_refined = 16'000'000;
  int rounds = 1;

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
  app.add_option("--repeat", job.repeat,
                 "warm repetitions per measurement, after the cold one and one unmeasured warm-up; the "
                 "best is reported (see docs/benchmarks.md, \"Cold and warm\")")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--rounds", rounds,
                 "runs of each side's worker process, alternating SubdivKit and OpenSubdiv, so both meet "
                 "the same moments of a noisy machine; the best warm and the best cold of all rounds are "
                 "reported, and each round's warm time as subdivkit_round_ms / osd_round_ms")
      ->capture_default_str()
      ->check(CLI::Range(1, 20));
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
  app.add_option("--osd-topology", osd_topology,
                 "the last level's topology, on both sides: default (faces only, OpenSubdiv's UniformOptions "
                 "as its users run it, and RefineOptions::faces_only_last_level), full (edges and vertex "
                 "rings too: fullTopologyInLastLevel), or both (a second set of lines)")
      ->capture_default_str()
      ->check(CLI::IsMember({"default", "full", "both"}));
  std::string row_plans = "on";
  app.add_option("--row-plans", row_plans, "SubdivKit: replay learnt stencil rows for smooth interior elements (off: "
                                           "the generic rule interpreter for every row, to measure what plans give)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  std::string kernels = "on";
  app.add_option("--kernels", kernels,
                 "SubdivKit: compute smooth interior points with the compiled kernels (off: plans and the rule "
                 "interpreter, to measure what kernels give; the points are the same to round-off)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  std::string mode = "refine";
  app.add_option("--mode", mode,
                 "refine: topology and positions every repetition; update: repeated evaluation (animation, "
                 "editing): topology (and tables) once, then each repetition re-evaluates the positions only, "
                 "SubdivKit's Evaluator (or one composed table with --geometry tables) against OpenSubdiv's "
                 "StencilTableFactory + UpdateValues; update_ms is one re-evaluation")
      ->check(CLI::IsMember({"refine", "update"}))
      ->capture_default_str();
  std::string geometry = "direct";
  app.add_option("--geometry", geometry,
                 "SubdivKit: direct (each level's positions straight from the rules, step_values; with --mode "
                 "update an Evaluator made once) or tables (build the stencil tables, then apply them; with "
                 "--mode update one table composed over the levels)")
      ->check(CLI::IsMember({"direct", "tables"}))
      ->capture_default_str();
  app.add_option("--worker", worker_side)->group("");  // internal: run one measurement
  app.add_option("--worker-fd", worker_fd)->group("");
  CLI11_PARSE(app, argc, argv);
  job.row_plans = row_plans == "on";
  job.kernels = kernels == "on";
  job.tables = geometry == "tables";
  job.update = mode == "update";

  try {
    if (!worker_side.empty()) {
      job.side = worker_side;
      job.scheme = schemes_text;
      job.mesh = mesh_text;
      job.level = std::stoi(levels_text);
      job.osd_full_topology = osd_topology == "full";
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
    const std::vector<bool> osd_topologies = osd_topology == "both"   ? std::vector<bool>{false, true}
                                             : osd_topology == "full" ? std::vector<bool>{true}
                                                                      : std::vector<bool>{false};
    return parent_main(schemes, meshes, parse_levels(levels_text), job, sides, check_mode != "off",
                       max_refined, osd_topologies, rounds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "subdiv-bench: %s\n", e.what());
    return 2;
  }
}
