#include "framework/io/text_input.h"

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "framework/io/io_progress.h"
#include "framework/util/decimal_number.h"
#include "framework/util/error.h"
#include "framework/util/input_file.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace

void require_readable(const fs::path& file) { check_input_file(file, "mesh"); }

std::string read_whole_file(const fs::path& file) { return read_input_file(file, "mesh"); }

bool LineCursor::next(std::string_view& line) {
  if (rest_.empty()) return false;
  // "\n", "\r\n" and a lone "\r" (classic Mac OS files) all end a line.
  const size_t end = rest_.find_first_of("\r\n");
  line = rest_.substr(0, end);
  size_t next = end == std::string_view::npos ? rest_.size() : end + 1;
  if (end != std::string_view::npos && rest_[end] == '\r' && next < rest_.size() && rest_[next] == '\n') ++next;
  rest_ = rest_.substr(next);
  if ((++line_ & 1023) == 0) read_position(size_ - rest_.size());
  return true;
}

bool Tokens::next(std::string_view& token) {
  size_t begin = 0;
  while (begin < rest_.size() && is_space(rest_[begin])) ++begin;
  if (begin == rest_.size()) return false;
  size_t end = begin;
  while (end < rest_.size() && !is_space(rest_[end])) ++end;
  token = rest_.substr(begin, end - begin);
  rest_ = rest_.substr(end);
  return true;
}

bool Tokens::empty() { return trim(rest_).empty(); }

// Overflow becomes +-inf (reported later as non-finite), underflow 0 (decimal_number.h).
bool parse_double(std::string_view token, double& value) {
  return parse_decimal(token, value) != DecimalParse::not_a_number;
}

bool parse_integer(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end && !token.empty();
}

std::string_view strip_comment(std::string_view line) {
  return trim(line.substr(0, line.find('#')));
}

void fail_at(const fs::path& file, size_t line, std::string_view message) {
  throw Error(fmt::format("{}:{}: {}", escaped(file.string()), line, message));
}

}  // namespace subdiv::io_detail
