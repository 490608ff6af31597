#pragma once
// Shared pieces of the hand-written text readers (OBJ, OFF, ASCII PLY): loading a file,
// walking it line by line with line numbers, splitting lines into tokens, parsing numbers
// without locale surprises, and the "file:line: problem" error form.
// Internal to io/: not installed as API other layers should rely on.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "framework/util/input_file.h"

namespace subdiv::io_detail {

// Throws subdiv::Error "cannot open '<file>': no such file" (or: is a directory, a FIFO or
// a device, too large for memory, or the system's reason) unless `file` can be read
// (framework/util/input_file.h).
void require_readable(const std::filesystem::path& file);

// The whole file as bytes; throws like require_readable.
std::string read_whole_file(const std::filesystem::path& file);

// Lines of a text, numbered from 1, without their line ending ("\n", "\r\n" or a lone "\r").
// A byte-order mark at the start of the text is not part of the first line.
class LineCursor {
public:
  explicit LineCursor(std::string_view text) : rest_(without_utf8_bom(text)), size_(text.size()) {}
  bool next(std::string_view& line);
  std::size_t line_number() const { return line_; }
  // The text after the current line (binary PLY data follows its text header).
  std::string_view remaining() const { return rest_; }

private:
  std::string_view rest_;
  std::size_t size_;  // of the whole text: what is passed, for read progress (io_progress.h)
  std::size_t line_ = 0;
};

// Whitespace-separated tokens of one line.
class Tokens {
public:
  explicit Tokens(std::string_view line) : rest_(line) {}
  bool next(std::string_view& token);
  bool empty();  // no tokens left

private:
  std::string_view rest_;
};

// Whole-token parses; false on any trailing garbage. "nan" and "inf" parse, so that the
// caller can report them as non-finite values rather than as syntax errors.
bool parse_double(std::string_view token, double& value);
bool parse_integer(std::string_view token, long long& value);

// Strips a '#' comment and surrounding whitespace.
std::string_view strip_comment(std::string_view line);

// Throws subdiv::Error "<file>:<line>: <message>".
[[noreturn]] void fail_at(const std::filesystem::path& file, std::size_t line,
                          std::string_view message);

}  // namespace subdiv::io_detail
