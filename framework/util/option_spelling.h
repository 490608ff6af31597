#pragma once
// Messages that name the request's options speak each front-end's language: the library
// writes an option as a placeholder, "{levels}", and each front-end spells it as its users
// know it ("--levels" on the command line, "levels=" in Python, "Levels" in ParaView).
// Unspelled, a placeholder reads as the request's own name ("levels").
#include <map>
#include <string>
#include <string_view>

#include "framework/util/error.h"

namespace subdiv {

// Placeholder name (without braces) -> the front-end's spelling.
using OptionSpelling = std::map<std::string, std::string, std::less<>>;

// `text` with every "{name}" replaced by spelling[name], or by the name with '_' read as a
// space when the spelling has none. Text without placeholders comes back unchanged.
std::string spell_options(std::string_view text, const OptionSpelling& spelling = {});

// An error about the request's options, its message written with placeholders; what() is
// the message spelled with the request's own names.
class OptionError : public Error {
public:
  explicit OptionError(std::string text) : Error(spell_options(text)), text_(std::move(text)) {}
  std::string spelled(const OptionSpelling& spelling) const { return spell_options(text_, spelling); }

private:
  std::string text_;
};

}  // namespace subdiv
