#pragma once
// Boundary vertices of a disc on a convex curve by arc length (tutte.h). Internal to
// parameterize/.
#include <span>
#include <string>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

// uv (two per vertex) for the loop's vertices on the unit circle, counter-clockwise.
void circle_layout(std::span<const Index> loop, std::span<const double> positions, std::vector<double>& uv);

// uv for the loop's vertices on the unit square [0, 1]^2, counter-clockwise from (0, 0),
// `corners` (four loop vertices) at its corners; returns the corners in loop order. Empty
// `corners`: the four sharpest turns. Throws subdiv::Error naming `source` for corners that
// are not four distinct boundary vertices.
std::vector<Index> square_layout(std::span<const Index> loop, std::span<const double> positions,
                                 std::vector<Index> corners, std::vector<double>& uv, const std::string& source);

}  // namespace subdiv
