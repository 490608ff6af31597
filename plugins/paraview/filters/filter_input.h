#pragma once
// What "SubdivKit Refine" and "SubdivKit Limit" read alike: the input polygons with the
// creases the Crease Array property asks for, and the shape properties (Boundary
// Interpolation, Crease Method drop-downs) as the library's options.
#include <string>

#include "framework/features/feature_options.h"
#include "framework/io/mesh_data.h"

class vtkPolyData;

namespace subdiv::paraview {

// The polygons of `input` (io's polydata conversion: SubdivKit's own crease arrays read as
// creases) plus those of `crease_array` ("" or "None": none); `source` names the filter in
// messages.
MeshData filter_input_mesh(vtkPolyData& input, const std::string& crease_array, const std::string& source);

// The drop-downs' entries (their order in SubdivKitFilters.xml.in: boundary 0
// edges-and-corners, 1 edges, 2 none; crease method 0 uniform, 1 chaikin).
FeatureOptions filter_features(int boundary_interpolation, int crease_method);

}  // namespace subdiv::paraview
