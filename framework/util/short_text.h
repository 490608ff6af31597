#pragma once
// Quoting user text in messages without echoing all of it: a 200 KB formula or a JSON
// value of a million elements would bury the message (and dumping a deep value costs
// memory and stack). Messages show the beginning and say how long the whole is.
#include <string>
#include <string_view>

namespace subdiv {

constexpr std::size_t kQuotedTextChars = 80;

// `text` itself when it has at most `max_chars` characters, else its first ones followed by
// "... (N characters)". Control characters (ANSI escapes, line breaks) become spaces so
// that a quote cannot redraw the terminal.
std::string shortened(std::string_view text, std::size_t max_chars = kQuotedTextChars);

}  // namespace subdiv
