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
    // Which of two values the user meant is theirs to say, not the order of the options.
    const std::string name = p.substr(0, eq);
    if (const auto seen = out.find(name); seen != out.end())
      throw Error(fmt::format("{} {} is given twice ({} and {}); give it once", option, subdiv::quoted(name),
                              subdiv::quoted(name + "=" + seen->second), subdiv::quoted(p)));
    out[name] = p.substr(eq + 1);
  }
  return out;
}

}  // namespace subdiv
