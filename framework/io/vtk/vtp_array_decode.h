#pragma once
// The bytes of one binary array of a .vtp file, decoded on every core (TBB) for the fast
// reader (vtp_fast_read.h). VTK's binary layout (vtkXMLWriter, vtkXMLDataParser): a header of
// UInt32 or UInt64 words, then the data. Uncompressed: one word, the byte count. Compressed:
// the block count n, the block size, the last block's size (0: a full block) and each
// block's compressed size; the blocks follow one after the other and decompress on their
// own, so each is a task. Base64 (inline, or appended with encoding="base64"): the header
// and the data are one run of base64 text without compression, two runs (each padded with
// '=') with it. Raw appended data needs no copy when it is not compressed. Internal to io/.
#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>

#include "framework/io/vtk/vtp_layout.h"

namespace subdiv::io_detail {

struct DecodedBytes {
  std::unique_ptr<unsigned char[]> owner;  // empty when `bytes` points into the file
  const unsigned char* bytes = nullptr;
  std::size_t size = 0;
};

// The data of `array` in `file`, which must be exactly `expected` bytes; nothing if the header
// says otherwise, the text is not base64, a block does not decompress to its size, or the data
// runs past `array.end` (the caller then leaves the file to VTK's reader and its checks).
std::optional<DecodedBytes> decode_vtp_array(std::string_view file, const VtpArray& array, std::size_t expected,
                                             std::size_t header_bytes, VtpCompressor compressor);

// Exactly `bytes` bytes from the 4 * ceil(bytes / 3) characters at `text`, with '=' padding
// in the last group as VTK writes it; false on any other character.
bool decode_base64_run(const char* text, std::size_t bytes, unsigned char* out);

}  // namespace subdiv::io_detail
