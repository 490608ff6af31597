#include "framework/util/json_text_check.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <map>
#include <vector>

#include "framework/util/error.h"
#include "framework/util/short_text.h"

namespace subdiv {
namespace {

// Line and column (1-based) of byte `at`.
struct Place {
  std::size_t line = 1, column = 1;
};

Place place_of(std::string_view text, std::size_t at) {
  Place p;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) {
    if (text[i] == '\n') ++p.line, p.column = 1;
    else ++p.column;
  }
  return p;
}

[[noreturn]] void fail(std::string_view text, std::size_t at, const std::string& label, const std::string& problem) {
  const Place p = place_of(text, at);
  throw Error(fmt::format("{}:{}:{}: {}", label, p.line, p.column, problem));
}

bool is_number_char(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// The fix for the usual slips at the character the parser stopped at (0-based `at`); empty
// when it is none of them.
std::string syntax_fix(std::string_view text, std::size_t at) {
  if (at >= text.size()) return {};
  const char c = text[at];
  if (c == '}' || c == ']') {
    std::size_t before = at;
    while (before > 0 && std::isspace(static_cast<unsigned char>(text[before - 1]))) --before;
    if (before == 0 || text[before - 1] != ',') return {};
    const Place comma = place_of(text, before - 1);
    return fmt::format("; the comma at line {}, column {} follows the last {}, and JSON allows none there: remove it",
                       comma.line, comma.column, c == '}' ? "member of the object" : "element of the array");
  }
  if (c == '/' || c == '#') return "; JSON has no comments: remove it (a note may go into \"description\")";
  if (c == '\'') return "; JSON strings take double quotes (\"...\"), not single ones";
  return {};
}

}  // namespace

std::string json_syntax_error(std::string_view text, const std::string& label, std::size_t byte, std::string what,
                              const std::string& in_what) {
  const std::size_t at = byte > 0 ? byte - 1 : 0;
  const Place p = place_of(text, at);
  // nlohmann's text repeats the place ("[json.exception.parse_error.101] parse error at line 2,
  // column 29: ..."); keep the rest.
  if (const auto pos = what.find("parse error"); pos != std::string::npos) what = what.substr(pos);
  if (const auto pos = what.find(": "); what.rfind("parse error", 0) == 0 && pos != std::string::npos)
    what = what.substr(pos + 2);
  return fmt::format("{}:{}:{}: malformed JSON{}: {}{}", label, p.line, p.column, in_what, what, syntax_fix(text, at));
}

void check_json_text(std::string_view text, const std::string& label) {
  // nlohmann stops at a NUL byte and takes what came before as the whole file.
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
    fail(text, nul, label, "a NUL byte; JSON text holds none, so the file is damaged or not text");
  // Per open object or array: the keys seen so far (an object's) and where each began.
  // nlohmann keeps the last of two equal keys, so the first one would be ignored silently.
  struct Open {
    bool object = false, expect_key = false;
    std::map<std::string_view, std::size_t> keys;
  };
  std::vector<Open> open;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {  // skip the string, escapes included
      const std::size_t start = i;
      for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
      if (!open.empty() && open.back().object && open.back().expect_key) {
        open.back().expect_key = false;
        const std::string_view key = text.substr(start + 1, std::min(i, text.size()) - start - 1);
        if (const auto [first, fresh] = open.back().keys.emplace(key, start); !fresh) {
          const Place p = place_of(text, first->second);
          fail(text, start, label,
               fmt::format("the key \"{}\" appears twice in one object (first at line {}, column {}); a JSON "
                           "reader keeps only one of them: remove the other",
                           shortened(std::string(key), 40), p.line, p.column));
        }
      }
      continue;
    }
    if (c == '[' || c == '{') {
      if (open.size() >= std::size_t(kMaxJsonDepth))
        fail(text, i, label,
             fmt::format("JSON nested deeper than {} levels; no scheme or feature file needs that many, so the "
                         "file is damaged or not meant for SubdivKit",
                         kMaxJsonDepth));
      open.push_back({c == '{', c == '{', {}});
    } else if (c == ']' || c == '}') {
      if (!open.empty()) open.pop_back();  // unbalanced brackets are the parser's to report
    } else if (c == ',') {
      if (!open.empty() && open.back().object) open.back().expect_key = true;
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i;
      while (end < text.size() && is_number_char(text[end])) ++end;
      const std::string number(text.substr(i, end - i));
      // strtod gives +-HUGE_VAL exactly when the value is beyond double's range.
      const double value = std::strtod(number.c_str(), nullptr);
      if (std::isinf(value))
        fail(text, i, label,
             fmt::format("the number {} is out of range: numbers must lie within +-1.8e308 (a double); "
                         "write a smaller value",
                         shortened(number, 40)));
      i = end - 1;
    }
  }
}

}  // namespace subdiv
