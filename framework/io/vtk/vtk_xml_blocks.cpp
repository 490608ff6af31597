#include "framework/io/vtk/vtk_xml_blocks.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <vector>

#include "framework/io/text_input.h"
#include "framework/io/vtk/vtk_xml_data_reader.h"
#include "framework/util/error.h"
#include "framework/util/byte_size_text.h"
#include "framework/util/memory_limit.h"
#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

// How much larger than its compressed form data can become: zlib's limit is about 1032:1,
// LZ4's about 255:1; LZMA has no small limit, so its bound is generous.
double expansion_limit(std::string_view compressor) {
  if (compressor == "vtkZLibDataCompressor") return 1100;
  if (compressor == "vtkLZ4DataCompressor") return 300;
  return 1e5;
}

class HeaderChecker {
public:
  HeaderChecker(const fs::path& file, std::string_view bytes) : file_(file), bytes_(bytes) {}

  std::map<std::size_t, XmlArrayData> run() {
    std::map<std::size_t, XmlArrayData> out;
    const std::size_t root = bytes_.find("<VTKFile");
    if (root == std::string_view::npos) return out;  // VTK's own check reports it
    const std::string_view tag = tag_at(root);
    word_size_ = xml_attribute(tag, "header_type").value_or("UInt32") == "UInt64" ? 8 : 4;
    big_endian_ = xml_attribute(tag, "byte_order").value_or("LittleEndian") == "BigEndian";
    compressor_ = xml_attribute(tag, "compressor").value_or("");
    const std::size_t appended = bytes_.find("<AppendedData");
    std::size_t data_start = std::string_view::npos;
    bool appended_base64 = true;
    if (appended != std::string_view::npos) {
      const std::string_view element = tag_at(appended);
      appended_base64 = xml_attribute(element, "encoding").value_or("base64") != "raw";
      data_start = appended_data_start(appended + element.size() + 1);
    }
    const std::string_view head = bytes_.substr(0, appended);
    for (const std::size_t at : xml_array_elements(head)) {
      const std::string_view array = tag_at(at);
      const std::string_view format = xml_attribute(array, "format").value_or("ascii");
      const std::string name(xml_attribute(array, "Name").value_or("(unnamed)"));
      // VTK reads an array with an offset attribute from the appended data, whatever its
      // format says, and one without as binary if the format is exactly "binary", else as
      // text (format="appendedJ" sent VTK to appended data this check had skipped, and it
      // allocated 81 GB: found by fuzz_read_vtp).
      if (const auto offset_text = xml_attribute(array, "offset")) {
        long long offset;
        if (!parse_integer(*offset_text, offset) || offset < 0 || data_start == std::string_view::npos ||
            std::size_t(offset) > bytes_.size() - data_start)
          fail(at, fmt::format("array {}: its offset=\"{}\" does not point into the appended data", subdiv::quoted(shortened(name)),
                               escaped(shortened(*offset_text))));
        out.emplace(at, check_header(XmlDataReader(bytes_, data_start + std::size_t(offset), appended_base64), at, name));
      } else if (format == "binary") {
        out.emplace(at, check_header(XmlDataReader(bytes_, at + array.size() + 1, true), at, name));
      }
    }
    return out;
  }

private:
  [[noreturn]] void fail(std::size_t at, const std::string& problem) const {
    const std::size_t line = 1 + std::size_t(std::count(bytes_.begin(), bytes_.begin() + std::min(at, bytes_.size()), '\n'));
    throw Error(fmt::format("{}:{}: {}", escaped(file_.string()), line, problem));
  }

  // Where VTK's vtkXMLDataParser::FindAppendedDataPosition puts the data: after the
  // blanks that follow the element's '>', and after the '_' that should come first (VTK
  // takes a first character other than '_' as data). Searching for the first '_' instead
  // read the headers at another place than VTK did, which then allocated 2^52 bytes
  // (found by fuzz_read_vtp).
  std::size_t appended_data_start(std::size_t after_tag) const {
    std::size_t at = after_tag;
    while (at < bytes_.size() && (bytes_[at] == ' ' || bytes_[at] == '\t' || bytes_[at] == '\n' || bytes_[at] == '\r')) ++at;
    if (at < bytes_.size() && bytes_[at] == '_') ++at;
    return at;
  }

  std::string_view tag_at(std::size_t at) const {
    const std::size_t end = bytes_.find('>', at);
    if (end == std::string_view::npos) fail(at, "the tag is not closed with '>'; the file is cut off or damaged");
    return bytes_.substr(at, end - at);
  }

