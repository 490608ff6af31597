#pragma once
// The structure of a .vtp file as the fast reader (vtp_fast_read.h) takes it: the XML
// before the data, read by a strict parser that accepts only the forms VTK's and
// SubdivKit's writers produce (one piece; binary arrays inline in base64 or appended, raw
// or base64; little-endian; numeric types) and declines everything else, so that what it
// accepts is well-formed XML that VTK's reader would read the same way. Internal to io/.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace subdiv::io_detail {

enum class VtpType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };
std::size_t vtp_type_size(VtpType type);
bool vtp_type_is_float(VtpType type);
// The type of a DataArray's type="..." text (Int8 ... Float64), if numeric.
std::optional<VtpType> vtp_type_named(std::string_view name);

enum class VtpCompressor : std::uint8_t { None, ZLib, LZ4, LZMA };
// The compressor of a VTKFile's compressor="..." ("" is None), if VTK has it.
std::optional<VtpCompressor> vtp_compressor_named(std::string_view name);

struct VtpArray {
  std::string name;  // empty when the element has no Name
  VtpType type = VtpType::Float64;
  int components = 1;
  long long tuples = -1;  // NumberOfTuples (field data only), else -1
  // Where the data starts in the file: an inline array's first base64 character, an
  // appended array's header; `end` bounds it (the '<' after inline text, else the file's end).
  std::size_t at = 0, end = 0;
  bool base64 = true;
  bool inline_text = false;  // inline: only blanks may follow the data up to `end`
};

// PointData or CellData: the arrays in file order and the attributes VTK makes active.
struct VtpSection {
  std::vector<VtpArray> arrays;
  std::string normals, tcoords, scalars;  // array names, empty when not said
};

struct VtpCells {
  VtpArray connectivity, offsets;
  bool present = false;
};

struct VtpLayout {
  std::size_t header_bytes = 4;  // UInt32 or UInt64 words in the binary headers
  VtpCompressor compressor = VtpCompressor::None;
  long long points = 0, verts = 0, lines = 0, strips = 0, polys = 0;
  std::vector<VtpArray> field;
  VtpSection point_data, cell_data;
  std::optional<VtpArray> coordinates;
  VtpCells cells[4];  // Verts, Lines, Strips, Polys
};

// The layout of `file`, or nothing where the file uses anything the fast reader leaves to
// VTK's (ascii data, several pieces, comments, entities, big-endian data, other attribute
// forms) or is malformed in any way this parser sees.
std::optional<VtpLayout> parse_vtp_layout(std::string_view file);

}  // namespace subdiv::io_detail
