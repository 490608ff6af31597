#pragma once
// Options that several commands take (--param, --boundary, --crease-method), declared and
// parsed in one place so that their names, help and errors agree everywhere.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/features/feature_options.h"
#include "framework/scheme/scheme_loader.h"

namespace subdiv::cli {

// -p/--param name=value, repeatable.
CLI::Option* add_param_option(CLI::App* cmd, std::vector<std::string>& params);
// The --param values as overrides; throws subdiv::Error for one not written name=value.
ParameterOverrides parse_params(const std::vector<std::string>& params);

// --vertex-param name=FILE, repeatable: a scheme parameter declared "per_vertex", one value
// per vertex of the input mesh in FILE.
CLI::Option* add_vertex_param_option(CLI::App* cmd, std::vector<std::string>& specs);
// Reads every file; throws subdiv::Error naming the file and line of a value that is not a
// number, or the count when it is not one per vertex. Ranges are checked by the engine.
VertexParameters read_vertex_params(const std::vector<std::string>& specs, Index vertex_count);
// One value per vertex, in vertex order: white space or commas between values, '#' comments.
std::vector<double> read_vertex_values(const std::string& file, const std::string& name, Index vertex_count);

// Boundary interpolation by OpenSubdiv's names: edges-and-corners, edges, none.
CLI::Option* add_boundary_option(CLI::App* cmd, const std::string& flag, std::string& value);
BoundaryInterpolation boundary_from_name(const std::string& name);

// --crease-method uniform|chaikin.
CLI::Option* add_crease_method_option(CLI::App* cmd, std::string& value);
CreaseMethod crease_method_from_name(const std::string& name);

}  // namespace subdiv::cli
