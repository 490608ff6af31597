// The SubdivKit side of subdiv-bench: the engine's topology refinement, stencil tables
// and stencil application, timed separately.
#include <memory>
#include <stdexcept>

#include <oneapi/tbb/global_control.h>

#include "bench_common.h"
#include "bench_memory.h"
#include "framework/engine/evaluator.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/topology/level.h"
#include "framework/util/bulk_memory.h"
#include "framework/util/scratch_vector.h"

namespace subdiv_bench {
namespace {

// Keys of level i + 1 from keys of level i, through the engine's recorded origins.
std::vector<std::uint64_t> child_keys(const subdiv::Level& parent, const subdiv::ChildOrigins& origins,
                                      const std::vector<std::uint64_t>& keys) {
  std::vector<std::uint64_t> out(origins.kind.size());
  for (size_t c = 0; c < out.size(); ++c) {
    const subdiv::Index p = origins.parent[c];
    switch (origins.kind[c]) {
      case subdiv::OriginKind::Vertex: out[c] = key_of_vertex_child(keys[p]); break;
      case subdiv::OriginKind::Edge:
        out[c] = key_of_edge_child(keys[parent.edge_vertices[2 * p]], keys[parent.edge_vertices[2 * p + 1]]);
        break;
      case subdiv::OriginKind::Face: {
        std::uint64_t sum = 0;
        for (subdiv::Index v : parent.face(p)) sum += key_face_term(keys[v]);
        out[c] = key_of_face_child(sum, parent.face_size(p));
        break;
      }
      default: throw std::runtime_error("SubdivKit side: unexpected child origin kind for " + std::string("CC/Loop"));
    }
  }
  return out;
}

// The cold repetition's results: memory peak (before anything else is allocated), counts,
// the new points by path, and origin-keyed positions for the parent's check.
void report_results(const Job& job, const Mesh& mesh, const subdiv::Hierarchy& h, std::span<const double> xyz,
                    std::uint64_t digest, const subdiv::RowPaths& paths, WorkerReport& report) {
  report.peak_rss_bytes = peak_rss_bytes();
  report.kernel_points = paths.kernel, report.plan_points = paths.plan, report.generic_points = paths.generic;
  report.flat_points = paths.flat;
  const auto& last = h.levels[size_t(job.level)];
  report.vertices = last.vertex_count;
  report.faces = last.face_count();
  report.digest = digest;
  report.check_modulus = check_modulus_for(report.vertices, job.check_max);
  if (report.check_modulus == 0) return;
  std::vector<std::uint64_t> keys(size_t(mesh.vertex_count));
  for (std::int32_t v = 0; v < mesh.vertex_count; ++v) keys[v] = key_base(v);
  for (int l = 0; l < job.level; ++l) keys = child_keys(h.levels[size_t(l)], h.origins[size_t(l)], keys);
  for (size_t i = 0; i < keys.size(); ++i)
    if (keys[i] % report.check_modulus == 0) report.records.push_back({keys[i], {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}});
}

}  // namespace

namespace {

// --mode update: the topology once, and either one table composed over the levels
// (--geometry tables) or an Evaluator with every step made ready (--geometry direct,
// engine/evaluator.h); each repetition re-evaluates the positions only, into a buffer kept
// between repetitions (as OpenSubdiv's side keeps its table).
WorkerReport run_subdivkit_updates(const Job& job, const Mesh& mesh, const subdiv::Scheme& scheme,
                                   subdiv::RefineOptions options) {
  Timings once;
  Stopwatch clock;
  subdiv::Hierarchy h = subdiv::refine_topology(
      scheme, subdiv::build_level(mesh.vertex_count, mesh.face_offsets, mesh.face_vertices), options);
  once.topo = clock.lap();
  subdiv::StencilTable composed;
  std::unique_ptr<subdiv::Evaluator> evaluator;
  subdiv::RowPaths paths;  // counted by the evaluator from the first evaluation, the cold one, which reports
  if (job.tables) {
    subdiv::build_stencils(scheme, h, options);
    composed = h.stencils[0];
    for (int l = 1; l < job.level; ++l) composed = subdiv::compose(composed, h.stencils[size_t(l)]);
    h.stencils.clear();
  } else {
    options.evaluation.row_paths = &paths;
    evaluator = std::make_unique<subdiv::Evaluator>(scheme, h, options);
  }
  once.stencil = clock.lap();
  std::vector<double> values(size_t(h.levels.back().vertex_count) * 3);
  return repeat_cold_and_warm(job, [&](Timings& t, WorkerReport* report) {
    t = once;
    Stopwatch evaluation;
    if (job.tables)
      composed.apply(mesh.xyz, values, 3);
    else
      evaluator->evaluate(mesh.xyz, values, 3);
    t.apply = evaluation.lap();
    const std::uint64_t digest = digest_of(values);
    if (report) report_results(job, mesh, h, values, digest, paths, *report);
    return digest;
  });
}

}  // namespace

WorkerReport run_subdivkit(const Job& job, const Mesh& mesh) {
  // One TBB arena of the requested size for the whole worker, on top of the engine's own
  // `threads` option.
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, size_t(std::max(1, job.threads)));
  const auto scheme = subdiv::load_scheme(job.scheme);
  subdiv::RefineOptions options;
  options.levels = job.level;
  options.evaluation.use_row_plans = job.row_plans;
  options.evaluation.use_kernels = job.kernels;
  // As OpenSubdiv's default UniformOptions: the last level's faces only (full with --osd-topology full).
  options.faces_only_last_level = !job.osd_full_topology;
  if (job.update) return run_subdivkit_updates(job, mesh, *scheme, options);

  return repeat_cold_and_warm(job, [&](Timings& t, WorkerReport* report) {
    subdiv::RowPaths paths;  // counted in the cold repetition
    options.evaluation.row_paths = report ? &paths : nullptr;
    Stopwatch clock;
    subdiv::Level base = subdiv::build_level(mesh.vertex_count, mesh.face_offsets, mesh.face_vertices);
    t.setup = clock.lap();
    subdiv::Hierarchy h = subdiv::refine_topology(*scheme, std::move(base), options);
    t.topo = clock.lap();
    if (job.tables) {
      subdiv::build_stencils(*scheme, h, options);
      t.stencil = clock.lap();
    }
    // Level by level, keeping only the current and next positions (as the OSD side), in
    // buffers the step's parallel loops touch first (no zero-fill: on both sides).
    subdiv::ScratchVector<double> src, dst;
    for (int l = 0; l < job.level; ++l) {
      const std::span<const double> from = l == 0 ? std::span<const double>(mesh.xyz) : std::span<const double>(src);
      dst.resize(3 * size_t(h.levels[size_t(l) + 1].vertex_count));
      if (job.tables)
        h.stencils[size_t(l)].apply(from, dst, 3);
      else
        subdiv::step_values(*scheme, h, l, from, dst, 3, options);
      std::swap(src, dst);
      subdiv::ScratchVector<double>().swap(dst);
    }
    t.apply = clock.lap();
    const std::uint64_t digest = digest_of(src);
    if (report) report_results(job, mesh, h, src, digest, paths, *report);
    return digest;
  });
}

}  // namespace subdiv_bench
