#pragma once
// Options that several commands take (--param, --boundary, --crease-method), declared and
// parsed in one place so that their names, help and errors agree everywhere.
#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/features/feature_options.h"
#include "framework/pipeline/option_names.h"
#include "framework/util/option_spelling.h"
#include "framework/scheme/scheme_loader.h"

namespace subdiv::cli {

// The command line's spelling of the pipeline's option names (framework/pipeline/
// option_spelling.h), for its messages and notes: "{levels}" reads "--levels".
const OptionSpelling& cli_option_spelling();

// -p/--param name=value, repeatable.
CLI::Option* add_param_option(CLI::App* cmd, std::vector<std::string>& params);
// The --param values as overrides; throws subdiv::Error for one not written name=value.
ParameterOverrides parse_params(const std::vector<std::string>& params);

// --vertex-param name=FILE, repeatable: a scheme parameter declared "per_vertex", one value
// per vertex of the input mesh in FILE.
CLI::Option* add_vertex_param_option(CLI::App* cmd, std::vector<std::string>& specs);
// The --vertex-param values as parameter name -> file (framework/io/vertex_values.h reads
// them); throws subdiv::Error for one not written name=FILE or a name given twice.
std::map<std::string, std::string> vertex_param_files(const std::vector<std::string>& specs);

// Boundary interpolation by OpenSubdiv's names (pipeline/option_names.h): edges-and-corners,
// edges, none; read the value with boundary_from_name.
CLI::Option* add_boundary_option(CLI::App* cmd, const std::string& flag, std::string& value);

// --crease-method uniform|chaikin; read the value with crease_method_from_name.
CLI::Option* add_crease_method_option(CLI::App* cmd, std::string& value);
// --fvar-boundary: OpenSubdiv's face-varying linear-interpolation mode, with the modes'
// meanings after `what` (how the command uses face-varying data).
CLI::Option* add_fvar_boundary_option(CLI::App* cmd, std::string& value, const std::string& what);

// "name (meaning), name (meaning) ..." of an option's choices, for help texts.
template <class Value>
std::string choices_help(const std::vector<OptionChoice<Value>>& choices) {
  std::string text;
  for (const auto& c : choices) text += (text.empty() ? "" : ", ") + std::string(c.name) + " (" + c.meaning + ")";
  return text;
}

}  // namespace subdiv::cli
