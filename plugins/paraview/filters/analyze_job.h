#pragma once
// What "SubdivKit Analyze" computes: `subdiv analyze`'s eigen-analysis of a surface scheme
// at extraordinary vertices (faces, for dual schemes) of one kind — interior, boundary
// (`--boundary`) or crease (`--crease`) — one valence after another.
#include <string>
#include <vector>

#include "framework/analysis/surface/surface_analysis.h"
#include "framework/features/feature_options.h"

namespace subdiv::paraview {

// Which vertices are analysed: the property "Vertices" (0, 1, 2).
enum class AnalysedVertices { Interior = 0, Boundary = 1, Crease = 2 };

struct AnalyzeRequest {
  std::string scheme = "catmull-clark";  // a registered name or a .json path
  std::string parameters;                // "name=value ...", as --param
  int min_valence = 3, max_valence = 12;
  BoundaryInterpolation boundary = BoundaryInterpolation::EdgesAndCorners;
  AnalysedVertices vertices = AnalysedVertices::Interior;
};

// One analysis per valence, with its characteristic map; throws subdiv::Error (the
// message `subdiv analyze` prints) for a scheme that does not load, a curve scheme, or an
// empty or out-of-range valence range (2..512). A scheme that fails the analysis at a valence is no error: the
// reason is in that analysis's verdict, as in `subdiv analyze`'s table.
std::vector<SurfaceAnalysis> analyze_valences(const AnalyzeRequest& request, const std::string& source);

}  // namespace subdiv::paraview
