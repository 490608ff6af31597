#pragma once
// A decimal number in text, read the same in every locale (std::from_chars), with what
// from_chars leaves undecided settled: a leading '+' (spreadsheets and some exporters write
// one) is taken, and a number too small for a double (1e-400) is 0 to double precision, as
// a subnormal such as 4e-320 is already close to it, while one too large (1e400) has no
// double near it and is reported as overflow.
#include <cstddef>
#include <string_view>

namespace subdiv {

enum class DecimalParse { ok, not_a_number, overflow };

// The whole of `text` (no spaces) as a double. "nan" and "inf" parse, as from_chars reads
// them, for the caller to refuse as non-finite. On underflow `value` is +0 or -0 and the
// result ok; on overflow `value` is +inf or -inf and the result overflow.
DecimalParse parse_decimal(std::string_view text, double& value);

// 1 when `text` starts with the '+' parse_decimal passes over (one that a sign does not
// follow: "+-1" is not a number), else 0; for parsers that share its rules (obj_fast_parse).
inline std::size_t leading_plus(std::string_view text) {
  return text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+' ? 1 : 0;
}

}  // namespace subdiv
