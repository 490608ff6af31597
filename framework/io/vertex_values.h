#pragma once
// Per-vertex values from a text file: a scheme parameter given per vertex (the scheme
// file's "per_vertex": true), one value per vertex of the input mesh, in vertex order.
#include <map>
#include <string>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

// White space or commas between values, '#' comments. Throws subdiv::Error naming the file
// and line of a value that is not a finite number, or the count when it is not one per
// vertex. Ranges are checked by the engine.
std::vector<double> read_vertex_values(const std::string& file, const std::string& name, Index vertex_count);

// Every file of `files` (parameter name -> file): name -> values (engine/refiner.h's
// VertexParameters).
std::map<std::string, std::vector<double>> read_vertex_parameter_files(const std::map<std::string, std::string>& files, Index vertex_count);

}  // namespace subdiv
