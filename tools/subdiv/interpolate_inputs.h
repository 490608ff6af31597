#pragma once
// Inputs shared by `subdiv interpolate` for surfaces (interpolate_command.cpp) and for
// polylines (curve_interpolate.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv::cli {

// --select: "all", a comma list of 0-based ids, or a file of ids ('#' comments).
std::vector<std::uint8_t> read_selection(const std::string& select, Index vertex_count);

// The diagonal of the bounding box of xyz positions (the default tolerance's scale).
double bounding_diagonal(const std::vector<double>& xyz);

}  // namespace subdiv::cli
