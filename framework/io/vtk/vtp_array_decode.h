#pragma once
// The bytes of one binary array of a .vtp file, decoded on every core (TBB) for the fast
// reader (vtp_fast_read.h). VTK's binary layout (vtkXMLWriter, vtkXMLDataParser): a header of
// UInt32 or UInt64 words, then the data. Uncompressed: one word, the byte count. Compressed:
// the block count n, the block size, the last block's size (0: a full block) and each
// block's compressed size; the blocks follow one after the other and decompress on their
// own, so each is a task. Base64 (inline, or appended with encoding="base64"): the header
// and the data are one run of base64 text without compression, two runs (each padded with
// '=') with it; a task decodes the text of its own piece. Internal to io/.
#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>

#include <vtkDataCompressor.h>
#include <vtkSmartPointer.h>

#include "framework/io/vtk/vtp_layout.h"

namespace subdiv::io_detail {

// Takes an array's bytes in pieces, from any thread, each piece starting and ending at a
// multiple of the value size; the pieces cover the array once.
class ArraySink {
public:
  virtual ~ArraySink() = default;
  // Where bytes [at, at + n) may be written as they are in the file (the destination has the
  // file's type), or null: then put() gets them.
  virtual unsigned char* direct(std::size_t at, std::size_t n) = 0;
  virtual void put(std::size_t at, const unsigned char* bytes, std::size_t n) = 0;
  // Bytes [at, at + n) were written where direct() said, on this thread, just now (in cache).
  virtual void written(std::size_t at, std::size_t n) { (void)at, (void)n; }
};

// Decodes the data of `array` in `file` into `sink`; it must be exactly `expected` bytes.
// False (the sink may have been given part of it) if the header says otherwise, the text is
// not base64, a block does not decompress to its size, or the data runs past `array.end`:
// the caller then leaves the file to VTK's reader and its checks.
bool decode_vtp_array_into(std::string_view file, const VtpArray& array, std::size_t expected,
                           std::size_t header_bytes, VtpCompressor compressor, ArraySink& sink);

struct DecodedBytes {
  std::unique_ptr<unsigned char[]> owner;  // empty when `bytes` points into the file
  const unsigned char* bytes = nullptr;
  std::size_t size = 0;
};

// The same into memory of its own (raw uncompressed data: a view of the file).
std::optional<DecodedBytes> decode_vtp_array(std::string_view file, const VtpArray& array, std::size_t expected,
                                             std::size_t header_bytes, VtpCompressor compressor);

// VTK's decompressor of `type` (not None), its error and warning events silenced: a block
// that does not decompress shows as a short result, not as text on the terminal.
vtkSmartPointer<vtkDataCompressor> make_vtp_decompressor(VtpCompressor type);

// Exactly `bytes` bytes from the 4 * ceil(bytes / 3) characters at `text`, with '=' padding
// in the last group as VTK writes it; false on any other character.
bool decode_base64_run(const char* text, std::size_t bytes, unsigned char* out);

}  // namespace subdiv::io_detail
