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
};

}  // namespace subdiv
