#pragma once
// Checks on JSON text before nlohmann parses it, for what its parser does not report as a
// parse error: nesting so deep that code walking the value recursively (dump(), copies,
// comparisons) overflows the stack, and numbers beyond double's range, which nlohmann
// throws as out_of_range without a position. Both are reported at their line and column.
#include <string>
#include <string_view>

namespace subdiv {

// No scheme or feature file needs more than a handful of levels; this is generous.
constexpr int kMaxJsonDepth = 100;

// Throws subdiv::Error "<label>:<line>:<column>: ..." naming the problem and the fix.
// Anything else malformed is left for the parser to report.
void check_json_text(std::string_view text, const std::string& label);

// The parser's syntax error as "<label>:<line>:<column>: malformed JSON<in_what>: <what>", where
// `byte` is the 1-based offset nlohmann's parse_error gives and `what` its text (the place it
// repeats is cut). What first-day authors write most gets its fix: a comma after the last
// member of an object or array, a comment, a string in single quotes.
std::string json_syntax_error(std::string_view text, const std::string& label, std::size_t byte, std::string what,
                              const std::string& in_what = "");

}  // namespace subdiv
