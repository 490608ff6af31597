#include "filter_input.h"

#include "framework/io/vtk/polydata_conversion.h"
#include "polydata_creases.h"

namespace subdiv::paraview {

MeshData filter_input_mesh(vtkPolyData& input, const std::string& crease_array, const std::string& source) {
  MeshData mesh = mesh_from_polydata(input, source);
  if (!crease_array.empty() && crease_array != "None") add_creases_from_cell_array(input, crease_array, mesh, source);
  return mesh;
}

FeatureOptions filter_features(int boundary_interpolation, int crease_method) {
  FeatureOptions features;
  features.boundary = boundary_interpolation == 1   ? BoundaryInterpolation::EdgesOnly
                      : boundary_interpolation == 2 ? BoundaryInterpolation::None
                                                    : BoundaryInterpolation::EdgesAndCorners;
  features.crease_method = crease_method == 1 ? CreaseMethod::Chaikin : CreaseMethod::Uniform;
  return features;
}

}  // namespace subdiv::paraview
