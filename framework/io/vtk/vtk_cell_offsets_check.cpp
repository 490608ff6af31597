#include "framework/io/vtk/vtk_cell_offsets_check.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <vector>

#include "framework/io/text_input.h"
#include "framework/io/vtk/vtp_array_decode.h"
#include "framework/io/vtk/vtp_layout.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kSections[] = {"Verts", "Lines", "Strips", "Polys"};

// Ascii data as vtkXMLDataParser reads it: from the file right after the element's start
// tag, one integer after the other as an input stream reads them (blanks skipped, a sign,
// digits up to the first other character), until the stream fails (at the closing tag).
// How many it reads (at most `limit`), and the last of them.
struct AsciiValues {
  std::uint64_t count = 0;
  double last = 0;
};

AsciiValues ascii_values(std::string_view text, std::uint64_t limit) {
  AsciiValues out;
  std::size_t p = 0;
  while (out.count < limit) {
    while (p < text.size() && std::isspace(static_cast<unsigned char>(text[p]))) ++p;
    const bool negative = p < text.size() && text[p] == '-';
    if (p < text.size() && (text[p] == '-' || text[p] == '+')) ++p;
    const std::size_t digits = p;
    double value = 0;
    for (; p < text.size() && text[p] >= '0' && text[p] <= '9'; ++p) value = 10 * value + (text[p] - '0');
    if (p == digits) break;
    out.last = negative ? -value : value;
    ++out.count;
  }
  return out;
}

// The integer in `raw` (the file's byte order) of `type`.
double integer_of(const std::string& raw, VtpType type, bool big_endian) {
  std::uint64_t bits = 0;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const std::size_t k = big_endian ? i : raw.size() - 1 - i;
    bits = (bits << 8) | static_cast<unsigned char>(raw[k]);
  }
  const bool is_signed = type == VtpType::Int8 || type == VtpType::Int16 || type == VtpType::Int32 || type == VtpType::Int64;
  const unsigned width = unsigned(8 * raw.size());
  if (is_signed && width < 64 && (bits >> (width - 1)) != 0) return double(bits) - double(std::uint64_t(1) << width);
  if (is_signed && width == 64) return double(std::int64_t(bits));
  return double(bits);
}

// Value `index` of a binary array, decompressing the one block that holds it; nothing if
// the data ends first or the block does not decompress (VTK's reader then fails first).
std::optional<double> binary_value(const XmlArrayData& data, std::uint64_t index, VtpType type, bool big_endian) {
  const std::size_t size = vtp_type_size(type);
  const double first = double(index) * double(size);
  if (first + double(size) > data.bytes) return std::nullopt;
  XmlDataReader reader = data.values;
  if (data.packed.empty()) {
    if (!reader.skip(index * size)) return std::nullopt;
    const auto raw = reader.take(size);
    return raw ? std::optional<double>(integer_of(*raw, type, big_endian)) : std::nullopt;
  }
  const std::uint64_t at = index * size, block = at / data.block_size, within = at - block * data.block_size;
  std::uint64_t before = 0;
  for (std::uint64_t b = 0; b < block; ++b) before += data.packed[b];
  const auto packed = reader.skip(before) ? reader.take(data.packed[block]) : std::nullopt;
  const auto compressor = vtp_compressor_named(data.compressor);
  if (!packed || !compressor || *compressor == VtpCompressor::None) return std::nullopt;
  const std::uint64_t plain_size = block + 1 == data.packed.size() && data.last_block ? data.last_block : data.block_size;
  if (within + size > plain_size) return std::nullopt;
  std::vector<unsigned char> plain(plain_size);
  const auto* in = reinterpret_cast<const unsigned char*>(packed->data());
  if (make_vtp_decompressor(*compressor)->Uncompress(in, packed->size(), plain.data(), plain.size()) != plain.size())
    return std::nullopt;
  return integer_of(std::string(plain.begin() + within, plain.begin() + within + size), type, big_endian);
}

class OffsetsChecker {
public:
  OffsetsChecker(const fs::path& file, std::string_view bytes, const std::map<std::size_t, XmlArrayData>& binary)
      : file_(file), bytes_(bytes), binary_(binary) {}

