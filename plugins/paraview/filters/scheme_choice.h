#pragma once
// The scheme the filters run: the drop-down of registered schemes, a .json file, and the
// parameters' text field.
#include <string>
#include <vector>

#include "framework/scheme/scheme_registry.h"

namespace subdiv::paraview {

// Every registered surface scheme by name: the built-in scheme files, SUBDIV_SCHEME_PATH's,
// and those of SubdivKit's plugins (SUBDIV_PLUGIN_PATH and the installed plugin folders,
// loaded the first time this is called, as `subdiv` loads them).
std::vector<std::string> surface_scheme_names();

// The name or path the filter refines with: the .json file when one is chosen, else the
// drop-down's scheme. Loads the plugins first, so a plugin's scheme is found by name.
std::string chosen_scheme(const std::string& name, const std::string& file);

// The "Parameters" field, "name=value name=value", as the overrides --param would give;
// throws subdiv::Error for a word not written name=value.
ParameterOverrides parameter_overrides(const std::string& text);

}  // namespace subdiv::paraview
