#pragma once
// The individual writers behind write_mesh. Each writes a mesh that validate_mesh_data
// accepted to `file` (a temporary); `shown` is the final name, for messages.
// Internal to io/: call write_mesh instead.
#include <filesystem>

#include "framework/io/io_progress.h"
#include "framework/io/mesh_data.h"

namespace subdiv::io_detail {

using std::filesystem::path;

void write_obj(const path& file, const path& shown, const MeshData& mesh, const ProgressCallback& progress = {});
void write_off(const path& file, const path& shown, const MeshData& mesh, const ProgressCallback& progress = {});
void write_ply(const path& file, const path& shown, const MeshData& mesh, const ProgressCallback& progress = {});
void write_stl(const path& file, const path& shown, const MeshData& mesh, const ProgressCallback& progress = {});

}  // namespace subdiv::io_detail
