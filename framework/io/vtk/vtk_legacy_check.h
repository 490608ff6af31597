#pragma once
// Legacy .vtk files checked before VTK's reader sees them. vtkPolyDataReader trusts the
// counts in the file: a cut-off or corrupt file makes it read past its buffers (a crash)
// or allocate what the counts say (std::bad_alloc). This walks the whole file the way
// the reader will, with every count checked against the bytes really there and every
// point index against the points, and names the line (or byte) of the first problem.
// Internal to io/.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace subdiv::io_detail {

// Throws subdiv::Error "<file>:<line>: ..." (ASCII) or "<file>: byte N: ..." (binary).
// METADATA blocks (component names, information keys: nothing SubdivKit uses) are not
// left to VTK, which parses them by rules no check can follow: when the file has any, the
// result is its bytes with each block turned into line ends, for VTK to read instead of
// the file; otherwise it is empty and VTK reads the file itself.
std::optional<std::string> check_legacy_vtk_text(const std::filesystem::path& file, std::string_view bytes);
std::optional<std::string> check_legacy_vtk_file(const std::filesystem::path& file);

}  // namespace subdiv::io_detail