  void run() const {
    const std::size_t root = bytes_.find("<VTKFile");
    if (root == std::string_view::npos) return;
    big_endian_ = xml_attribute(tag_at(root), "byte_order").value_or("") == "BigEndian";
    head_ = bytes_.substr(0, bytes_.find("<AppendedData"));
    arrays_ = xml_array_elements(head_);
    for (std::size_t piece = element(head_, "Piece", 0); piece != std::string_view::npos;
         piece = element(head_, "Piece", piece + 1)) {
      const std::size_t piece_end = std::min(head_.find("</Piece", piece), head_.size());
      for (const std::string_view section : kSections) {
        long long cells = 0;
        const auto count = xml_attribute(tag_at(piece), fmt::format("NumberOf{}", section));
        if (!count || !parse_integer(*count, cells) || cells <= 0) continue;
        const std::size_t at = element(head_, section, piece);
        if (at < piece_end) check_section(section, at, std::min(head_.find(fmt::format("</{}", section), at), piece_end), cells);
      }
    }
  }

private:
  [[noreturn]] void fail(std::size_t at, const std::string& problem) const {
    const std::size_t line = 1 + std::size_t(std::count(bytes_.begin(), bytes_.begin() + std::min(at, bytes_.size()), '\n'));
    throw Error(fmt::format("{}:{}: {}", escaped(file_.string()), line, problem));
  }

  std::string_view tag_at(std::size_t at) const {
    return bytes_.substr(at, std::min(bytes_.find('>', at), bytes_.size()) - at);
  }

  // The next start tag named `name` at or after `from`.
  static std::size_t element(std::string_view text, std::string_view name, std::size_t from) {
    const std::string open = fmt::format("<{}", name);
    for (std::size_t at = text.find(open, from); at != std::string_view::npos; at = text.find(open, at + 1)) {
      const std::size_t after = at + open.size();
      if (after < text.size() && !std::isalnum(static_cast<unsigned char>(text[after]))) return at;
    }
    return std::string_view::npos;
  }

  // The first array named `name` in [begin, end).
  std::optional<std::size_t> array_named(std::string_view name, std::size_t begin, std::size_t end) const {
    for (auto a = std::lower_bound(arrays_.begin(), arrays_.end(), begin); a != arrays_.end() && *a < end; ++a)
      if (xml_attribute(tag_at(*a), "Name") == name) return *a;
    return std::nullopt;
  }

  VtpType type_of(std::size_t array) const {
    return vtp_type_named(xml_attribute(tag_at(array), "type").value_or("")).value_or(VtpType::Int64);
  }

  void check_section(std::string_view section, std::size_t begin, std::size_t end, long long cells) const {
    const auto offsets = array_named("offsets", begin, end), connectivity = array_named("connectivity", begin, end);
    if (!offsets || !connectivity) return;  // VTK's reader refuses the section before it allocates
    const std::optional<double> last = value(*offsets, std::uint64_t(cells - 1));
    if (!last) return;
    const double capacity = length(*connectivity);
    if (*last > capacity)
      fail(*offsets, fmt::format("the last offset of <{}> is {:.0f}, but its connectivity array holds at most {:.0f} "
                                 "values; the offsets or the connectivity are damaged",
                                 section, *last, capacity));
  }

  std::optional<double> value(std::size_t array, std::uint64_t index) const {
    if (const auto data = binary_.find(array); data != binary_.end())
      return binary_value(data->second, index, type_of(array), big_endian_);
    const AsciiValues read = ascii_values(ascii_text(array), index + 1);
    return read.count == index + 1 ? std::optional<double>(read.last) : std::nullopt;
  }

  // How many values VTK can read from `array` (binary: at most).
  double length(std::size_t array) const {
    if (const auto data = binary_.find(array); data != binary_.end())
      return data->second.bytes / double(vtp_type_size(type_of(array)));
    return double(ascii_values(ascii_text(array), UINT64_MAX).count);
  }

  std::string_view ascii_text(std::size_t array) const {
    const std::size_t tag_end = bytes_.find('>', array);
    return tag_end == std::string_view::npos || bytes_[tag_end - 1] == '/' ? std::string_view() : bytes_.substr(tag_end + 1);
  }

  const fs::path& file_;
  std::string_view bytes_;
  const std::map<std::size_t, XmlArrayData>& binary_;
  mutable bool big_endian_ = false;
  mutable std::string_view head_;
  mutable std::vector<std::size_t> arrays_;
};

}  // namespace

void check_vtp_cell_offsets(const fs::path& file, std::string_view bytes, const std::map<std::size_t, XmlArrayData>& binary) {
  OffsetsChecker(file, bytes, binary).run();
}

}  // namespace subdiv::io_detail
