#pragma once
// The individual readers behind read_mesh. Each returns the mesh exactly as the file
// orders it and throws subdiv::Error naming the file (and line, for text formats).
// Internal to io/: call read_mesh instead.
#include <filesystem>

#include "framework/io/mesh_data.h"

namespace subdiv::io_detail {

MeshData read_obj(const std::filesystem::path& file);
// The OBJ reader without its parallel fast path: the reference the fast path must match (tests).
MeshData read_obj_line_by_line(const std::filesystem::path& file);
MeshData read_off(const std::filesystem::path& file);
MeshData read_ply(const std::filesystem::path& file);
MeshData read_with_openmesh(const std::filesystem::path& file);  // .stl, .om

}  // namespace subdiv::io_detail
