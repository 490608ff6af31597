#pragma once
// Writing MeshData to a mesh file, atomically: the target is either left as it was or
// replaced by the complete new file.
#include <filesystem>
#include <functional>

#include "framework/io/mesh_data.h"

namespace subdiv {

// Writes by extension (any case):
//   .obj  positions, faces, 'l' polylines, 't crease' and 't corner' tags (exact doubles)
//   .off  positions and faces (exact doubles)
//   .ply  binary little-endian, double positions and faces
//   .stl  binary, 32-bit floats, polygons split into triangle fans
//   .vtp / .pvd  ParaView output as write_vtp / write_pvd with one level, 0
// Formats without polylines or tags (OFF, PLY, STL) leave them out.
// Throws subdiv::Error, before creating any file, for an unknown extension, a missing
// directory or a mesh that validate_mesh_data refuses; on a write failure the partial
// temporary file is removed.
// `progress`, when given, is told the share written, 0 to 1, a few hundred times at most
// (OBJ, OFF, PLY, STL; formats registered by other libraries, e.g. VTK's, report their own way).
void write_mesh(const std::filesystem::path& file, const MeshData& mesh,
                const std::function<void(double done)>& progress = {});

// The refusal write_mesh gives for an extension it cannot write, for front-ends to give
// before any work.
void check_mesh_output_format(const std::filesystem::path& file);

}  // namespace subdiv
