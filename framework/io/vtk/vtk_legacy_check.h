#pragma once
// Legacy .vtk files checked before VTK's reader sees them. vtkPolyDataReader trusts the
// counts in the file: a cut-off or corrupt file makes it read past its buffers (a crash)
// or allocate what the counts say (std::bad_alloc). This walks the whole file the way
// the reader will, with every count checked against the bytes really there and every
// point index against the points, and names the line (or byte) of the first problem.
// Internal to io/.
#include <filesystem>
#include <string_view>

namespace subdiv::io_detail {

// Throws subdiv::Error "<file>:<line>: ..." (ASCII) or "<file>: byte N: ..." (binary).
void check_legacy_vtk_text(const std::filesystem::path& file, std::string_view bytes);
void check_legacy_vtk_file(const std::filesystem::path& file);

}  // namespace subdiv::io_detail
