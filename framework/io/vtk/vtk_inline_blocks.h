#pragma once
// One array's inline binary data (base64 inside its DataArray) as vtkXMLWriter writes it,
// with the blocks compressed and encoded on every core while earlier ones are written.
// Internal to io/.
//
// vtkXMLWriter::WriteBinaryData does one block at a time on one thread: compress, encode,
// write, then the next; the cores waited for each write() and the write for the cores. Here
// the blocks go through a pipeline (TBB's parallel_pipeline): compressed in parallel, encoded
// and written in order (straight into the file's buffer when the stream is a
// CheckedFileStream; otherwise encoded in parallel too), a few blocks ahead of the write. The bytes are VTK's: the same
// compressor class and level for each block (a fresh instance per slot, as
// vtk_block_compressor.h does), the same header, the same base64 runs (the compressed
// header in a run of its own, written first as a placeholder and again once the block sizes
// are known; the blocks in one run; without compression the 8-byte length and the data in
// one run), so the file is the one VTK writes, for any thread count.
#include <cstddef>
#include <functional>
#include <ostream>

class vtkDataCompressor;

namespace subdiv::io_detail {

struct InlineBytes {
  const unsigned char* data = nullptr;  // the array's values, little-endian, as written
  std::size_t size = 0;                 // bytes, more than 0
  std::size_t block_size = 0;           // vtkXMLWriter's BlockSize, a multiple of the value size
};

// Writes the base64 text of `bytes` (header type UInt64) at the stream's position, compressed
// by instances of `compressor`'s class at its level (none if null). `progress` is called on
// the calling thread with the share done, 0 to 1. Returns false if a block failed to
// compress; the stream's own state says whether writing failed.
bool write_inline_base64(std::ostream& os, const InlineBytes& bytes, vtkDataCompressor* compressor,
                         const std::function<void(double)>& progress);

}  // namespace subdiv::io_detail
