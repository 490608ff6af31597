#pragma once
// SubdivKit's VTK file IO (library subdiv_vtkio, target SubdivKit::vtkio): call once, before
// read_mesh or write_mesh see a VTK file name. Reads .vtp and legacy .vtk polygonal data;
// writes .vtp and .pvd (io/vtk/vtk_output.h). Safe to call more than once.
namespace subdiv {

void register_vtk_formats();

}  // namespace subdiv
