// subdiv-bench-meshlibs, SubdivKit's side: the library as a user calls it, with the
// shipped scheme file: build_level, refine_topology, then step_values level by level.
#include <memory>
#include <span>

#include "framework/engine/refiner.h"
#include "framework/rules/row_paths.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/topology/level.h"
#include "meshlibs_sides.h"

namespace subdiv_bench {

SideRun subdivkit_side(const SideRequest& request) {
  std::shared_ptr<const subdiv::Scheme> scheme = subdiv::load_scheme(request.scheme);
  subdiv::RefineOptions options;
  options.levels = request.level;
  options.faces_only_last_level = !request.last_level_full;
  return [scheme, options, level = request.level](const Mesh& mesh, Timings& t, Refined& out) mutable {
    subdiv::RowPaths paths;
    options.evaluation.row_paths = &paths;
    Stopwatch clock;
    subdiv::Level base = subdiv::build_level(mesh.vertex_count, mesh.face_offsets, mesh.face_vertices);
    t.setup = clock.lap();
    const subdiv::Hierarchy h = subdiv::refine_topology(*scheme, std::move(base), options);
    t.topo = clock.lap();
    std::vector<double> values;
    for (int l = 0; l < level; ++l) {
      const std::span<const double> from = l == 0 ? std::span<const double>(mesh.xyz) : std::span<const double>(values);
      values = subdiv::step_values(*scheme, h, l, from, 3, options);
    }
    t.apply = clock.lap();
    out.peak_rss_bytes = peak_rss_bytes();
    out.faces = h.levels[size_t(level)].face_count();
    out.xyz = std::move(values);
    out.kernel_points = paths.kernel, out.plan_points = paths.plan, out.generic_points = paths.generic;
    out.flat_points = paths.flat;
  };
}

}  // namespace subdiv_bench