  std::uint64_t word(XmlDataReader& data, std::size_t at, const std::string& name) const {
    const auto raw = data.take(word_size_);
    if (!raw) fail(at, fmt::format("array {}: the file ends inside its data header; it is cut off", subdiv::quoted(shortened(name))));
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < word_size_; ++i) {
      const std::size_t k = big_endian_ ? i : word_size_ - 1 - i;
      v = (v << 8) | static_cast<unsigned char>((*raw)[k]);
    }
    return v;
  }

  XmlArrayData check_header(XmlDataReader data, std::size_t at, const std::string& name) const {
    const double budget = available_memory().bytes;
    if (compressor_.empty()) {
      const std::uint64_t size = word(data, at, name);
      if (double(size) > data.remaining())
        fail(at, fmt::format("array {} says {} bytes of data, but only {:.0f} follow; the file is cut off or its "
                             "header is damaged",
                             subdiv::quoted(shortened(name)), size, data.remaining()));
      return XmlArrayData{data, double(size), compressor_, 0, 0, {}};
    }
    const std::uint64_t blocks = word(data, at, name), block_size = word(data, at, name), last = word(data, at, name);
    // VTK divides by the block size, and takes the last block as no larger than the others.
    if (blocks > 0 && (block_size == 0 || last > block_size))
      fail(at, fmt::format("array {}: its data header gives blocks of {} bytes and a last block of {}; the "
                           "header is damaged",
                           subdiv::quoted(shortened(name)), block_size, last));
    // With a partial last block VTK takes the data's size as blocks x block size, less one
    // block, plus the last block: with no blocks that wraps round to about 2^64, and VTK
    // read block sizes that do not exist (a null dereference, found by fuzz_read_vtp).
    if (blocks == 0 && last != 0)
      fail(at, fmt::format("array {}: its data header gives no compressed blocks but a last block of {} bytes; "
                           "the header is damaged",
                           subdiv::quoted(shortened(name)), last));
    if (double(blocks) * double(word_size_) > data.remaining())
      fail(at, fmt::format("array {} says {} compressed blocks, more than the rest of the file can hold; its data "
                           "header is damaged",
                           subdiv::quoted(shortened(name)), blocks));
    double compressed = 0;
    std::vector<std::uint64_t> packed(blocks);
    for (std::uint64_t& size : packed) compressed += double(size = word(data, at, name));
    data.end_run();
    const double expanded = blocks == 0 ? 0 : double(blocks - 1) * double(block_size) + double(last ? last : block_size);
    const double possible = compressed * expansion_limit(compressor_) + 65536;
    if (compressed > data.remaining())
      fail(at, fmt::format("array {} has {:.0f} compressed bytes, but only {:.0f} follow; the file is cut off",
                           subdiv::quoted(shortened(name)), compressed, data.remaining()));
    // VTK allocates one buffer of the block size: a block size the data cannot fill is harmless
    // up to a modest bound (a small array written in large blocks, as write_vtp's 1 MB).
    const double any_block_size = 64.0 * (1 << 20);
    if (double(block_size) > std::max(possible, any_block_size) || double(last) > possible || expanded > possible)
      fail(at, fmt::format("array {}: its data header claims {} blocks of {} bytes from {:.0f} compressed bytes, "
                           "more than {} can produce; the header is damaged",
                           subdiv::quoted(shortened(name)), blocks, block_size, compressed, compressor_));
    if (expanded > budget) {
      const auto [need_text, have_text] = byte_sizes_compared(expanded, budget);
      fail(at, fmt::format("array {} decompresses to {}, more than the {} of memory available",
                           subdiv::quoted(shortened(name)), need_text, have_text));
    }
    return XmlArrayData{data, expanded, compressor_, block_size, last, std::move(packed)};
  }

  const fs::path& file_;
  std::string_view bytes_;
  std::size_t word_size_ = 4;
  bool big_endian_ = false;
  std::string compressor_;
};

}  // namespace

std::optional<std::string_view> xml_attribute(std::string_view tag, std::string_view name) {
  for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
    const bool starts = at > 0 && (tag[at - 1] == ' ' || tag[at - 1] == '\t' || tag[at - 1] == '\n' || tag[at - 1] == '\r');
    std::size_t p = at + name.size();
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t')) ++p;
    if (!starts || p >= tag.size() || tag[p] != '=') continue;
    ++p;
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t')) ++p;
    if (p >= tag.size() || (tag[p] != '"' && tag[p] != '\'')) return std::string_view();
    const char quote = tag[p];
    const std::size_t end = tag.find(quote, p + 1);
    if (end == std::string_view::npos) return tag.substr(p + 1);
    return tag.substr(p + 1, end - p - 1);
  }
  return std::nullopt;
}

std::vector<std::size_t> xml_array_elements(std::string_view head) {
  // The file's structure, and what VTK writes inside an array (its information keys).
  static constexpr std::string_view kNotArrays[] = {"VTKFile",   "PolyData", "Piece",  "FieldData", "PointData",
                                                    "CellData",  "Points",   "Verts",  "Lines",     "Strips",
                                                    "Polys",     "InformationKey", "Value"};
  std::vector<std::size_t> out;
  for (std::size_t at = head.find('<'); at != std::string_view::npos; at = head.find('<', at + 1)) {
    if (at + 1 >= head.size() || head[at + 1] == '/' || head[at + 1] == '!' || head[at + 1] == '?') continue;
    const std::string_view rest = head.substr(at + 1, 32);  // bounded: no rescan of a long run without '>'
    const std::string_view name = rest.substr(0, rest.find_first_of(" \t\r\n/>"));
    if (std::find(std::begin(kNotArrays), std::end(kNotArrays), name) == std::end(kNotArrays)) out.push_back(at);
  }
  return out;
}

std::map<std::size_t, XmlArrayData> check_vtp_data_headers(const fs::path& file, std::string_view bytes) {
  return HeaderChecker(file, bytes).run();
}

}  // namespace subdiv::io_detail
