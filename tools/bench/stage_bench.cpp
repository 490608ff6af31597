// subdiv-bench-stages: where a refinement's time goes, stage by stage, on one and on two
// threads (issue 32, item 1: the serial part of a step).
//
// One process refines the same generated mesh as subdiv-bench (base level, topology to the
// level with the last level's faces only, positions level by level with step_values), in
// rounds that alternate the thread counts, so every count meets the same stretches of a
// noisy machine. Each stage (engine/refiner.h, EvaluationSwitches::stage_times) reports
// its wall and process CPU time; per thread count the best round (smallest total wall) is
// kept, and per stage the smallest wall over the rounds. For two threads a stage's
// `cores` (CPU / wall) says how much of it ran in parallel, and its `loss` (wall on two
// threads minus half its wall on one) is what it costs against a perfect speed-up: the
// losses add up to the total's.
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <oneapi/tbb/global_control.h>

#include "bench_common.h"
#include "bench_mesh.h"
#include "framework/engine/refiner.h"
#include "framework/rules/stage_times.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/topology/level.h"
#include "framework/util/bulk_memory.h"
#include "framework/util/scratch_vector.h"

namespace {

using subdiv_bench::digest_of;

struct Round {
  double total_wall_ms = 0, total_cpu_ms = 0;
  std::vector<subdiv::StageTimes::Entry> stages;
  std::uint64_t digest = 0;
};

double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}
double wall_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// One refinement as subdiv-bench's SubdivKit side runs it (bench_subdivkit.cpp).
Round refine_once(const subdiv::Scheme& scheme, const subdiv_bench::Mesh& mesh, int level, int threads) {
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, size_t(threads));
  subdiv::StageTimes times;
  subdiv::RefineOptions options;
  options.levels = level;
  options.faces_only_last_level = true;
  options.evaluation.stage_times = &times;
  const double wall0 = wall_ms(), cpu0 = cpu_ms();
  std::optional<subdiv::StageTimer> timer(std::in_place, &times, "L0 base level");
  subdiv::Level base = subdiv::build_level(mesh.vertex_count, mesh.face_offsets, mesh.face_vertices);
  timer.reset();
  subdiv::Hierarchy h = subdiv::refine_topology(scheme, std::move(base), options);
  subdiv::ScratchVector<double> src, dst;
  for (int l = 0; l < level; ++l) {
    const std::span<const double> from = l == 0 ? std::span<const double>(mesh.xyz) : std::span<const double>(src);
    dst.resize(3 * size_t(h.levels[size_t(l) + 1].vertex_count));
    subdiv::step_values(scheme, h, l, from, dst, 3, options);
    std::swap(src, dst);
    subdiv::ScratchVector<double>().swap(dst);
  }
  Round r;
  r.total_wall_ms = wall_ms() - wall0, r.total_cpu_ms = cpu_ms() - cpu0;
  r.stages = times.entries();
  r.digest = digest_of(src);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"subdiv-bench-stages: each stage of a refinement on one and two threads (docs/benchmarks.md)"};
  std::string scheme_name = "catmull-clark", mesh_kind;
  std::int64_t faces = 1000000;
  int level = 2, rounds = 5;
  std::vector<int> thread_counts{1, 2};
  app.add_option("--scheme", scheme_name, "a scheme name (catmull-clark, loop)");
  app.add_option("--mesh", mesh_kind, "a subdiv-bench mesh kind (default: torus, tri-torus for Loop)");
  app.add_option("--faces", faces, "approximate face count of the base mesh")->check(CLI::Range(1, 50000000));
  app.add_option("--level", level, "levels to refine")->check(CLI::Range(1, 6));
  app.add_option("--rounds", rounds, "rounds; each runs every thread count once")->check(CLI::Range(1, 100));
  app.add_option("--threads", thread_counts, "thread counts, alternated within each round")->delimiter(',');
  CLI11_PARSE(app, argc, argv);
  if (mesh_kind.empty()) mesh_kind = scheme_name == "loop" ? "tri-torus" : "torus";
  try {
    const auto scheme = subdiv::load_scheme(scheme_name);
    const subdiv_bench::Mesh mesh = subdiv_bench::make_mesh(mesh_kind, faces);
    double load[3] = {-1, -1, -1};
    getloadavg(load, 3);
    std::printf("# subdiv-bench-stages: scheme=%s mesh=%s faces=%d level=%d rounds=%d loadavg=%.2f %.2f %.2f\n",
                scheme_name.c_str(), mesh_kind.c_str(), mesh.face_count(), level, rounds, load[0], load[1], load[2]);
    // Warm memory, as subdiv-bench's warm repetitions (bench_memory.h): the heap keeps what is freed.
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1);
    mallopt(M_TOP_PAD, 64 << 20);
    subdiv::reuse_bulk_memory(true);
    for (int t : thread_counts) refine_once(*scheme, mesh, level, t);  // unmeasured: the heap grows
    std::map<int, Round> best;                                         // per thread count: the best round
    std::map<int, std::map<std::string, subdiv::StageTimes::Entry>> fastest;  // per count and stage
    std::map<int, std::vector<double>> round_ms;
    bool same_bits = true;
    std::uint64_t digest = 0;
    for (int r = 0; r < rounds; ++r)
      for (int t : thread_counts) {
        Round now = refine_once(*scheme, mesh, level, t);
        if (digest == 0) digest = now.digest;
        same_bits &= now.digest == digest;
        round_ms[t].push_back(now.total_wall_ms);
        for (const auto& e : now.stages) {
          auto [it, fresh] = fastest[t].try_emplace(e.name, e);
          if (!fresh && e.wall_ms < it->second.wall_ms) it->second = e;
        }
        if (!best.count(t) || now.total_wall_ms < best[t].total_wall_ms) best[t] = std::move(now);
      }
    const int one = thread_counts.front();
    const Round& base = best[one];
    for (int t : thread_counts) {
      const Round& b = best[t];
      std::printf("total threads=%d wall_ms=%.1f cpu_ms=%.1f cores=%.2f speedup=%.2f rounds_ms=", t, b.total_wall_ms,
                  b.total_cpu_ms, b.total_cpu_ms / b.total_wall_ms, base.total_wall_ms / b.total_wall_ms);
      for (size_t i = 0; i < round_ms[t].size(); ++i) std::printf("%s%.1f", i ? "/" : "", round_ms[t][i]);
      std::printf("\n");
    }
    // Stages in the order they ran, fastest wall over the rounds.
    for (const auto& e : base.stages) {
      const auto& s1 = fastest[one][e.name];
      std::printf("stage=\"%s\" t%d_wall_ms=%.2f", e.name.c_str(), one, s1.wall_ms);
      for (int t : thread_counts) {
        if (t == one) continue;
        const auto& st = fastest[t][e.name];
        std::printf(" t%d_wall_ms=%.2f t%d_cpu_ms=%.2f cores=%.2f speedup=%.2f loss_ms=%.2f", t, st.wall_ms, t,
                    st.cpu_ms, st.wall_ms > 0 ? st.cpu_ms / st.wall_ms : 0.0, st.wall_ms > 0 ? s1.wall_ms / st.wall_ms : 0.0,
                    st.wall_ms - s1.wall_ms / t);
      }
      std::printf("\n");
    }
    double sum1 = 0;
    for (const auto& [name, e] : fastest[one]) sum1 += e.wall_ms;
    std::printf("summary stages_t%d_ms=%.1f outside_stages_t%d_ms=%.1f digest=%016llx bits=%s\n", one, sum1, one,
                base.total_wall_ms - sum1, static_cast<unsigned long long>(digest), same_bits ? "same" : "DIFFERENT");
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    getloadavg(load, 3);
    std::printf("# process user_s=%.2f sys_s=%.2f loadavg_end=%.2f %.2f %.2f\n",
                double(usage.ru_utime.tv_sec) + usage.ru_utime.tv_usec * 1e-6,
                double(usage.ru_stime.tv_sec) + usage.ru_stime.tv_usec * 1e-6, load[0], load[1], load[2]);
    return same_bits ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "subdiv-bench-stages: %s\n", e.what());
    return 1;
  }
}
