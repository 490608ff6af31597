#pragma once
// Reading a mesh file into MeshData, with the file's vertex and face order kept exactly.
#include <filesystem>
#include <functional>

#include "framework/io/mesh_data.h"

namespace subdiv {

// Reads .obj (with 'l' polylines and 't crease' / 't corner' tags), .off, .ply, .stl,
// .om, .vtp and .vtk, chosen by the extension (any case). OBJ, OFF and PLY keep
// non-manifold faces as written so that the engine can name the problem; STL and OM go
// through OpenMesh, which cannot hold them, and STL is refused when OpenMesh had to split.
// VTK files give polygons as faces, lines as polylines, strips as triangles; files from
// write_vtp also give back their crease and corner tags.
//
// Throws subdiv::Error naming the file and, for text formats, the line: missing file,
// unknown extension, syntax errors, indices out of range, non-finite coordinates, faces
// with fewer than 3 vertices, invalid crease or corner tags.
// `progress`, when given, is told the share read, 0 to 1, a few hundred times at most (the
// text readers by bytes parsed; the others at the start and the end).
MeshData read_mesh(const std::filesystem::path& file, const std::function<void(double done)>& progress = {});

}  // namespace subdiv
