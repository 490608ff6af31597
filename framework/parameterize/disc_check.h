#pragma once
// Whether a mesh is a topological disc, the domain of Tutte's embedding: manifold, every
// vertex on some face, connected, one boundary loop, Euler characteristic V - E + F = 1.
// Internal to parameterize/.
#include <string>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

// The boundary loop of a disc, in the order that keeps its faces on the left (the faces'
// own winding), starting at its lowest vertex. Throws subdiv::Error naming `source` and
// what makes the mesh no disc.
std::vector<Index> disc_boundary_loop(const Level& level, const std::string& source);

}  // namespace subdiv
