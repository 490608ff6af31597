#include "framework/pipeline/limit_mesh.h"

#include <fmt/format.h>

#include "framework/limit/tessellation.h"
#include "framework/limit/unit_normal.h"
#include "framework/pipeline/phase_progress.h"
#include "framework/util/memory_limit.h"

namespace subdiv {
namespace {

DataArray index_array(const char* name, const std::vector<Index>& indices) {
  DataArray a{name, 1, {}, true};
  a.values.assign(indices.begin(), indices.end());
  return a;
}

// Channel c of the mesh's face-varying data on the tessellation: the same grid laid over
// the channel's value mesh numbers its values (shared across an edge exactly where the
// channel is continuous there, split at its seams), and each is the channel's limit at its
// (face, u, v).
FaceVaryingArray face_varying_samples(const PreparedEvaluation& prepared, size_t c, int segments) {
  const FaceVaryingSurface& channel = prepared.face_varying[c];
  const LimitSurface& surface = *prepared.surface;
  const Tessellation grid = tessellation_grid(channel.level, surface.base(), surface.triangles(), segments);
  EvaluatedPoints values = evaluate_face_varying(prepared, c, grid.uv_face, grid.uv, 0);
  return {channel.name, channel.components, std::move(values.position), grid.face_vertices, channel.role};
}

// The samples and the mesh they make, once they are known to fit.
MeshData sample(const PreparedEvaluation& prepared, int segments) {
  Tessellation t =
      naming_the_mesh(prepared, [&] {
        return tessellate(*prepared.surface, segments, limit_sampler(prepared), negligible_tangent(prepared.mesh.positions));
      });
  MeshData m;
  if (std::string w = zero_normals_warning(t.normals, t.uv_face, t.uv); !w.empty()) m.warnings.push_back(std::move(w));
  for (size_t c = 0; c < prepared.face_varying.size(); ++c)
    m.face_varying.push_back(face_varying_samples(prepared, c, segments));
  m.point_data = {DataArray{"Normals", 3, std::move(t.normals), false, ArrayRole::Normals},
                  index_array("base_face", t.uv_face), DataArray{"uv", 2, std::move(t.uv), false}};
  m.cell_data = {index_array("base_face", t.base_face)};
  m.positions = std::move(t.positions);
  m.face_offsets.assign(t.face_offsets.begin(), t.face_offsets.end());
  m.face_vertices.assign(t.face_vertices.begin(), t.face_vertices.end());
  return m;
}

}  // namespace

MeshData sampled_limit_mesh(const PreparedEvaluation& prepared, int segments,
                            const std::function<void(const std::string&)>& say,
                            const std::function<void(double)>& fraction) {
  // The channels' grids too are counted before any sample, not one grid at a time.
  check_samples_fit(prepared.surface->base(), prepared.surface->triangles(), segments, prepared.face_varying.size());
  const PhaseProgress bar(say, fraction, fmt::format("sampling the limit surface, {} x {} per face", segments, segments));
  return advising_when_out_of_memory(fmt::format("sampling the limit surface with {} segments per face edge", segments),
                                     kFewerSamplesAdvice, [&] { return sample(prepared, segments); });
}

}  // namespace subdiv
