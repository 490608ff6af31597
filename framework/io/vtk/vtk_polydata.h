#pragma once
// Turning an OutputLevel into a vtkPolyData and writing it as VTK XML. Internal to io/:
// shared by write_vtp and write_pvd.
#include <filesystem>
#include <string_view>

#include <vtkSmartPointer.h>

#include "framework/io/vtk/vtk_output.h"

class vtkPolyData;

namespace subdiv::io_detail {

// Checks the mesh and every array's name and length; throws subdiv::Error
// "<context>: <problem>".
void check_output_level(const OutputLevel& level, std::string_view context);

// Assumes check_output_level passed.
vtkSmartPointer<vtkPolyData> make_polydata(const OutputLevel& level);

// Binary, appended, zlib-compressed VTK XML into `file`; `shown` names it in messages.
void write_polydata_file(vtkPolyData& poly, const std::filesystem::path& file,
                         const std::filesystem::path& shown);

}  // namespace subdiv::io_detail
