#include "framework/io/vtk/vtk_array_lengths_check.h"

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
#include "framework/util/short_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kCellSections[] = {"Verts", "Lines", "Strips", "Polys"};

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

// At most how many numbers text holds: each needs a digit of its own.
double digit_runs(std::string_view text) {
  double runs = 0;
  for (std::size_t p = 0; p < text.size(); ++p)
    if (std::isdigit(static_cast<unsigned char>(text[p])) && (p == 0 || !std::isdigit(static_cast<unsigned char>(text[p - 1]))))
      ++runs;
  return runs;
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

class LengthsChecker {
public:
  LengthsChecker(const fs::path& file, std::string_view bytes, const std::map<std::size_t, XmlArrayData>& binary)
      : file_(file), bytes_(bytes), binary_(binary) {
    if (const std::size_t root = bytes_.find("<VTKFile"); root != std::string_view::npos)
      big_endian_ = xml_attribute(tag_at(root), "byte_order").value_or("") == "BigEndian";
    head_ = bytes_.substr(0, bytes_.find("<AppendedData"));
    arrays_ = xml_array_elements(head_);
  }

  void run() const {
    for (std::size_t at = element("FieldData", 0); at != std::string_view::npos; at = element("FieldData", at + 1))
      for (const std::size_t a : arrays_in(at, end_of("FieldData", at, head_.size())))
        require_values(a, count_attribute(a, "NumberOfTuples"), "NumberOfTuples", "FieldData");
    for (std::size_t piece = element("Piece", 0); piece != std::string_view::npos; piece = element("Piece", piece + 1))
      check_piece(piece, end_of("Piece", piece, head_.size()));
  }

private:
  [[noreturn]] void fail(std::size_t at, const std::string& problem) const {
    const std::size_t line = 1 + std::size_t(std::count(bytes_.begin(), bytes_.begin() + std::min(at, bytes_.size()), '\n'));
    throw Error(fmt::format("{}:{}: {}", escaped(file_.string()), line, problem));
  }

  std::string_view tag_at(std::size_t at) const {
    return bytes_.substr(at, std::min(bytes_.find('>', at), bytes_.size()) - at);
  }

  // The next start tag named `name` in the head at or after `from`.
  std::size_t element(std::string_view name, std::size_t from) const {
    const std::string open = fmt::format("<{}", name);
    for (std::size_t at = head_.find(open, from); at != std::string_view::npos; at = head_.find(open, at + 1)) {
      const std::size_t after = at + open.size();
      if (after < head_.size() && !std::isalnum(static_cast<unsigned char>(head_[after]))) return at;
    }
    return std::string_view::npos;
  }

  // Where the element `name` that starts at `at` ends (its closing tag), at most `limit`.
  std::size_t end_of(std::string_view name, std::size_t at, std::size_t limit) const {
    return std::min(head_.find(fmt::format("</{}", name), at), limit);
  }

  std::vector<std::size_t> arrays_in(std::size_t begin, std::size_t end) const {
    return {std::lower_bound(arrays_.begin(), arrays_.end(), begin), std::lower_bound(arrays_.begin(), arrays_.end(), end)};
  }

  // A count attribute's value; 0 when missing or not a count (vtk_xml_check.cpp refuses those).
  long long count_attribute(std::size_t at, std::string_view name) const {
    long long v = 0;
    const auto text = xml_attribute(tag_at(at), name);
    return text && parse_integer(*text, v) && v > 0 ? v : 0;
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

  // VTK sizes these arrays from the piece's counts and allocates before it reads them.
  void check_piece(std::size_t piece, std::size_t piece_end) const {
    const long long points = count_attribute(piece, "NumberOfPoints");
    long long cells = 0;
    for (const std::string_view section : kCellSections) cells += count_attribute(piece, fmt::format("NumberOf{}", section));
    const auto section_range = [&](std::string_view name) -> std::pair<std::size_t, std::size_t> {
      const std::size_t at = element(name, piece);
      if (at >= piece_end) return {piece_end, piece_end};
      return {at, end_of(name, at, piece_end)};
    };
    for (const auto& [name, count] : {std::pair<std::string_view, long long>{"Points", points}, {"PointData", points},
                                      {"CellData", cells}}) {
      const auto [begin, end] = section_range(name);
      for (const std::size_t a : arrays_in(begin, end))
        require_values(a, count, name == "CellData" ? "the piece's cells" : "NumberOfPoints", name);
    }
    for (const std::string_view section : kCellSections) {
      const long long n = count_attribute(piece, fmt::format("NumberOf{}", section));
      if (n <= 0) continue;
      const auto [begin, end] = section_range(section);
      check_cells(section, begin, end, n);
    }
  }

  // An array of `tuples` tuples in <section> must hold tuples x components values.
  void require_values(std::size_t array, long long tuples, std::string_view counted, std::string_view section) const {
    if (tuples <= 0) return;
    long long components = 1;
    if (const auto c = xml_attribute(tag_at(array), "NumberOfComponents")) parse_integer(*c, components);
    const double needed = double(tuples) * double(components), held = length(array);
    const std::string_view name = xml_attribute(tag_at(array), "Name").value_or("");
    if (needed > held)
      fail(array, fmt::format("{} needs {:.0f} values ({} = {} x {} components), but its data holds at most {:.0f}; "
                              "the file is cut off or its sizes are wrong",
                              name.empty() ? fmt::format("the unnamed array in <{}>", section)
                                           : fmt::format("array {}", subdiv::quoted(shortened(name))),
                              needed, counted, tuples, components, held));
  }

  // The connectivity is sized by the last offset.
  void check_cells(std::string_view section, std::size_t begin, std::size_t end, long long cells) const {
    const auto offsets = array_named("offsets", begin, end), connectivity = array_named("connectivity", begin, end);
    if (!offsets || !connectivity) return;  // VTK's reader refuses the section before it allocates
    require_values(*offsets, cells, fmt::format("NumberOf{}", section), section);
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

  // At most how many values VTK can read from `array`: binary, what its header says;
  // ascii, one per run of digits up to the element's end (a number has at least one).
  double length(std::size_t array) const {
    if (const auto data = binary_.find(array); data != binary_.end())
      return data->second.bytes / double(vtp_type_size(type_of(array)));
    const std::string_view text = ascii_text(array);
    return digit_runs(text.substr(0, text.find('<')));
  }

  std::string_view ascii_text(std::size_t array) const {
    const std::size_t tag_end = bytes_.find('>', array);
    return tag_end == std::string_view::npos || bytes_[tag_end - 1] == '/' ? std::string_view() : bytes_.substr(tag_end + 1);
  }

  const fs::path& file_;
  std::string_view bytes_;
  const std::map<std::size_t, XmlArrayData>& binary_;
  bool big_endian_ = false;
  std::string_view head_;
  std::vector<std::size_t> arrays_;
};

}  // namespace

void check_vtp_array_lengths(const fs::path& file, std::string_view bytes, const std::map<std::size_t, XmlArrayData>& binary) {
  LengthsChecker(file, bytes, binary).run();
}

}  // namespace subdiv::io_detail
