#include "typed_parameters.h"

#include <set>
#include <sstream>

namespace subdiv::paraview {
namespace {

// The names the "name=value" words of `text` assign.
std::set<std::string> assigned_names(const std::string& text) {
  std::istringstream words(text);
  std::set<std::string> names;
  for (std::string word; words >> word;)
    if (const auto eq = word.find('='); eq != std::string::npos) names.insert(word.substr(0, eq));
  return names;
}

}  // namespace

bool TypedParameters::set(const std::string& key, const std::string& value) {
  const auto colon = key.find(':');
  std::string& slot = values_[key.substr(0, colon)][colon == std::string::npos ? "" : key.substr(colon + 1)];
  if (slot == value) return false;
  slot = value;
  return true;
}

std::string TypedParameters::words_for(const std::string& scheme, const std::string& overriding) const {
  const std::set<std::string> overridden = assigned_names(overriding);
  std::string words;
  if (const auto it = values_.find(scheme); it != values_.end())
    for (const auto& [name, value] : it->second)
      if (!overridden.count(name)) words += name + "=" + value + " ";
  return words;
}

}  // namespace subdiv::paraview
