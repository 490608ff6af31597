#pragma once
// Mesh file formats added at run time by libraries layered on io/: the engine library links
// no VTK, and SubdivKit's VTK file IO (framework/io/vtk, library subdiv_vtkio) registers
// .vtp and .vtk here when a program calls register_vtk_formats(). read_mesh and write_mesh
// then handle them like the built-in formats.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/io/mesh_data.h"

namespace subdiv {

// Reads `file` (already known to exist); throws subdiv::Error naming it.
using MeshFileReader = std::function<MeshData(const std::filesystem::path& file)>;
// Writes `mesh` (validated) to `file` atomically; throws subdiv::Error naming it.
using MeshFileWriter = std::function<void(const std::filesystem::path& file, const MeshData& mesh)>;

// `extension` with its dot, lower case (".vtp"). A later registration of the same extension
// replaces the earlier one.
void register_mesh_reader(std::string extension, MeshFileReader reader);
void register_mesh_writer(std::string extension, MeshFileWriter writer);

// The registered function, or null.
const MeshFileReader* registered_mesh_reader(std::string_view extension);
const MeshFileWriter* registered_mesh_writer(std::string_view extension);

std::vector<std::string> registered_input_extensions();
std::vector<std::string> registered_output_extensions();

}  // namespace subdiv
