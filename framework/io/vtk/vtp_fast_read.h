#pragma once
// The .vtp reader's fast path: the file's XML parsed by a strict parser of its own
// (vtp_layout.h), every array's blocks decoded on every core (vtp_array_decode.h) straight
// into MeshData, without VTK's reader, its vtkPolyData and the conversion after it. VTK's
// reader decodes one block after another on one core and the conversion copies every point
// and cell again.
//
// It gives exactly the MeshData that VTK's reader and polydata_to_mesh_data give, and
// declines (returns nothing) on anything else: ascii data, several pieces, triangle strips,
// big-endian data, any malformed structure or data, ids out of range, sizes beyond memory.
// read_vtk_polydata then reads the file with VTK's reader and its checks, which name the
// file and place of every problem; so no error message is written twice.
// Internal to io/.
#include <filesystem>
#include <optional>
#include <string_view>

#include "framework/io/mesh_data.h"

namespace subdiv::io_detail {

// `bytes` is the whole file.
std::optional<MeshData> read_vtp_fast(std::string_view bytes);
// The same for a file (nothing if it cannot be read: VTK's reader then says why).
std::optional<MeshData> read_vtp_fast_file(const std::filesystem::path& file);

}  // namespace subdiv::io_detail
