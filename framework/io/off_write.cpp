// ASCII OFF: positions and polygons only (OFF has no polylines or tags).
#include "framework/io/writers.h"
#include "framework/util/buffered_output.h"

namespace subdiv::io_detail {

void write_off(const path& file, const path& shown, const MeshData& mesh) {
  BufferedOutput out(file, shown);
  // The edge count is optional information that readers ignore; 0 is the usual value.
  out.print("OFF\n{} {} 0\n", mesh.vertex_count(), mesh.face_count());
  const std::vector<double>& p = mesh.positions;
  for (std::size_t i = 0; i < p.size(); i += 3) out.print("{} {} {}\n", p[i], p[i + 1], p[i + 2]);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    out.print("{}", mesh.face_offsets[f + 1] - mesh.face_offsets[f]);
    for (Index k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
      out.print(" {}", mesh.face_vertices[k]);
    out.print("\n");
  }
  out.close();
}

}  // namespace subdiv::io_detail
