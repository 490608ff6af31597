#pragma once
// What "SubdivKit Limit" does once its input is a MeshData: its properties translated into
// the library's limit requests (framework/pipeline/evaluate_request.h, limit_mesh.h,
// adaptive_request.h), as `subdiv evaluate --samples N` and `--adaptive L` translate
// theirs, ending in the mesh those commands would write. VTK-free; vtkSubdivKitLimit converts.
#include <string>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/io/mesh_data.h"

namespace subdiv::paraview {

enum class LimitMode { Samples = 0, Adaptive = 1 };

struct LimitSettings {
  std::string scheme = "catmull-clark";  // a registered name or a .json path
  std::string parameters;                // "name=value ...", as --param
  FeatureOptions features;               // --boundary, --crease-method
  double feature_angle = -1;             // --feature-angle DEG; < 0: off
  int threads = 0;                       // 0: all cores
  LimitMode mode = LimitMode::Samples;
  int samples = 4;          // --samples N: N x N samples per quad face
  int adaptive_levels = 4;  // --adaptive L
  double tolerance = 0;     // --tolerance T (adaptive): also split faces farther than T from the limit
  bool limit_positions = true;  // --limit (adaptive): every point on the limit surface
  bool triangle_transitions = false;  // --transitions triangles (adaptive): no transition polygons
};

struct LimitMesh {
  MeshData mesh;                   // with the arrays the command line writes
  std::vector<std::string> notes;  // warnings and notes for ParaView's output window
};

// Throws subdiv::Error with the message `subdiv evaluate` would print, options named as the
// filter's properties; `source` names the input in it (the filter's name).
LimitMesh limit_mesh(const MeshData& mesh, const LimitSettings& settings, const std::string& source);

}  // namespace subdiv::paraview
