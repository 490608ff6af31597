#include "framework/io/vtk/vtk_xml_check.h"

#include <algorithm>
#include <cstdint>
#include <fmt/format.h>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "framework/io/text_input.h"
#include "framework/io/vtk/vtk_array_lengths_check.h"
#include "framework/io/vtk/vtk_xml_blocks.h"
#include "framework/util/error.h"
#include "framework/util/byte_size_text.h"
#include "framework/util/memory_limit.h"
#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

constexpr long long kMaxCount = std::numeric_limits<std::int32_t>::max();
// The most components a data array may have: positions have 3, tensors 9.
constexpr long long kMaxComponents = 64;
// Bytes per point and per cell VTK and the conversion hold: coordinates as doubles in
// VTK and in MeshData, plus offsets and about four ids per cell in both.
constexpr double kBytesPerPoint = 2 * 3 * 8, kBytesPerCell = 2 * (8 + 4 * 8);

std::size_t line_of(std::string_view text, std::size_t at) {
  return 1 + std::size_t(std::count(text.begin(), text.begin() + std::min(at, text.size()), '\n'));
}

class XmlChecker {
public:
  XmlChecker(const fs::path& file, std::string_view bytes) : file_(file), bytes_(bytes) {}

  void run() {
    // The appended binary data may contain anything; tags are only before it.
    const std::size_t appended = bytes_.find("<AppendedData");
    const std::string_view head = bytes_.substr(0, appended);
    double points = 0, cells = 0;
    for (std::size_t at = head.find("<Piece"); at != std::string_view::npos; at = head.find("<Piece", at + 1)) {
      const std::string_view tag = tag_at(head, at);
      points += count(tag, at, "NumberOfPoints");
      for (const char* c : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
        cells += count(tag, at, c);
    }
    const std::vector<std::size_t> arrays = xml_array_elements(head);
    for (const std::size_t at : arrays) {
      const std::string_view tag = tag_at(head, at);
      // An unknown type makes VTK's reader dereference a null array (found by fuzz_read_vtp).
      static constexpr std::string_view kTypes[] = {"Int8",   "UInt8",  "Int16", "UInt16",  "Int32",  "UInt32",
                                                    "Int64",  "UInt64", "Float32", "Float64", "String"};
      const auto type = xml_attribute(tag, "type");
      if (!type || std::find(std::begin(kTypes), std::end(kTypes), *type) == std::end(kTypes))
        fail(at, fmt::format("DataArray type=\"{}\" is not a VTK type (Int8 ... UInt64, Float32, Float64, String)",
                             escaped(shortened(type.value_or("")))));
      // Points need their three components said: VTK reads one otherwise, fails and leaks.
      if (xml_attribute(tag, "Name").value_or("") == "Points" && !xml_attribute(tag, "NumberOfComponents"))
        fail(at, "the Points array needs NumberOfComponents=\"3\"");
      if (const auto c = xml_attribute(tag, "NumberOfComponents")) {
        long long v;
        if (!parse_integer(*c, v) || v < 1 || v > kMaxComponents)
          fail(at, fmt::format("NumberOfComponents=\"{}\" must be a whole number from 1 to {}", escaped(shortened(*c)),
                               kMaxComponents));
      }
    }
    sections(head, arrays);
    const double need = points * kBytesPerPoint + cells * kBytesPerCell;
    const MemoryBudget budget = available_memory();
    if (need > budget.bytes) {
      const auto [need_text, have_text] = byte_sizes_compared(need, budget.bytes);
      throw Error(fmt::format("cannot read {}: its {:.3g} points and {:.3g} cells would need about {}, but only {} of "
                              "memory is available (limited by {}); the sizes in its <Piece> are wrong, or the mesh is "
                              "too large for this machine",
                              subdiv::quoted(file_.string()), points, cells, need_text, have_text, budget.source));
    }
  }

private:
  [[noreturn]] void fail(std::size_t at, const std::string& problem) const {
    throw Error(fmt::format("{}:{}: {}", escaped(file_.string()), line_of(bytes_, at), problem));
  }

  // Calls visit(section_start, array_start) for each array element inside each
  // <section ...> ... </section> of `head`. One pass: each search starts where the last
  // section ended.
  template <class Visit>
  void for_each_array_in(std::string_view head, const std::vector<std::size_t>& arrays, std::string_view section,
                         Visit visit) const {
    const std::string open = fmt::format("<{}", section), close = fmt::format("</{}", section);
    for (std::size_t at = head.find(open); at != std::string_view::npos;) {
      const std::size_t end = std::min(head.find(close, at), head.size());
      for (auto a = std::lower_bound(arrays.begin(), arrays.end(), at); a != arrays.end() && *a < end; ++a)
        visit(at, *a);
      at = end < head.size() ? head.find(open, end) : std::string_view::npos;
    }
  }

  void sections(std::string_view head, const std::vector<std::size_t>& arrays) const {
    // Field data arrays are sized by their own NumberOfTuples; VTK's reader leaks the array
    // when it is missing (found by fuzz_read_vtp under LeakSanitizer), so it is required.
    for_each_array_in(head, arrays, "FieldData", [&](std::size_t, std::size_t a) {
      const auto tuples = xml_attribute(tag_at(head, a), "NumberOfTuples");
      long long v;
      if (!tuples || !parse_integer(*tuples, v) || v < 0 || v > kMaxCount)
        fail(a, fmt::format("a field data array needs NumberOfTuples, a whole number from 0 to {}", kMaxCount));
    });
    // String arrays: VTK's reader crashes on point or cell strings fewer than the tuples
    // (found by hand: one string for three points), and SubdivKit refines numbers only, so
    // they are refused before VTK parses them, as the reader would refuse them after. Field
    // data (labels, which SubdivKit does not read) may hold strings: sized by NumberOfTuples.
    std::set<std::size_t> field_arrays;
    for_each_array_in(head, arrays, "FieldData", [&](std::size_t, std::size_t a) { field_arrays.insert(a); });
    for (const std::size_t a : arrays) {
      const std::string_view tag = tag_at(head, a);
      if (xml_attribute(tag, "type").value_or("") != "String" || field_arrays.count(a)) continue;
      const std::size_t point = head.rfind("<PointData", a), cell = head.rfind("<CellData", a);
      const bool is_point = point != std::string_view::npos && (cell == std::string_view::npos || point > cell);
      fail(a, fmt::format("{} array {} is not numeric (a String array); SubdivKit refines numbers only: remove it "
                          "or convert it",
                          is_point ? "point" : "cell", subdiv::quoted(shortened(xml_attribute(tag, "Name").value_or("")))));
    }
    // Cell connectivity and offsets are indices: VTK converts any type silently (Float64
    // 3.7 became vertex 3), so only integer types are taken.
    for (const std::string_view section : {"Verts", "Lines", "Strips", "Polys"})
      for_each_array_in(head, arrays, section, [&](std::size_t, std::size_t a) {
        const std::string_view tag = tag_at(head, a);
        const std::string_view type = xml_attribute(tag, "type").value_or("");
        if (type.rfind("Int", 0) != 0 && type.rfind("UInt", 0) != 0)
          fail(a, fmt::format("<{}> array {} has type {}; cell connectivity and offsets must have an integer type "
                              "(Int32 or Int64)",
                              section, subdiv::quoted(shortened(xml_attribute(tag, "Name").value_or(""))), shortened(type)));
      });
    // VTK creates one array per name but reads every element: a second array of the same
    // name in one section made it read into an array it never created (a null
    // dereference, found by fuzz_read_vtp).
    for (const std::string_view section : {"FieldData", "PointData", "CellData"}) {
      std::size_t current = std::string_view::npos;
      std::set<std::string_view> names;
      for_each_array_in(head, arrays, section, [&](std::size_t section_at, std::size_t a) {
        if (section_at != current) current = section_at, names.clear();
        const auto name = xml_attribute(tag_at(head, a), "Name");
        if (!name) return;
        if (!names.insert(*name).second)
          fail(a, fmt::format("a second array named {} in the same <{}>; array names must differ",
                              subdiv::quoted(shortened(*name)), section));
      });
    }
  }

  std::string_view tag_at(std::string_view head, std::size_t at) const {
    const std::size_t end = head.find('>', at);
    if (end == std::string_view::npos) fail(at, "the tag is not closed with '>'; the file is cut off or damaged");
    return head.substr(at, end - at);
  }

  double count(std::string_view tag, std::size_t at, const char* name) const {
    const auto value = xml_attribute(tag, name);
    if (!value) return 0;
    long long v;
    if (!parse_integer(*value, v) || v < 0)
      fail(at, fmt::format("{}=\"{}\" must be a whole number >= 0", name, escaped(shortened(*value))));
    if (v > kMaxCount)
      fail(at, fmt::format("{}=\"{}\" is more than SubdivKit's 32-bit indices hold ({})", name, v, kMaxCount));
    return double(v);
  }

  const fs::path& file_;
  std::string_view bytes_;
};

}  // namespace

void check_vtp_text(const fs::path& file, std::string_view bytes) {
  XmlChecker(file, bytes).run();
  check_vtp_array_lengths(file, bytes, check_vtp_data_headers(file, bytes));
}

void check_vtp_file(const fs::path& file) { check_vtp_text(file, read_whole_file(file)); }

}  // namespace subdiv::io_detail
