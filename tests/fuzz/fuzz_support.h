#pragma once
// Shared by the libFuzzer harnesses: the one rule every entry point must keep (a
// subdiv::Error is the only acceptable failure; anything else, a crash or a sanitizer
// report is a bug), and a scratch file for readers that take paths.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <unistd.h>

#include "framework/io/vtk/vtk_formats.h"
#include "framework/util/error.h"

namespace subdiv::fuzz {

// read_mesh handles .vtp and .vtk through SubdivKit's VTK file IO, as in the `subdiv` tool.
inline const bool kVtkFormatsRegistered = (register_vtk_formats(), true);

// Runs `body`; subdiv::Error is the documented refusal, every other exception aborts so
// that libFuzzer records the input as a crash.
template <class Body>
void expect_only_subdiv_errors(Body&& body) {
  try {
    body();
  } catch (const Error&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: an exception other than subdiv::Error escaped: %s\n", e.what());
    std::abort();
  }
}

// A file in /dev/shm (or /tmp) private to this process, rewritten for every input: the
// readers under test take paths, and the extension picks the format.
// The file is removed when the process exits normally (after a crash it stays, next to
// the artifact libFuzzer keeps).
inline std::string scratch_file(const char* extension) {
  const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  static std::string path;
  path = std::string(dir) + "/subdiv-fuzz-" + std::to_string(getpid()) + extension;
  std::atexit([] { std::remove(path.c_str()); });
  return path;
}

inline void write_file(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
}

// Splits fuzz data at the first occurrence of `separator` (first part, rest); all in the
// first part when absent. Lets one input carry two texts (a scheme and a mesh).
inline std::pair<std::string, std::string> split_at(const std::uint8_t* data, std::size_t size,
                                                    const std::string& separator) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t at = text.find(separator);
  if (at == std::string::npos) return {text, std::string()};
  return {text.substr(0, at), text.substr(at + separator.size())};
}

}  // namespace subdiv::fuzz
