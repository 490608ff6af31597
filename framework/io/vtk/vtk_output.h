#pragma once
// ParaView output: one mesh level as a .vtp file, and a series of levels as a .pvd
// collection whose time steps are the levels, so that ParaView's time slider steps through
// the refinement.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <functional>

#include "framework/io/mesh_data.h"
#include "framework/io/output_level.h"

namespace subdiv {

// How write_vtp, write_pvd and the pieces' .vtp files are written.
enum class VtkCompressor { None, ZLib, LZ4, LZMA };  // VTK's vtkXMLWriter compressor types
// Where the arrays' bytes go. Base64: inside each DataArray as base64 text (inline binary),
// well-formed XML that every ParaView reads. Raw: after the XML as raw appended data, a third
// smaller and written without encoding, but VTK before 9.3 fails on it with Expat 2.6's
// reparse deferral (Debian 12's ParaView 5.11 among them; see expat_reparse_fix.cpp, which
// makes SubdivKit's own readers read it).
enum class VtkEncoding { Base64, Raw };
struct VtkWriteOptions {
  // LZ4 at its fastest wrote the 16M-face torus in a third of zlib's (level 1) time, in a
  // file 2.6 times as large (docs/benchmarks.md, "End to end").
  VtkCompressor compressor = VtkCompressor::LZ4;
  // 1 (fastest) to 9 (smallest), as vtkXMLWriter::SetCompressionLevel takes it (LZ4: its
  // acceleration is 10 - level).
  int compression_level = 1;
  VtkEncoding encoding = VtkEncoding::Base64;
  // Written past the page cache (O_DIRECT), in 4 MB chunks on a thread of their own, with
  // ordinary writes where the file system refuses direct I/O; the bytes are the same either
  // way. A buffered write copies every byte into new page-cache pages first: 800 MB cost
  // 0.65-2 s of system time that way on the benchmark machine (a virtual machine), and ran at
  // 0.2 GB/s while an earlier file's pages were being flushed, against 1.6-1.8 GB/s direct
  // (docs/benchmarks.md, "Writing and reading"). false: through the page cache, which returns
  // sooner where the disk is much slower than memory and the file fits in it.
  bool direct_io = true;
  // The arrays write_vtp adds itself (see write_vtp); each can be left out.
  bool sharpness = true, cell_kind = true, corner_sharpness = true;
  // Told the share written so far, 0 to 1 (VTK's progress events, as arrays are written;
  // write_pvd's over all its level files, weighted by their sizes); may be empty.
  std::function<void(double done)> progress;
};

// Writes faces as polygons, polylines and crease edges as line cells, in VTK XML with the
// arrays inline in base64 or raw appended (`options.encoding`), compressed as `options` say; the blocks of each array are compressed on every core
// TBB may use, and the file is the same for any thread count (vtk_block_compressor.h).
// Added arrays (each can be left out, see VtkWriteOptions): cell "sharpness" (a crease's
// sharpness, 0 on other cells), cell "cell_kind" (0 face, 1 polyline, 2 crease edge), point
// "corner_sharpness" (0 where untagged); always field "level" and "TimeValue" (the level).
// Throws subdiv::Error, before creating any file, for an invalid mesh, arrays of the wrong
// length, duplicate or reserved array names; atomic like write_mesh.
void write_vtp(const std::filesystem::path& file, const OutputLevel& level, const VtkWriteOptions& options = {});

// Writes <dir>/<stem>_levels/level_<k>.vtp for every level k and then <dir>/<stem>.pvd
// listing them with timestep k. All level files are complete before the .pvd appears; if
// anything fails, no new file is left behind. Level numbers must be distinct.
void write_pvd(const std::filesystem::path& pvd, std::span<const OutputLevel> levels,
               const VtkWriteOptions& options = {});

}  // namespace subdiv
