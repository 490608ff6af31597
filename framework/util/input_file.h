#pragma once
// Checks on a file the user names as input, before anything opens it: it must exist, be a
// regular file (a FIFO, a device or a symlink to /dev/zero would block or never end) and
// fit in the memory this process may still use. Every reader goes through here.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace subdiv {

// Throws subdiv::Error "cannot open '<file>': <why>; <fix>". `what` names the kind of file
// expected ("mesh", "scheme", "feature") for the fix.
void check_input_file(const std::filesystem::path& file, std::string_view what);

// "a FIFO (named pipe)", "a character device", "a directory", ...: what a path that is not a
// regular file is, for messages (the output writers refuse such targets too).
const char* file_type_name(std::filesystem::file_type type);

// `text` without the UTF-8 byte-order mark (EF BB BF) that Windows editors and spreadsheets
// ("CSV UTF-8") put at the start of text files. Left in, the mark glues itself to the first
// word ("\xEF\xBB\xBFv", "\xEF\xBB\xBF0"), which is then skipped or refused in words that
// show nothing wrong. The text readers (OBJ, OFF, PLY, per-vertex values, vertex
// selections, the points CSV) take it off; the STL check names it.
std::string_view without_utf8_bom(std::string_view text);

// The whole file, after check_input_file; throws subdiv::Error on read errors. A file of
// more than `max_bytes` is refused with its size before a byte is read (scheme and feature
// files are small; a 1 GB sparse file was read whole before the first check).
std::string read_input_file(const std::filesystem::path& file, std::string_view what,
                            std::uintmax_t max_bytes = UINTMAX_MAX);

}  // namespace subdiv
