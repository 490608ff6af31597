#include "framework/pipeline/parameter_text.h"

#include <fmt/format.h>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

ParameterOverrides parse_parameter_assignments(const std::vector<std::string>& assignments, std::string_view option) {
  ParameterOverrides out;
  for (const auto& p : assignments) {
    const auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0) throw Error(fmt::format("{} {} must be written name=value", option, subdiv::quoted(p)));
    out[p.substr(0, eq)] = p.substr(eq + 1);
  }
  return out;
}

}  // namespace subdiv
