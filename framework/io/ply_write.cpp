// Binary little-endian PLY with double coordinates, so that a round trip is exact. Point
// and cell arrays are written as vertex and face properties (ply_properties.h): doubles as
// double, integer arrays as int, integer colours within 0..255 as uchar (what viewers expect).
#include <algorithm>
#include <cstdint>

#include "framework/io/binary_le.h"
#include "framework/io/ply_properties.h"
#include "framework/io/writers.h"

namespace subdiv::io_detail {

namespace {

int largest_face(const MeshData& mesh) {
  Index largest = 0;
  for (Index f = 0; f < mesh.face_count(); ++f)
    largest = std::max(largest, mesh.face_offsets[f + 1] - mesh.face_offsets[f]);
  return largest;
}

enum class Stored { Double, Int, UChar };

Stored stored_as(const DataArray& a) {
  if (!a.integer) return Stored::Double;
  const bool bytes = std::all_of(a.values.begin(), a.values.end(), [](double x) { return x >= 0 && x <= 255; });
  return a.role == ArrayRole::Color && bytes ? Stored::UChar : Stored::Int;
}

const char* type_name(Stored s) { return s == Stored::Double ? "double" : s == Stored::Int ? "int" : "uchar"; }

void declare(BufferedOutput& out, const std::vector<DataArray>& arrays,
             const std::vector<std::vector<std::string>>& names) {
  for (std::size_t k = 0; k < arrays.size(); ++k)
    for (const std::string& name : names[k]) out.print("property {} {}\n", type_name(stored_as(arrays[k])), name);
}

// Tuple i of every array, in declaration order.
void put_tuple(BufferedOutput& out, const std::vector<DataArray>& arrays, const std::vector<Stored>& kinds, std::size_t i) {
  for (std::size_t k = 0; k < arrays.size(); ++k) {
    const DataArray& a = arrays[k];
    for (int c = 0; c < a.components; ++c) {
      const double x = a.values[i * std::size_t(a.components) + std::size_t(c)];
      if (kinds[k] == Stored::Double) put_le(out, x);
      else if (kinds[k] == Stored::Int) put_le(out, std::int32_t(x));
      else put_le(out, std::uint8_t(x));
    }
  }
}

std::vector<Stored> kinds_of(const std::vector<DataArray>& arrays) {
  std::vector<Stored> kinds;
  for (const DataArray& a : arrays) kinds.push_back(stored_as(a));
  return kinds;
}

}  // namespace

void write_ply(const path& file, const path& shown, const MeshData& mesh, const ProgressCallback& progress) {
  // A one-byte face size is what most tools expect; larger polygons need a wider count.
  const bool small_faces = largest_face(mesh) <= 255;
  std::vector<std::string> notes;
  const auto point_names = writable_property_names(mesh.point_data, {"x", "y", "z"}, "point", notes);
  const auto cell_names = writable_property_names(mesh.cell_data, {"vertex_indices"}, "cell", notes);
  BufferedOutput out(file, shown);
  out.print("ply\nformat binary_little_endian 1.0\ncomment SubdivKit\n");
  for (const std::string& note : notes) out.print("comment {}\n", note);
  out.print("element vertex {}\nproperty double x\nproperty double y\nproperty double z\n", mesh.vertex_count());
  declare(out, mesh.point_data, point_names);
  out.print("element face {}\nproperty list {} int vertex_indices\n", mesh.face_count(), small_faces ? "uchar" : "int");
  declare(out, mesh.cell_data, cell_names);
  out.print("end_header\n");
  const std::vector<Stored> point_kinds = kinds_of(mesh.point_data), cell_kinds = kinds_of(mesh.cell_data);
  WriteProgress written(progress, std::size_t(mesh.vertex_count()) + std::size_t(mesh.face_count()));
  for (Index v = 0; v < mesh.vertex_count(); ++v, written.step()) {
    for (int c = 0; c < 3; ++c) put_le(out, mesh.positions[3 * std::size_t(v) + std::size_t(c)]);
    put_tuple(out, mesh.point_data, point_kinds, std::size_t(v));
  }
  for (Index f = 0; f < mesh.face_count(); ++f, written.step()) {
    const Index size = mesh.face_offsets[f + 1] - mesh.face_offsets[f];
    if (small_faces) put_le(out, std::uint8_t(size));
    else put_le(out, std::int32_t(size));
    for (Index k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
      put_le(out, std::int32_t(mesh.face_vertices[k]));
    put_tuple(out, mesh.cell_data, cell_kinds, std::size_t(f));
  }
  out.close();
  written.finish();
}

}  // namespace subdiv::io_detail
