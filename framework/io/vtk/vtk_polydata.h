#pragma once
// Turning an OutputLevel into a vtkPolyData and writing it as VTK XML. Internal to io/:
// shared by write_vtp and write_pvd.
#include <filesystem>
#include <string>
#include <string_view>

#include <vtkSmartPointer.h>

#include "framework/io/mesh_validate.h"
#include "framework/io/vtk/vtk_output.h"

class vtkPolyData;

namespace subdiv::io_detail {

// Whether check_output_level checks that an integer array's values are whole numbers that
// fit an int (Checked), or leaves that to make_polydata, which converts them to ints anyway
// and checks them in the same pass (WhenConverted: for a caller that calls make_polydata
// before it creates a file).
enum class IntegerValues { Checked, WhenConverted };

// What check_output_level found, for make_polydata.
struct LevelCheck {
  MeshValueRanges mesh;  // the points' and faces' value ranges
  std::string context;   // for make_polydata's message
};

// Checks the mesh and every array's name and length; throws subdiv::Error
// "<context>: <problem>".
LevelCheck check_output_level(const OutputLevel& level, std::string_view context,
                              IntegerValues integers = IntegerValues::Checked);

// Share: the polydata's points, faces and double arrays are the level's own memory, handed
// over without a copy (a 16M-face level is gigabytes), for a polydata written at once while
// `level`, its mesh and arrays live. Copy: the polydata owns all its data (ParaView's plugin).
enum class LevelMemory { Copy, Share };

// Assumes check_output_level passed. Adds the arrays write_vtp adds that `options` asks for.
// `check`, check_output_level's result if given, gives the points' and faces' ranges in the
// file's headers instead of another pass over them, and names the file if an integer array's
// value is refused (IntegerValues::WhenConverted; throws subdiv::Error as check_output_level).
vtkSmartPointer<vtkPolyData> make_polydata(const OutputLevel& level, const VtkWriteOptions& options = {},
                                           LevelMemory memory = LevelMemory::Copy,
                                           const LevelCheck* check = nullptr);

struct BlockCounts;

// VTK XML into `file` (inline base64 or raw appended, as `options` say), compressed as `options` say on every core TBB may use;
// `shown` names it in messages. `counts`, if given, counts how the blocks were compressed.
void write_polydata_file(vtkPolyData& poly, const std::filesystem::path& file, const std::filesystem::path& shown,
                         const VtkWriteOptions& options = {}, BlockCounts* counts = nullptr);

}  // namespace subdiv::io_detail
