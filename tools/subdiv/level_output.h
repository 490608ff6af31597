#pragma once
// Writes refined levels: .vtp (finest level), .pvd (every level, for ParaView's time
// slider), or a mesh format (.obj, .off, .ply, .stl: finest level, creases kept in .obj).
#include <filesystem>
#include <vector>

#include "framework/scheme/refiner.h"

namespace subdiv::cli {

// positions[l] holds level l's xyz.
void write_levels(const std::filesystem::path& out, const Hierarchy& h,
                  const std::vector<std::vector<double>>& positions);

// The output extensions write_levels accepts, for help texts and early checks.
void check_output_path(const std::filesystem::path& out);

}  // namespace subdiv::cli
