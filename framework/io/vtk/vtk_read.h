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

}  // namespace subdiv::io_detail
