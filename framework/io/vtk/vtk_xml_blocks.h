#pragma once
// The binary data headers of a .vtp file, checked before VTK's XML reader allocates from
// them. Binary arrays (appended, raw or base64, or inline base64) start with a header:
// the byte count, or for compressed data the number of blocks, the block size, the last
// block's size and each block's compressed size. vtkXMLDataParser allocates what these
// say; a damaged header asked it for 200 GB (found by fuzz_read_vtp). Here every size
// must fit in the file, and what the blocks decompress to must be possible for the
// compressor and fit in memory. Internal to io/.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/io/vtk/vtk_xml_data_reader.h"

namespace subdiv::io_detail {

// The value of attribute `name` in the text of a start tag, if present.
std::optional<std::string_view> xml_attribute(std::string_view tag, std::string_view name);

// Where each element VTK may read as an array starts in `head` (the file before
// <AppendedData>): every start tag but those of the file's structure (VTKFile, Piece,
// PointData, ...) and of information keys. VTK reads every element nested in field, point
// and cell data as an array, whatever its name: checking only <DataArray> let an <Array>
// ask VTK for 14 GB, and one without a type attribute made it dereference a null array
// (both found by fuzz_read_vtp).
std::vector<std::size_t> xml_array_elements(std::string_view head);

// One binary array's values as VTK reads them, its header checked.
struct XmlArrayData {
  XmlDataReader values;  // at the first value byte, or at the first compressed block's first byte
  double bytes = 0;      // the values' size, decompressed
  std::string compressor;                 // the VTKFile's compressor attribute ("" for none)
  std::uint64_t block_size = 0, last_block = 0;  // compressed: the header's sizes (last 0: a full block)
  std::vector<std::uint64_t> packed;      // compressed: each block's compressed size
};

// Throws subdiv::Error "<file>:<line>: ..." naming the array and the problem. Returns the
// binary arrays' data by where their element starts in `bytes`.
std::map<std::size_t, XmlArrayData> check_vtp_data_headers(const std::filesystem::path& file, std::string_view bytes);

}  // namespace subdiv::io_detail
