#pragma once
// A cheap check of a plugin file before dlopen sees it. dlopen maps the file and reads its
// headers and segments in place: a half-copied library (a copy in progress, a full disk)
// made it die with SIGBUS reading past the end of the file, and a FIFO made it block for
// ever. Internal to plugin/.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace subdiv {

// What is wrong with `bytes` as a shared library of this machine (ELF of this word size
// and byte order, a shared object, program and section headers and every segment and section
// within the bytes), or nothing when it passes.
std::optional<std::string> elf_problem(std::string_view bytes);

// The same for a file, which must be a regular file (not a FIFO, device or folder) and is
// read without blocking; nothing when it passes.
std::optional<std::string> plugin_file_problem(const std::filesystem::path& file);

}  // namespace subdiv
