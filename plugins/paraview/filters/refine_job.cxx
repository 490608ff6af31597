#include "refine_job.h"

#include <fmt/format.h>
#include <memory>
#include <tbb/global_control.h>

#include "framework/engine/refiner.h"
#include "framework/io/feature_angle.h"
#include "framework/io/mesh_cleanup.h"
#include "framework/io/mesh_level.h"
#include "framework/primvar/level_data.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "level_output.h"
#include "limit_output.h"
#include "memory_guard.h"
#include "scheme_choice.h"

namespace subdiv::paraview {
namespace {

Level base_level(const MeshData& mesh, const RefineRequest& r, const std::string& source) {
  Level base = level_from_mesh(mesh, source);
  if (r.feature_angle >= 0) tag_edges_sharper_than(base, mesh.positions, r.feature_angle);
  return base;
}

// The user's point and cell arrays, level by level, refined as the library does
// (framework/primvar/level_data.h); normals are left out, as `subdiv refine` leaves them.
std::vector<LevelData> refine_data(const SchemeSequence& seq, const Hierarchy& h, const MeshData& mesh,
                                   const RefineOptions& options, const std::string& source) {
  std::vector<LevelData> data{{mesh.positions, carried_point_arrays(mesh.point_data), mesh.cell_data}};
  check_finite_arrays(data.front(), source);
  // Normals are left out without a note: most of ParaView's sources have them, and a
  // warning on every refinement would bury the ones that matter (docs/paraview.md says so).
  for (int l = 0; l < seq.total_levels; ++l) data.push_back(next_level_data(seq.runs, h, l, data.back(), options));
  return data;
}

}  // namespace

RefinedLevels refine_levels(const MeshData& input, const RefineRequest& r, const std::string& source) {
  std::unique_ptr<tbb::global_control> thread_limit;
  if (r.threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, r.threads);
  const SchemeSequence seq = load_scheme_sequence(r.scheme, r.levels, parameter_overrides(r.parameters));
  RefinedLevels out;
  MeshCleanup cleanup;
  const MeshData mesh = drop_unrefinable(input, cleanup);
  out.notes = cleanup.warnings(source);
  if (mesh.face_count() == 0)
    throw Error(fmt::format("{}: the input has no polygons to refine; give it a surface (e.g. Extract Surface)",
                            source));
  RefineOptions options;
  options.levels = seq.total_levels;
  options.threads = r.threads;
  options.features = r.features;
  Level base = base_level(mesh, r, source);
  // A level too many would take ParaView down with it: refused before any work, as `subdiv` does.
  cli::check_fits_in_memory(*seq.schemes.front(), base, seq.total_levels);
  Hierarchy h = refine_topology(seq.runs, std::move(base), options);
  out.notes.insert(out.notes.end(), h.warnings.begin(), h.warnings.end());
  std::vector<LevelData> data = refine_data(seq, h, mesh, options, source);
  std::vector<DataArray> limit_data;
  if (r.limit) {  // as --limit: the limit normals come along, as point data "normal"
    cli::LimitArrays limits = cli::limit_arrays(seq, h, options, data.back(), true);
    if (limits.result.approximate > 0)
      out.notes.push_back(fmt::format("Limit Positions: {} of {} positions approximated (point data limit_exact)",
                                      limits.result.approximate, limits.result.exact.size()));
    limit_data = std::move(limits.point_data);
  }
  out.levels = cli::describe_levels(h, std::move(data), options.features, limit_data, out.meshes);
  return out;
}

}  // namespace subdiv::paraview
