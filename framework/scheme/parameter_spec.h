#pragma once
// A scheme parameter as the scheme file declares it: a number with a range, or a choice.
#include <string>
#include <vector>

namespace subdiv {

struct ParameterSpec {
  std::string name, description;
  bool is_choice = false;
  double value = 0, minimum = 0, maximum = 0;  // numeric parameters
  bool has_minimum = false, has_maximum = false;
  bool minimum_exclusive = false, maximum_exclusive = false;
  std::string choice;                           // choice parameters: the chosen value
  std::vector<std::string> choices;
  // "per_vertex": true — the value may be given per vertex (RefineOptions::vertex_parameters);
  // only vertex rules read it, at their own vertex (docs/scheme-format.md).
  bool per_vertex = false;
};

// Empty when `value` lies in the parameter's range; else "lambda = 2 is outside its range (0.35, 1]".
std::string range_violation(const ParameterSpec& p, double value);

}  // namespace subdiv
