#include "framework/util/decimal_number.h"

#include <charconv>
#include <limits>

namespace subdiv {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Whether a number from_chars found out of range lies below double's range rather than
// above it: the power of ten of its first nonzero digit, plus its exponent, is negative.
// The mantissa counts as well as the exponent's sign: 0.(500 zeros)1e100 underflows.
bool below_range(std::string_view t) {
  constexpr long long kFar = 1LL << 50;  // beyond any exponent that matters; no overflow
  size_t i = 0;
  if (i < t.size() && t[i] == '-') ++i;
  long long digits_before_point = 0, first_nonzero = -1, index = 0;
  bool after_point = false;
  for (; i < t.size() && (is_digit(t[i]) || t[i] == '.'); ++i) {
    if (t[i] == '.') {
      after_point = true;
      continue;
    }
    if (t[i] != '0' && first_nonzero < 0) first_nonzero = index;
    if (!after_point) ++digits_before_point;
    ++index;
  }
  if (first_nonzero < 0) return true;  // zero: never out of range, but never above it
  long long exponent = 0;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    const bool negative = i < t.size() && t[i] == '-';
    if (i < t.size() && (t[i] == '-' || t[i] == '+')) ++i;
    for (; i < t.size() && is_digit(t[i]); ++i) exponent = exponent < kFar ? exponent * 10 + (t[i] - '0') : kFar;
    if (negative) exponent = -exponent;
  }
  return digits_before_point - 1 - first_nonzero + exponent < 0;
}

}  // namespace

DecimalParse parse_decimal(std::string_view text, double& value) {
  text.remove_prefix(leading_plus(text));
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ptr != end || (ec != std::errc() && ec != std::errc::result_out_of_range))
    return DecimalParse::not_a_number;
  if (ec == std::errc()) return DecimalParse::ok;
  const bool negative = text[0] == '-';
  if (below_range(text)) {
    value = negative ? -0.0 : 0.0;
    return DecimalParse::ok;
  }
  value = negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  return DecimalParse::overflow;
}

}  // namespace subdiv
