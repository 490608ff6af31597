#include "framework/io/vtk/vtk_formats.h"

#include <span>

#include "framework/io/format_registry.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/io/vtk/vtk_read.h"

namespace subdiv {

void register_vtk_formats() {
  register_mesh_reader(".vtp", io_detail::read_vtk_polydata);
  register_mesh_reader(".vtk", io_detail::read_vtk_polydata);
  // write_vtp and write_pvd validate the mesh and write atomically themselves.
  // The mesh's point and cell arrays go into the file, as the other formats write them.
  register_mesh_writer(".vtp", [](const std::filesystem::path& file, const MeshData& mesh) {
    OutputLevel level{&mesh, 0, mesh.point_data, mesh.cell_data};
    write_vtp(file, level);
  });
  register_mesh_writer(".pvd", [](const std::filesystem::path& file, const MeshData& mesh) {
    OutputLevel level{&mesh, 0, mesh.point_data, mesh.cell_data};
    write_pvd(file, std::span(&level, 1));
  });
}

}  // namespace subdiv
