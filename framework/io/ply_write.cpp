// Binary little-endian PLY with double coordinates, so that a round trip is exact.
#include <algorithm>
#include <cstdint>

#include "framework/io/binary_le.h"
#include "framework/io/writers.h"

namespace subdiv::io_detail {

namespace {

int largest_face(const MeshData& mesh) {
  Index largest = 0;
  for (Index f = 0; f < mesh.face_count(); ++f)
    largest = std::max(largest, mesh.face_offsets[f + 1] - mesh.face_offsets[f]);
  return largest;
}

}  // namespace

void write_ply(const path& file, const path& shown, const MeshData& mesh) {
  // A one-byte face size is what most tools expect; larger polygons need a wider count.
  const bool small_faces = largest_face(mesh) <= 255;
  BufferedOutput out(file, shown);
  out.print("ply\nformat binary_little_endian 1.0\ncomment SubdivKit\n"
            "element vertex {}\nproperty double x\nproperty double y\nproperty double z\n"
            "element face {}\nproperty list {} int vertex_indices\nend_header\n",
            mesh.vertex_count(), mesh.face_count(), small_faces ? "uchar" : "int");
  for (double c : mesh.positions) put_le(out, c);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Index size = mesh.face_offsets[f + 1] - mesh.face_offsets[f];
    if (small_faces) put_le(out, std::uint8_t(size));
    else put_le(out, std::int32_t(size));
    for (Index k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
      put_le(out, std::int32_t(mesh.face_vertices[k]));
  }
  out.close();
}

}  // namespace subdiv::io_detail
