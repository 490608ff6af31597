#pragma once
// Scheme parameters written as text, "name=value", as the command line's --param, the
// ParaView filter's Parameters field and sequence specs give them.
#include <string>
#include <string_view>
#include <vector>

#include "framework/scheme/scheme_loader.h"

namespace subdiv {

// Each "name=value" as an override; throws subdiv::Error "<option> '<text>' must be written
// name=value" for one that is not, or for a name given twice, `option` spelled as the
// caller's user knows it.
ParameterOverrides parse_parameter_assignments(const std::vector<std::string>& assignments,
                                               std::string_view option = "parameter");

}  // namespace subdiv
