#pragma once
// Checks on a file the user names as input, before anything opens it: it must exist, be a
// regular file (a FIFO, a device or a symlink to /dev/zero would block or never end) and
// fit in the memory this process may still use. Every reader goes through here.
#include <filesystem>
#include <string>
#include <string_view>

namespace subdiv {

// Throws subdiv::Error "cannot open '<file>': <why>; <fix>". `what` names the kind of file
// expected ("mesh", "scheme", "feature") for the fix.
void check_input_file(const std::filesystem::path& file, std::string_view what);

// The whole file, after check_input_file; throws subdiv::Error on read errors.
std::string read_input_file(const std::filesystem::path& file, std::string_view what);

}  // namespace subdiv
