#include "framework/util/option_spelling.h"

#include <algorithm>
#include <cctype>

namespace subdiv {
namespace {

bool is_placeholder_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::islower(static_cast<unsigned char>(c)) || c == '_';
  });
}

}  // namespace

std::string spell_options(std::string_view text, const OptionSpelling& spelling) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const size_t close = text[i] == '{' ? text.find('}', i) : std::string_view::npos;
    const std::string_view name = close == std::string_view::npos ? "" : text.substr(i + 1, close - i - 1);
    if (!is_placeholder_name(name)) {
      out += text[i++];
      continue;
    }
    if (const auto it = spelling.find(name); it != spelling.end()) {
      out += it->second;
    } else {
      std::string plain(name);
      std::replace(plain.begin(), plain.end(), '_', ' ');
      out += plain;
    }
    i = close + 1;
  }
  return out;
}

}  // namespace subdiv
