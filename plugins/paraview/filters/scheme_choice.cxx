#include "scheme_choice.h"

#include <mutex>
#include <sstream>

#include "framework/pipeline/parameter_text.h"
#include "framework/plugin/plugin_loader.h"
#include "framework/scheme/scheme_registry.h"

namespace subdiv::paraview {
namespace {

void load_subdivkit_plugins_once() {
  static std::once_flag once;
  // A refused plugin is skipped with its reason kept (plugin_statuses); the others load.
  std::call_once(once, [] { load_plugins(PluginSearch{}); });
}

}  // namespace

std::vector<std::string> surface_scheme_names() {
  load_subdivkit_plugins_once();
  std::vector<std::string> names;
  for (const SchemeListing& s : list_schemes())
    if (s.kind == "surface") names.push_back(s.name);
  return names;
}

std::string chosen_scheme(const std::string& name, const std::string& file) {
  load_subdivkit_plugins_once();
  return file.empty() ? name : file;
}

ParameterOverrides parameter_overrides(const std::string& text) {
  std::istringstream words(text);
  std::vector<std::string> params;
  for (std::string word; words >> word;) params.push_back(word);
  return parse_parameter_assignments(params, "Parameters");
}

}  // namespace subdiv::paraview
