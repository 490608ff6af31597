// One reader per build: FUZZ_EXTENSION (".obj", ".off", ".ply", ".stl", ".vtp", ".vtk",
// ".om") picks the format read_mesh dispatches to. The input is written to a scratch
// file because the readers take paths (VTK and OpenMesh read files themselves).
//
// For OBJ also a differential check: the parallel fast path (io/obj_fast_parse.h), cut into
// any number of chunks, must give exactly the line-by-line reader's mesh, or decline (and
// leave the file to that reader): a mesh where the line-by-line reader refuses the file, or
// a different one, is silently accepted garbage. For VTP the same between the fast path
// (io/vtk/vtp_fast_read.h) and VTK's reader with its checks.
#include <cstring>
#include <string_view>

#include "fuzz_support.h"
#include "framework/io/mesh_read.h"
#include "framework/io/obj_fast_parse.h"
#include "framework/io/readers.h"
#include "framework/io/vtk/vtk_read.h"
#include "framework/io/vtk/vtp_fast_read.h"

namespace {

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same_arrays(const std::vector<subdiv::DataArray>& a, const std::vector<subdiv::DataArray>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].name != b[i].name || a[i].components != b[i].components || a[i].integer != b[i].integer ||
        a[i].role != b[i].role || !same_bits(a[i].values, b[i].values))
      return false;
  return true;
}

bool same_mesh(const subdiv::MeshData& a, const subdiv::MeshData& b) {
  if (!same_arrays(a.point_data, b.point_data) || !same_arrays(a.cell_data, b.cell_data)) return false;
  for (std::size_t i = 0; i < a.creases.size() && i < b.creases.size(); ++i)
    if (a.creases[i].v0 != b.creases[i].v0 || a.creases[i].v1 != b.creases[i].v1 ||
        std::memcmp(&a.creases[i].sharpness, &b.creases[i].sharpness, sizeof(double)) != 0)
      return false;
  for (std::size_t i = 0; i < a.corners.size() && i < b.corners.size(); ++i)
    if (a.corners[i].v != b.corners[i].v || std::memcmp(&a.corners[i].sharpness, &b.corners[i].sharpness, sizeof(double)) != 0)
      return false;
  if (!same_bits(a.positions, b.positions) || a.face_offsets != b.face_offsets || a.face_vertices != b.face_vertices ||
      a.line_offsets != b.line_offsets || a.line_vertices != b.line_vertices || a.holes != b.holes ||
      a.creases.size() != b.creases.size() || a.corners.size() != b.corners.size() ||
      a.point_data.size() != b.point_data.size() || a.cell_data.size() != b.cell_data.size() ||
      a.warnings != b.warnings || a.face_varying.size() != b.face_varying.size())
    return false;
  for (std::size_t i = 0; i < a.face_varying.size(); ++i) {
    const auto &x = a.face_varying[i], &y = b.face_varying[i];
    if (x.name != y.name || x.components != y.components || !same_bits(x.values, y.values) || x.indices != y.indices ||
        x.role != y.role)
      return false;
  }
  return true;
}

void check_obj_fast_path(const std::string& file, const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (std::size_t chunks : {std::size_t(1), std::size_t(3), std::size_t(7)}) {
    const std::optional<subdiv::MeshData> fast = subdiv::io_detail::parse_obj_fast(text, chunks);
    if (!fast) continue;
    subdiv::MeshData reference;
    try {
      reference = subdiv::io_detail::read_obj_line_by_line(file);
    } catch (const subdiv::Error& e) {
      std::fprintf(stderr, "fuzz: the OBJ fast path (%zu chunks) accepted a file the reader refuses: %s\n", chunks,
                   e.what());
      std::abort();
    }
    if (!same_mesh(*fast, reference)) {
      std::fprintf(stderr, "fuzz: the OBJ fast path (%zu chunks) read another mesh than the reader\n", chunks);
      std::abort();
    }
  }
}

void check_vtp_fast_path(const std::string& file) {
  const std::optional<subdiv::MeshData> fast = subdiv::io_detail::read_vtp_fast_file(file);
  if (!fast) return;
  subdiv::MeshData reference;
  try {
    reference = subdiv::io_detail::read_vtk_polydata_with_vtk(file);
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "fuzz: the VTP fast path accepted a file VTK's reader refuses: %s\n", e.what());
    std::abort();
  }
  if (!same_mesh(*fast, reference)) {
    std::fprintf(stderr, "fuzz: the VTP fast path read another mesh than VTK's reader\n");
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string file = subdiv::fuzz::scratch_file(FUZZ_EXTENSION);
  subdiv::fuzz::write_file(file, data, size);
  subdiv::fuzz::expect_only_subdiv_errors([&] { (void)subdiv::read_mesh(file); });
  if (std::string_view(FUZZ_EXTENSION) == ".obj") subdiv::fuzz::expect_only_subdiv_errors([&] { check_obj_fast_path(file, data, size); });
  if (std::string_view(FUZZ_EXTENSION) == ".vtp") subdiv::fuzz::expect_only_subdiv_errors([&] { check_vtp_fast_path(file); });
  return 0;
}
