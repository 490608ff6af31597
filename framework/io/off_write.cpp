// ASCII OFF: positions and polygons (OFF has no polylines or tags), with Geomview's
// per-vertex extras when the mesh has them: a normal (N), a colour (C), texture
// coordinates (ST), in that order after x y z; a face colour after the face's indices.
#include "framework/io/writers.h"
#include "framework/util/buffered_output.h"

namespace subdiv::io_detail {
namespace {

const DataArray* with_role(const std::vector<DataArray>& arrays, ArrayRole role, int min_components, int max_components) {
  for (const DataArray& a : arrays)
    if (a.role == role && a.components >= min_components && a.components <= max_components) return &a;
  return nullptr;
}

void put_tuple(BufferedOutput& out, const DataArray* a, std::size_t i) {
  if (!a) return;
  for (int c = 0; c < a->components; ++c) out.print(" {}", a->values[i * std::size_t(a->components) + std::size_t(c)]);
}

}  // namespace

void write_off(const path& file, const path& shown, const MeshData& mesh, const ProgressCallback& progress) {
  const DataArray* normal = with_role(mesh.point_data, ArrayRole::Normals, 3, 3);
  const DataArray* colour = with_role(mesh.point_data, ArrayRole::Color, 3, 4);
  const DataArray* uv = with_role(mesh.point_data, ArrayRole::TextureCoordinates, 2, 2);
  const DataArray* face_colour = with_role(mesh.cell_data, ArrayRole::Color, 3, 4);
  BufferedOutput out(file, shown);
  // The edge count is optional information that readers ignore; 0 is the usual value.
  out.print("{}{}{}OFF\n{} {} 0\n", uv ? "ST" : "", colour ? "C" : "", normal ? "N" : "", mesh.vertex_count(),
            mesh.face_count());
  const std::vector<double>& p = mesh.positions;
  WriteProgress written(progress, std::size_t(mesh.vertex_count()) + std::size_t(mesh.face_count()));
  for (std::size_t v = 0; v < std::size_t(mesh.vertex_count()); ++v, written.step()) {
    out.print("{} {} {}", p[3 * v], p[3 * v + 1], p[3 * v + 2]);
    put_tuple(out, normal, v);
    put_tuple(out, colour, v);
    put_tuple(out, uv, v);
    out.print("\n");
  }
  for (Index f = 0; f < mesh.face_count(); ++f, written.step()) {
    out.print("{}", mesh.face_offsets[f + 1] - mesh.face_offsets[f]);
    for (Index k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
      out.print(" {}", mesh.face_vertices[k]);
    put_tuple(out, face_colour, std::size_t(f));
    out.print("\n");
  }
  out.close();
  written.finish();
}

}  // namespace subdiv::io_detail
