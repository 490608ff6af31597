#pragma once
// What "SubdivKit Refine" does once its input is a MeshData: its properties translated into
// the library's pipeline request (framework/pipeline/refine_pipeline.h), as `subdiv refine`
// and Python's refine() translate theirs, ending in the levels `subdiv refine -o X.pvd`
// would write, with the same arrays. VTK-free; vtkSubdivKitRefine converts.
#include <functional>
#include <string>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/io/mesh_data.h"
#include "framework/io/output_level.h"

namespace subdiv::paraview {

struct RefineSettings {
  std::string scheme = "catmull-clark";  // a registered name or a .json path
  int levels = 2;
  std::string parameters;                // "name=value ...", as --param
  FeatureOptions features;               // --boundary, --crease-method
  double feature_angle = -1;             // --feature-angle DEG; < 0: off
  int threads = 0;                       // 0: all cores
  bool limit = false;                    // --limit: the finest level moved to the limit surface, with limit normals
  std::function<void(double done)> progress;  // the share of the levels' work done (ParaView's progress bar)
};

struct RefinedLevels {
  std::vector<MeshData> meshes;     // what `levels` point to
  std::vector<OutputLevel> levels;  // level 0 (the input) to the finest, with SubdivKit's arrays
  std::vector<std::string> notes;   // warnings (vertices dropped, limits approximated) for ParaView's output window
};

// Throws subdiv::Error with the message `subdiv refine` would print, options named as the
// filter's properties; `source` names the input in it (the filter's name).
RefinedLevels refine_levels(const MeshData& mesh, const RefineSettings& settings, const std::string& source);

}  // namespace subdiv::paraview
