#pragma once
// Reading .vtp and .vtk polygonal data with VTK. Internal to io/vtk: programs call
// register_vtk_formats() and then read_mesh.
#include <filesystem>

#include "framework/io/mesh_data.h"

namespace subdiv::io_detail {

MeshData read_vtk_polydata(const std::filesystem::path& file);  // .vtp, .vtk

}  // namespace subdiv::io_detail
