#pragma once
// One refined level as it is shown or written: a mesh with the arrays that go with it.
// VTK-free, so that the pipeline can describe levels for any front-end; the .vtp and .pvd
// writers (io/vtk/vtk_output.h) take it.
#include <vector>

#include "framework/io/mesh_data.h"

namespace subdiv {

// One level to write. point_data has one tuple per vertex. cell_data has either one tuple
// per face, and line cells get -1 in every component, or one tuple per cell in the order
// faces, polylines, crease edges.
struct OutputLevel {
  const MeshData* mesh = nullptr;
  int level = 0;
  std::vector<DataArray> point_data;
  std::vector<DataArray> cell_data;
};

}  // namespace subdiv
