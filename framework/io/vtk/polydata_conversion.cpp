#include "framework/io/vtk/polydata_conversion.h"

#include <filesystem>
#include <string>

#include <vtkPolyData.h>

#include "framework/io/vtk/vtk_polydata.h"
#include "framework/io/vtk/vtk_read.h"

namespace subdiv {

MeshData mesh_from_polydata(vtkPolyData& poly, std::string_view source) {
  return io_detail::polydata_to_mesh_data(poly, std::filesystem::path(std::string(source)));
}

vtkSmartPointer<vtkPolyData> polydata_from_level(const OutputLevel& level, std::string_view source) {
  io_detail::check_output_level(level, source);
  return io_detail::make_polydata(level);
}

}  // namespace subdiv
