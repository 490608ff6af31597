#pragma once
// How far a uniform level is from the limit surface (`subdiv evaluate --level-distance L`):
// every vertex of uniform level L against the exact limit at its own (face, u, v) (Bfr's
// parameterisation: the vertices of level L sit at the parameters i / 2^L of their base face
// for binary splits), written as the limit surface sampled at those parameters, coloured
// by the distance.
#include <string>

#include "framework/io/mesh_data.h"
#include "framework/pipeline/evaluate_request.h"

namespace subdiv {

struct LevelDistance {
  MeshData mesh;  // level L's faces, its vertices moved onto the limit; point array level_distance
  int level = 0;
  double largest = 0, mean = 0;
  Index largest_vertex = kNone;
  Index vertices = 0;
};

// Level L (0..12) of the request's mesh and scheme (as subdiv refine -l L makes it: found
// here with feature-adaptive refinement split everywhere, which carries each vertex's
// (face, u, v)), its vertices put on the limit surface, with the point arrays
// level_distance (|level-L vertex - limit point|) and Normals (the unit limit normal; at an
// extraordinary vertex its limit from a face, as limit_normal gives it; (0, 0, 0) where the
// surface has none, which the mesh's `warnings` then say) and the cell array base_face. Throws subdiv::Error as
// refine_adaptive_request and prepare_evaluation do (naming the mesh and the scheme).
LevelDistance level_distance(const EvaluateRequest& request, int level);

// "uniform level L against the exact limit: largest distance X (vertex V), mean Y over N vertices".
std::string level_distance_summary(const LevelDistance& d);

}  // namespace subdiv
