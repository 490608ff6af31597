#pragma once
// Turning an OutputLevel into a vtkPolyData and writing it as VTK XML. Internal to io/:
// shared by write_vtp and write_pvd.
#include <filesystem>
#include <string_view>

#include <vtkSmartPointer.h>

#include "framework/io/mesh_validate.h"
#include "framework/io/vtk/vtk_output.h"

class vtkPolyData;

namespace subdiv::io_detail {

// Checks the mesh and every array's name and length; throws subdiv::Error
// "<context>: <problem>". Returns the value ranges the mesh's checks saw (for make_polydata).
MeshValueRanges check_output_level(const OutputLevel& level, std::string_view context);

// Share: the polydata's points, faces and double arrays are the level's own memory, handed
// over without a copy (a 16M-face level is gigabytes), for a polydata written at once while
// `level`, its mesh and arrays live. Copy: the polydata owns all its data (ParaView's plugin).
enum class LevelMemory { Copy, Share };

// Assumes check_output_level passed. Adds the arrays write_vtp adds that `options` asks for.
// `ranges`, check_output_level's result if given, become the points' and faces' ranges in the
// file's headers instead of another pass over them.
vtkSmartPointer<vtkPolyData> make_polydata(const OutputLevel& level, const VtkWriteOptions& options = {},
                                           LevelMemory memory = LevelMemory::Copy,
                                           const MeshValueRanges* ranges = nullptr);

struct BlockCounts;

// VTK XML into `file` (inline base64 or raw appended, as `options` say), compressed as `options` say on every core TBB may use;
// `shown` names it in messages. `counts`, if given, counts how the blocks were compressed.
void write_polydata_file(vtkPolyData& poly, const std::filesystem::path& file, const std::filesystem::path& shown,
                         const VtkWriteOptions& options = {}, BlockCounts* counts = nullptr);

}  // namespace subdiv::io_detail
