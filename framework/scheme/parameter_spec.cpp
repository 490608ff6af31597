#include "framework/scheme/parameter_spec.h"

#include <fmt/format.h>

namespace subdiv {

std::string range_violation(const ParameterSpec& p, double value) {
  const bool below = p.has_minimum && (value < p.minimum || (p.minimum_exclusive && value == p.minimum));
  const bool above = p.has_maximum && (value > p.maximum || (p.maximum_exclusive && value == p.maximum));
  if (!below && !above && value == value) return {};
  return fmt::format("{} = {} is outside its range {}{}, {}{}", p.name, value, p.minimum_exclusive ? "(" : "[",
                     p.has_minimum ? fmt::format("{}", p.minimum) : "-inf",
                     p.has_maximum ? fmt::format("{}", p.maximum) : "inf", p.maximum_exclusive ? ")" : "]");
}

}  // namespace subdiv
