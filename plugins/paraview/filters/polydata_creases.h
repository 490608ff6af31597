#pragma once
// Creases of the "SubdivKit Refine" filter's input from one of its cell arrays (the
// "Crease array" property), as OpenSubdiv's edge sharpness.
#include <string>

#include "framework/io/mesh_data.h"

class vtkPolyData;

namespace subdiv::paraview {

// Adds to mesh.creases (mesh: the polygons of `poly`, io's polydata_to_mesh_data):
//  - each segment of a line cell whose value is > 0, with that value as its sharpness
//    (>= 10: infinitely sharp; decays by one per level below that): edges drawn as lines;
//  - each edge between two polygons whose values differ, infinitely sharp: the borders of
//    parts or materials given as a cell array on the faces.
// Throws subdiv::Error naming the array when the input has no numeric cell array of that name.
void add_creases_from_cell_array(vtkPolyData& poly, const std::string& name, MeshData& mesh,
                                 const std::string& source);

}  // namespace subdiv::paraview
