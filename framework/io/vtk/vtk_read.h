#pragma once
// Reading .vtp and .vtk polygonal data with VTK. Internal to io/vtk: programs call
// register_vtk_formats() and then read_mesh. The ParaView plugin (plugins/paraview) converts
// its input through polydata_conversion.h.
#include <filesystem>

#include "framework/io/mesh_data.h"

class vtkPolyData;

namespace subdiv::io_detail {

MeshData read_vtk_polydata(const std::filesystem::path& file);  // .vtp, .vtk

// Polygons and strips as faces, line cells as polylines (or crease edges where SubdivKit's
// cell_kind and sharpness arrays say so), corner_sharpness as corners, the other numeric
// point and cell arrays as the user's data. `file` names the data in messages.
MeshData polydata_to_mesh_data(vtkPolyData& poly, const std::filesystem::path& file);

// Arrays SubdivKit writes about its own refinement (vtk_polydata.cpp and the CLI's level
// output): read back as tags (cell_kind, sharpness, corner_sharpness) or recomputed by the
// next refinement, so they are not the user's data.
bool subdivkit_array(const char* name, bool point);

// VTK's reader and polydata_to_mesh_data, without the fast path (vtp_fast_read.h): tests and
// the fuzzer compare the two.
MeshData read_vtk_polydata_with_vtk(const std::filesystem::path& file);

}  // namespace subdiv::io_detail
