#include "framework/io/ply_properties.h"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace {

struct Convention {
  std::string name;
  ArrayRole role;
  std::vector<std::string> components;
};

// Longest first, so that red green blue alpha wins over red green blue.
const std::vector<Convention>& conventions() {
  static const std::vector<Convention> list = {
      {"normal", ArrayRole::Normals, {"nx", "ny", "nz"}},
      {"color", ArrayRole::Color, {"red", "green", "blue", "alpha"}},
      {"color", ArrayRole::Color, {"red", "green", "blue"}},
      {"color", ArrayRole::Color, {"diffuse_red", "diffuse_green", "diffuse_blue"}},
      {"uv", ArrayRole::TextureCoordinates, {"s", "t"}},
      {"uv", ArrayRole::TextureCoordinates, {"texture_u", "texture_v"}},
      {"uv", ArrayRole::TextureCoordinates, {"u", "v"}},
  };
  return list;
}

int find(const std::vector<std::string>& names, const std::vector<bool>& used, const std::string& name) {
  for (size_t i = 0; i < names.size(); ++i)
    if (!used[i] && names[i] == name) return int(i);
  return -1;
}

// "temperature_0" -> ("temperature", 0); anything else -> ("", -1).
std::pair<std::string, int> component_suffix(const std::string& name) {
  const auto underscore = name.rfind('_');
  if (underscore == std::string::npos || underscore == 0 || underscore + 1 == name.size()) return {"", -1};
  const std::string digits = name.substr(underscore + 1);
  if (digits.size() > 3 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return {"", -1};
  return {name.substr(0, underscore), std::stoi(digits)};
}

}  // namespace

std::vector<PropertyGroup> group_properties(const std::vector<std::string>& names, const std::vector<bool>& skip) {
  std::vector<bool> used = skip;
  std::vector<PropertyGroup> groups;
  for (const Convention& c : conventions()) {
    PropertyGroup g{c.name, c.role, {}};
    for (const std::string& component : c.components) g.properties.push_back(find(names, used, component));
    if (std::find(g.properties.begin(), g.properties.end(), -1) != g.properties.end()) continue;
    for (int i : g.properties) used[size_t(i)] = true;
    groups.push_back(std::move(g));
  }
  for (size_t i = 0; i < names.size(); ++i) {
    if (used[i]) continue;
    const auto [base, index] = component_suffix(names[i]);
    PropertyGroup g{names[i], ArrayRole::Data, {int(i)}};
    if (index == 0) {
      // base_0 base_1 ... in order: one array.
      for (int k = 1;; ++k) {
        const int next = find(names, used, fmt::format("{}_{}", base, k));
        if (next < 0 || next == int(i)) break;
        g.properties.push_back(next);
      }
      if (g.properties.size() > 1) {
        g.name = base;
        for (int p : g.properties) used[size_t(p)] = true;
      }
    }
    used[i] = true;
    groups.push_back(std::move(g));
  }
  // In the file's order, as written.
  std::stable_sort(groups.begin(), groups.end(), [](const PropertyGroup& a, const PropertyGroup& b) {
    return *std::min_element(a.properties.begin(), a.properties.end()) <
           *std::min_element(b.properties.begin(), b.properties.end());
  });
  return groups;
}

std::vector<std::string> property_names(const DataArray& a) {
  for (const Convention& c : conventions())
    if (a.role == c.role && int(c.components.size()) == a.components) return c.components;
  if (a.components == 1) return {a.name};
  std::vector<std::string> names;
  for (int k = 0; k < a.components; ++k) names.push_back(fmt::format("{}_{}", a.name, k));
  return names;
}

namespace {

// Printable ASCII without spaces: what a PLY header word can be (the header is ASCII lines
// split at white space).
std::string header_word(const std::string& name) {
  std::string word;
  for (const char c : name) word += c > ' ' && c < 0x7f ? c : '_';
  return word.empty() ? std::string("array") : word;
}

// A name as a header comment can hold: printable ASCII, other bytes as \xNN (a line break
// or a lone carriage return would end the comment line and break the header).
std::string comment_text(const std::string& name) {
  std::string out;
  for (const char c : name.substr(0, 80)) {
    const auto b = static_cast<unsigned char>(c);
    out += b >= 0x20 && b < 0x7f ? std::string(1, c) : fmt::format("\\x{:02x}", unsigned(b));
  }
  return name.size() > 80 ? out + "..." : out;
}

std::vector<std::string> generic_names(const std::string& base, int components) {
  if (components == 1) return {base};
  std::vector<std::string> names;
  for (int k = 0; k < components; ++k) names.push_back(fmt::format("{}_{}", base, k));
  return names;
}

}  // namespace

std::vector<std::vector<std::string>> writable_property_names(const std::vector<DataArray>& arrays,
                                                              std::vector<std::string> taken, const char* what,
                                                              std::vector<std::string>& notes) {
  std::set<std::string> used(taken.begin(), taken.end());
  const auto free = [&](const std::vector<std::string>& names) {
    std::set<std::string> own;
    for (const std::string& n : names)
      if (used.count(n) || !own.insert(n).second) return false;
    return true;
  };
  std::vector<std::vector<std::string>> out;
  for (const DataArray& a : arrays) {
    std::vector<std::string> names = property_names(a);
    const std::string word = header_word(a.name);
    const bool conventional = names != generic_names(a.name, a.components);
    if (!conventional || !free(names)) {
      // A suffix that is not all digits, so that reading back does not take it for a component.
      std::string base = word;
      for (int k = 2; !free(names = generic_names(base, a.components)); ++k) base = fmt::format("{}_v{}", word, k);
      if (base != a.name)
        notes.push_back(fmt::format("{} array {} written as {}", what, subdiv::quoted(comment_text(a.name)), subdiv::quoted(base)));
    }
    used.insert(names.begin(), names.end());
    out.push_back(std::move(names));
  }
  return out;
}

}  // namespace subdiv::io_detail
