#pragma once
// The binary data headers of a .vtp file, checked before VTK's XML reader allocates from
// them. Binary arrays (appended, raw or base64, or inline base64) start with a header:
// the byte count, or for compressed data the number of blocks, the block size, the last
// block's size and each block's compressed size. vtkXMLDataParser allocates what these
// say; a damaged header asked it for 200 GB (found by fuzz_read_vtp). Here every size
// must fit in the file, and what the blocks decompress to must be possible for the
// compressor and fit in memory. Internal to io/.
#include <filesystem>
#include <string_view>

namespace subdiv::io_detail {

// Throws subdiv::Error "<file>:<line>: ..." naming the array and the problem.
void check_vtp_data_headers(const std::filesystem::path& file, std::string_view bytes);

}  // namespace subdiv::io_detail
