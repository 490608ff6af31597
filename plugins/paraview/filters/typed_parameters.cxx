#include "typed_parameters.h"

namespace subdiv::paraview {

bool TypedParameters::set(const std::string& key, const std::string& value) {
  const auto colon = key.find(':');
  std::string& slot = values_[key.substr(0, colon)][colon == std::string::npos ? "" : key.substr(colon + 1)];
  if (slot == value) return false;
  slot = value;
  return true;
}

std::string TypedParameters::words_for(const std::string& scheme) const {
  std::string words;
  if (const auto it = values_.find(scheme); it != values_.end())
    for (const auto& [name, value] : it->second) words += name + "=" + value + " ";
  return words;
}

}  // namespace subdiv::paraview
