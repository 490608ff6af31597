#pragma once
// What "SubdivKit Refine" does once its input is a MeshData: the steps of `subdiv refine`
// (tools/subdiv/refine_command.cpp) without files, ending in the levels `subdiv refine -o
// X.pvd` would write, with the same arrays. VTK-free; vtkSubdivKitRefine converts.
#include <string>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/io/mesh_data.h"
#include "framework/io/vtk/vtk_output.h"

namespace subdiv::paraview {

struct RefineRequest {
  std::string scheme = "catmull-clark";  // a registered name or a .json path
  int levels = 2;
  std::string parameters;                // "name=value ...", as --param
  FeatureOptions features;               // --boundary, --crease-method
  double feature_angle = -1;             // --feature-angle DEG; < 0: off
  int threads = 0;                       // 0: all cores
  bool limit = false;                    // --limit: the finest level moved to the limit surface, with limit normals
};

struct RefinedLevels {
  std::vector<MeshData> meshes;     // what `levels` point to
  std::vector<OutputLevel> levels;  // level 0 (the input) to the finest, with SubdivKit's arrays
  std::vector<std::string> notes;   // warnings (vertices dropped, limits approximated) for ParaView's output window
};

// Throws subdiv::Error with the message `subdiv refine` would print; `source` names the
// input in it (the filter's name).
RefinedLevels refine_levels(const MeshData& mesh, const RefineRequest& request, const std::string& source);

}  // namespace subdiv::paraview
