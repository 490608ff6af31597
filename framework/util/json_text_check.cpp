#include "framework/util/json_text_check.h"

#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

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

}  // namespace

void check_json_text(std::string_view text, const std::string& label) {
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {  // skip the string, escapes included
      for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
      continue;
    }
    if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        fail(text, i, label,
             fmt::format("JSON nested deeper than {} levels; no scheme or feature file needs that many, so the "
                         "file is damaged or not meant for SubdivKit",
                         kMaxJsonDepth));
    } else if (c == ']' || c == '}') {
      --depth;  // unbalanced brackets are the parser's to report
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
