#include "framework/pipeline/array_selection.h"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sstream>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

const std::vector<std::string>& output_array_names() {
  static const std::vector<std::string> names = {"origin",      "valence",   "level",     "vertex_class",
                                                 "corner_sharpness", "parent_face", "base_face", "sharpness",
                                                 "cell_kind"};
  return names;
}

const std::vector<std::string>& default_array_names() {
  static const std::vector<std::string> names = {"base_face", "cell_kind", "sharpness", "corner_sharpness"};
  return names;
}

ArraySelection ArraySelection::all() {
  ArraySelection s;
  s.names_.insert(output_array_names().begin(), output_array_names().end());
  return s;
}

ArraySelection ArraySelection::defaults() {
  ArraySelection s;
  s.names_.insert(default_array_names().begin(), default_array_names().end());
  return s;
}

ArraySelection ArraySelection::parse(const std::string& text) {
  const std::string valid = fmt::format("{}, or default, all, none", fmt::join(output_array_names(), ", "));
  if (text == "none") return {};
  ArraySelection s;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    if (item == "all") s = all();
    else if (item == "default") s.names_.insert(default_array_names().begin(), default_array_names().end());
    else if (item == "none") throw Error(fmt::format("arrays {}: 'none' stands alone (no array at all)", subdiv::quoted(text)));
    else if (std::find(output_array_names().begin(), output_array_names().end(), item) != output_array_names().end())
      s.names_.insert(item);
    else
      throw Error(fmt::format("arrays {}: unknown array {}; give a comma list of {}", subdiv::quoted(text), subdiv::quoted(item), valid));
  }
  if (text.empty() || text.back() == ',')
    throw Error(fmt::format("arrays {}: an empty name; give a comma list of {}", subdiv::quoted(text), valid));
  return s;
}

}  // namespace subdiv
