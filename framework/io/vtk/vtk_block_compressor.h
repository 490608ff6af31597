#pragma once
// A compressor for vtkXMLWriter that uses every core. Internal to io/.
//
// Inline binary data (write_vtp's default) no longer reaches it: FastXMLPolyDataWriter writes
// that itself in a pipeline (vtk_inline_blocks.h). Raw appended data still goes through VTK's
// block loop (vtkXMLWriter::WriteArrayAppendedData is not virtual), and so through this.
//
// VTK's XML writer compresses an array block after block on one thread
// (vtkXMLWriter::WriteCompressionBlock calls vtkDataCompressor::Compress once per block of
// BlockSize bytes, then writes it, in order), and its API has no hook to do otherwise: the
// block loop and the stream are protected and not virtual. What the API does allow is a
// compressor of one's own (vtkXMLWriter::SetCompressor). This one is told beforehand where
// the arrays of the dataset lie in memory. When the writer hands it the first block of one
// of them, it compresses that block and the next ones (64 at a time) at once, in parallel
// (TBB), with fresh instances of VTK's own compressor at the same level, and then answers
// the writer's calls for them from those results. A block it was not told about (VTK copied
// the data first, e.g. to convert it) is compressed on the spot, as VTK would.
//
// Each block is compressed on its own by the same code at the same level as VTK's serial
// writer would, so the file is byte for byte the one VTK writes alone, for any thread
// count. The class name written into the file is VTK's compressor's (no vtkTypeMacro
// here), so every VTK reader and ParaView read it as an ordinary zlib/LZ4/LZMA file.
#include <cstddef>
#include <vector>

#include <vtkSmartPointer.h>

#include "framework/io/vtk/vtk_output.h"

class vtkDataCompressor;
class vtkPolyData;

namespace subdiv::io_detail {

// Bytes of one array as the writer reads them: `word` is the size of one value, so that the
// blocks start where the writer's do (every BlockSize / word values).
struct ArrayBytes {
  const unsigned char* data = nullptr;
  std::size_t size = 0;
  std::size_t word = 1;
};

// The arrays of `data` (points, point, cell and field data, cell connectivity and offsets)
// whose values lie in one contiguous block of memory, as the writer reads them.
std::vector<ArrayBytes> contiguous_arrays(vtkPolyData& data);

// Blocks each other compressor counts: from the parallel pass, and compressed on the spot.
struct BlockCounts {
  std::size_t parallel = 0, serial = 0;
};

// The compressor to give vtkXMLWriter::SetCompressor together with SetBlockSize(block_size);
// null for VtkCompressor::None. `counts`, if given, must outlive the compressor.
vtkSmartPointer<vtkDataCompressor> make_block_compressor(VtkCompressor type, int level, std::size_t block_size,
                                                         std::vector<ArrayBytes> arrays,
                                                         BlockCounts* counts = nullptr);

}  // namespace subdiv::io_detail
