#pragma once
// Writes refined levels: .vtp (finest level), .pvd (every level, for ParaView's time
// slider), or a mesh format (.obj, .off, .ply, .stl: finest level, creases kept in .obj).
#include <filesystem>
#include <vector>

#include "framework/io/vtk_output.h"
#include "framework/scheme/refiner.h"

namespace subdiv::cli {

// positions[l] holds level l's xyz. finest_point_data is added to the finest level's
// point data in .vtp/.pvd output (e.g. limit normals).
void write_levels(const std::filesystem::path& out, const Hierarchy& h,
                  const std::vector<std::vector<double>>& positions,
                  const std::vector<DataArray>& finest_point_data = {});

// The output extensions write_levels accepts, for help texts and early checks.
void check_output_path(const std::filesystem::path& out);

}  // namespace subdiv::cli
