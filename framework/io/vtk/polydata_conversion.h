#pragma once
// SubdivKit's meshes and levels to and from vtkPolyData in memory, for programs that hold
// VTK data themselves (ParaView's filters, plugins/paraview). Part of libsubdiv_vtkio, but
// not installed: it includes VTK, and the installed headers include none (so that the
// package needs no VTK). The same conversions read_mesh and write_vtp make through files.
#include <string_view>

#include <vtkSmartPointer.h>

#include "framework/io/mesh_data.h"
#include "framework/io/vtk/vtk_output.h"

class vtkPolyData;

namespace subdiv {

// Polygons and strips as faces, line cells as polylines (or crease edges where SubdivKit's
// cell_kind and sharpness arrays say so), corner_sharpness as corners, the other numeric
// point and cell arrays as the user's data. `source` names the data in messages.
MeshData mesh_from_polydata(vtkPolyData& poly, std::string_view source);

// `level` as a polydata that owns its data, with the arrays write_vtp writes; the level and
// its arrays are checked first as write_vtp checks them (names, lengths), and a bad one
// throws subdiv::Error "<source>: <problem>".
vtkSmartPointer<vtkPolyData> polydata_from_level(const OutputLevel& level, std::string_view source);

}  // namespace subdiv
