#pragma once
// Tutte's embedding of a topological disc: boundary vertices fixed on a convex curve, every
// interior vertex a convex combination of its neighbours, one sparse linear solve (Eigen).
//
// - Uniform weights: each interior vertex the average of its edge neighbours (Tutte 1963,
//   "How to draw a graph"); for a convex boundary the result is an embedding, every face
//   convex and none flipped.
// - Mean-value weights (Floater 2003, "Mean value coordinates", eq. 3.1): for neighbour j
//   of vertex i, w_ij = (tan(a/2) + tan(b/2)) / |x_j - x_i|, with a and b the angles at i
//   of the two face corners beside edge ij; positive, so the same theorem holds (Floater
//   2003 section 6), and the map reproduces planar meshes (linear precision), which keeps
//   shapes closer to the surface's.
// The boundary is laid out by arc length: on the unit circle x^2 + y^2 = 1, or on the unit
// square [0, 1]^2 with four boundary vertices at its corners (given, or the sharpest turns
// of the boundary).
#include <span>
#include <string>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

enum class BoundaryShape { Circle, Square };
enum class TutteWeights { Uniform, MeanValue };

struct TutteOptions {
  BoundaryShape boundary = BoundaryShape::Circle;
  TutteWeights weights = TutteWeights::Uniform;
  // Square: the four corner vertices (any order; they are taken in boundary order). Empty:
  // the four boundary vertices where the boundary turns most sharply.
  std::vector<Index> corners;
};

struct TutteResult {
  std::vector<double> uv;        // two per vertex
  std::vector<Index> boundary;   // the boundary loop, in the order laid out (counter-clockwise)
  std::vector<Index> corners;    // square: the corner vertices used, in boundary order
};

// Throws subdiv::Error, naming `source`, for a mesh that is not a disc (disc_check.h), bad
// corners, or a system the solver cannot factor.
TutteResult tutte_embedding(const Level& level, std::span<const double> positions, const TutteOptions& options,
                            const std::string& source);

// The weights of interior vertex v's edge neighbours (row of the linear system), in ring
// order, summing to 1: what tutte_embedding solves for, for tests and checks.
std::vector<std::pair<Index, double>> tutte_row(const Level& level, std::span<const double> positions, Index v,
                                                TutteWeights weights);

}  // namespace subdiv
