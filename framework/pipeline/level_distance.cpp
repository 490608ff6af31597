#include "framework/pipeline/level_distance.h"

#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "framework/limit/tessellation.h"
#include "framework/limit/unit_normal.h"
#include "framework/pipeline/adaptive_request.h"
#include "framework/pipeline/phase_progress.h"
#include "framework/util/error.h"

namespace subdiv {

LevelDistance level_distance(const EvaluateRequest& request, int level) {
  // Split wherever the surface differs from a bilinear patch at all: the uniform level.
  AdaptiveRequest uniform = adaptive_request_from(request, level, std::numeric_limits<double>::min(), false);
  uniform.uniform = true;
  AdaptiveResult refined = refine_adaptive_request(std::move(uniform));
  AdaptiveMesh& a = refined.mesh;
  if (Index(a.face_offsets.size()) - 1 != a.uniform_faces)
    throw Error(fmt::format("--level-distance {}: {} faces are flat to round-off, so the level could not be found "
                            "face by face ({} faces instead of {})",
                            level, request.mesh_name, a.face_offsets.size() - 1, a.uniform_faces));
  const PreparedEvaluation prepared = prepare_evaluation(request);
  const size_t V = a.positions.size() / 3;
  std::vector<Index> faces(V, kNone);
  std::vector<double> uv(2 * V, 0.0);
  for (Index f = 0; f + 1 < Index(a.face_offsets.size()); ++f)
    for (Index c = a.face_offsets[size_t(f)]; c < a.face_offsets[size_t(f) + 1]; ++c) {
      const size_t v = size_t(a.face_vertices[size_t(c)]);
      if (faces[v] != kNone) continue;
      faces[v] = a.base_face[size_t(f)];
      uv[2 * v] = a.corner_uv[size_t(c)][0];
      uv[2 * v + 1] = a.corner_uv[size_t(c)][1];
    }
  const PhaseProgress bar(request.progress, request.progress_fraction,
                          fmt::format("the limit at level {}'s {} vertices", level, V));
  const EvaluatedPoints limit = evaluate_limit_points(prepared, faces, uv, 1);
  LevelDistance d;
  d.level = level;
  d.vertices = Index(V);
  DataArray distance{"level_distance", 1, {}, false}, normals{"Normals", 3, {}, false, ArrayRole::Normals};
  // Where the derivatives do not exist (an extraordinary vertex of the level), the limit of
  // the normals towards it from its face, as the sampled surface's (tessellation.h).
  const SurfaceSample sample = limit_sampler(prepared);
  LimitSample at_vertex;
  const double negligible = negligible_tangent(prepared.mesh.positions);
  const auto normal_of = [&](size_t v) {
    if (std::isfinite(limit.du[3 * v])) return unit_normal({&limit.du[3 * v], 3}, {&limit.dv[3 * v], 3}, negligible);
    sample(faces[v], uv[2 * v], uv[2 * v + 1], at_vertex);
    return limit_normal(*prepared.surface, sample, at_vertex, faces[v], uv[2 * v], uv[2 * v + 1], negligible);
  };
  double sum = 0;
  for (size_t v = 0; v < V; ++v) {
    const double* x = &a.positions[3 * v];
    const double* y = &limit.position[3 * v];
    const double e = std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]);
    distance.values.push_back(e);
    sum += e;
    if (d.largest_vertex == kNone || e > d.largest) d.largest = e, d.largest_vertex = Index(v);
    for (double c : normal_of(v)) normals.values.push_back(c);
  }
  d.mean = V ? sum / double(V) : 0.0;
  a.positions = limit.position;
  d.mesh = adaptive_mesh_data(std::move(a));
  d.mesh.cell_data.erase(d.mesh.cell_data.begin());  // face_level: L everywhere
  if (std::string w = zero_normals_warning(normals.values, faces, uv); !w.empty()) d.mesh.warnings.push_back(std::move(w));
  d.mesh.point_data = {std::move(distance), std::move(normals)};
  return d;
}

std::string level_distance_summary(const LevelDistance& d) {
  return fmt::format("uniform level {} against the exact limit: largest distance {:.3e} (vertex {}), mean {:.3e} over "
                     "{} vertices",
                     d.level, d.largest, d.largest_vertex, d.mean, d.vertices);
}

}  // namespace subdiv
