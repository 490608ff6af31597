#include "framework/io/vtk/vtk_legacy_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fmt/format.h>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "framework/io/text_input.h"
#include "framework/util/error.h"
#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

// Bytes per value in BINARY files; 0 for types this check does not know.
std::size_t binary_size(const std::string& type) {
  if (type == "unsigned_char" || type == "char" || type == "vtktypeint8" || type == "vtktypeuint8") return 1;
  if (type == "unsigned_short" || type == "short" || type == "vtktypeint16" || type == "vtktypeuint16") return 2;
  if (type == "unsigned_int" || type == "int" || type == "float" || type == "vtkidtype" || type == "vtktypeint32" ||
      type == "vtktypeuint32" || type == "vtktypefloat32")
    return 4;
  if (type == "unsigned_long" || type == "long" || type == "double" || type == "vtktypeint64" ||
      type == "vtktypeuint64" || type == "vtktypefloat64" || type == "unsigned_long_long" || type == "long_long")
    return 8;
  return 0;
}

constexpr std::uint64_t kMaxPoints = std::uint64_t(std::numeric_limits<std::int32_t>::max());

class LegacyChecker {
public:
  LegacyChecker(const fs::path& file, std::string_view bytes) : file_(file), bytes_(bytes) {}

  // Byte ranges of the METADATA blocks, for blanking.
  const std::vector<std::pair<std::size_t, std::size_t>>& metadata_blocks() const { return metadata_; }

  void run() {
    header();
    while (auto keyword = next_token()) {
      const std::string k = lower(*keyword);
      if (k == "points") points();
      else if (k == "vertices" || k == "lines" || k == "polygons" || k == "triangle_strips") cells(k);
      else if (k == "point_data" || k == "cell_data") attributes(k);
      else if (k == "field") field(kUnknownTuples);
      else if (k == "metadata") metadata();
      else fail(fmt::format("unknown section {}; a POLYDATA file has POINTS, VERTICES, LINES, POLYGONS, "
                            "TRIANGLE_STRIPS, POINT_DATA, CELL_DATA and FIELD",
                            subdiv::quoted(shortened(*keyword))));
    }
    if (!seen_points_) fail("the file has no POINTS section");
  }

private:
  static constexpr std::uint64_t kUnknownTuples = std::numeric_limits<std::uint64_t>::max();

  [[noreturn]] void fail(const std::string& problem) const {
    if (in_binary_data_) throw Error(fmt::format("{}: byte {}: {}", escaped(file_.string()), pos_, problem));
    throw Error(fmt::format("{}:{}: {}", escaped(file_.string()), line_, problem));
  }

  // Past binary data, line ends in the data make line numbers useless: binary files are
  // named by byte.
  [[noreturn]] void fail_at(std::size_t byte, std::size_t line, const std::string& problem) {
    in_binary_data_ = binary_;
    pos_ = byte;
    line_ = line;
    fail(problem);
  }

  std::size_t remaining() const { return bytes_.size() - pos_; }

  // One raw line (the header's first lines may hold anything).
  std::string_view raw_line() {
    if (pos_ >= bytes_.size()) fail("the file ends inside its header; it is cut off");
    std::size_t end = bytes_.find('\n', pos_);
    if (end == std::string_view::npos) end = bytes_.size();
    std::string_view line = bytes_.substr(pos_, end - pos_);
    pos_ = std::min(end + 1, bytes_.size());
    ++line_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
  }

  std::optional<std::string_view> next_token() {
    while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= bytes_.size()) return std::nullopt;
    const std::size_t begin = pos_;
    while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
    // VTK reads words into 256-byte buffers: a longer one is split in two, and the reader
    // takes its second half for the next word while this check would not.
    if (pos_ - begin > 255)
      fail(fmt::format("a word of {} characters ({}); VTK's reader reads words of at most 255 and would split it",
                       pos_ - begin, subdiv::quoted(shortened(bytes_.substr(begin, pos_ - begin)))));
    return bytes_.substr(begin, pos_ - begin);
  }

  std::string_view token(const char* what) {
    const auto t = next_token();
    if (!t) fail(fmt::format("the file ends where {} should be; it is cut off", what));
    return *t;
  }

  std::uint64_t count(const char* what) {
    const std::string_view t = token(what);
    long long v;
    if (!parse_integer(t, v) || v < 0)
      fail(fmt::format("{} must be a whole number >= 0, found {}", what, subdiv::quoted(shortened(t))));
    return std::uint64_t(v);
  }

  // The end of the keyword line; binary data starts after it. VTK skips the rest of the
  // line with getline() into a 256-byte buffer, which fails on longer or unterminated
  // lines and then crashes the reader (found by fuzz_read_vtk): only blanks may follow.
  void end_of_line() {
    const std::size_t end = bytes_.find('\n', pos_);
    if (end == std::string_view::npos) fail("the file ends before the binary data that should follow; it is cut off");
    if (bytes_.substr(pos_, end - pos_).find_first_not_of(" \t\r") != std::string_view::npos)
      fail("unexpected text after the keyword line; binary data must start on the next line");
    pos_ = end + 1;
    ++line_;
  }

  void header() {
    const std::string_view first = raw_line();
    constexpr std::string_view kMagic = "# vtk DataFile Version";
    if (first.rfind(kMagic, 0) != 0)
      line_ = 1, fail("not a legacy VTK file: the first line must be '# vtk DataFile Version x.y'");
    // VTK lays cells out as OFFSETS + CONNECTIVITY from major version 5 on, as it reads
    // the version (an integer before the dot), and as the old counted lists before.
    // Both numbers must be there: VTK falls back to old rules when it cannot read them.
    Tokens version(first.substr(kMagic.size()));
    std::string_view number;
    long long major = -1, minor = -1;
    const std::size_t dot = version.next(number) ? number.find('.') : std::string_view::npos;
    if (dot == std::string_view::npos || !parse_integer(number.substr(0, dot), major) ||
        !parse_integer(number.substr(dot + 1), minor) || major < 0 || minor < 0 || !version.empty())
      line_ = 1, fail("the first line must be '# vtk DataFile Version x.y' with a version such as 3.0 or 5.1");
    offsets_layout_ = major >= 5;
    raw_line();  // the title: any text
    const std::string format = lower(token("ASCII or BINARY"));
    if (format != "ascii" && format != "binary")
      fail(fmt::format("the third line must say ASCII or BINARY, not {}", subdiv::quoted(shortened(format))));
    binary_ = format == "binary";
    if (lower(token("DATASET")) != "dataset") fail("expected 'DATASET POLYDATA' after ASCII or BINARY");
    const std::string type = lower(token("the dataset type"));
    if (type != "polydata")
      fail(fmt::format("it is not a legacy VTK file with POLYDATA but {} (other dataset types are not surfaces "
                       "this tool refines)",
                       shortened(type)));
  }

  // Checks that `n` values of `type` can be in the rest of the file before walking them:
  // ASCII values take at least two bytes each (a digit and a separator).
  void require_room(std::uint64_t n, std::size_t value_bytes, const char* what) {
    const std::uint64_t per = binary_ ? value_bytes : 2;
    if (per != 0 && n > remaining() / per)
      fail(fmt::format("{} says {} values, but only {} bytes follow; the file is cut off or the count is wrong",
                       what, n, remaining()));
  }

  // Walks `n` values; `visit` sees each as a double (for checks on coordinates and ids).
  template <class Visit>
  void values(std::uint64_t n, const std::string& type, const char* what, Visit visit) {
    const std::size_t size = binary_size(type);
    if (size == 0 && type != "bit")
      fail(fmt::format("{} has data type {}, which SubdivKit does not read; use float, double or an integer type",
                       what, subdiv::quoted(shortened(type))));
    if (type == "bit") {  // packed 8 to a byte; holds no coordinates or ids
      if (binary_) {
        end_of_line();
        skip_bytes((n + 7) / 8, what);
      } else {
        require_room(n, 1, what);
        // VTK reads each as an integer; one that is not fails the array, and a failed FIELD
        // array made VTK dereference a null pointer (found by fuzz_read_vtk).
        for (std::uint64_t i = 0; i < n; ++i) {
          const std::string_view t = token(what);
          long long v;
          if (!parse_integer(t, v)) fail(fmt::format("{}: {} is not a bit (0 or 1)", what, subdiv::quoted(shortened(t))));
        }
      }
      blanks_after_data();
      return;
    }
    if (binary_) end_of_line();  // binary data starts on the next line: count only its bytes
    require_room(n, size, what);
    if (binary_) {
      in_binary_data_ = true;
      for (std::uint64_t i = 0; i < n; ++i) visit(binary_value(type, size));
      in_binary_data_ = false;
      blanks_after_data();
      return;
    }
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::string_view t = token(what);
      double v;
      if (!parse_double(t, v)) fail(fmt::format("{}: {} is not a number", what, subdiv::quoted(shortened(t))));
      visit(v);
    }
    blanks_after_data();
  }

  void skip_bytes(std::uint64_t n, const char* what) {
    if (n > remaining())
      fail(fmt::format("{} needs {} bytes of data, but only {} follow; the file is cut off", what, n, remaining()));
    pos_ += n;
  }

  // Legacy binary data is big-endian.
  double binary_value(const std::string& type, std::size_t size) {
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < size; ++i) bits = (bits << 8) | static_cast<unsigned char>(bytes_[pos_ + i]);
    pos_ += size;
    if (type == "float" || type == "vtktypefloat32") {
      std::uint32_t b32 = std::uint32_t(bits);
      float f;
      std::memcpy(&f, &b32, 4);
      return f;
    }
    if (type == "double" || type == "vtktypefloat64") {
      double d;
      std::memcpy(&d, &bits, 8);
      return d;
    }
    const bool is_signed = type.find("unsigned") == std::string::npos && type.find("uint") == std::string::npos;
    if (is_signed && size < 8 && (bits >> (8 * size - 1)) != 0) return -double((std::uint64_t(1) << (8 * size)) - bits);
    return is_signed ? double(std::int64_t(bits)) : double(bits);
  }

  void points() {
    if (seen_points_) fail("a second POINTS section");
    seen_points_ = true;
    points_ = count("the number of points");
    if (points_ > kMaxPoints)
      fail(fmt::format("{} points are more than SubdivKit's 32-bit indices hold", points_));
    const std::string type = lower(token("the points' data type"));
    std::uint64_t i = 0;
    values(3 * points_, type, "POINTS", [&](double v) {
      if (!std::isfinite(v)) fail(fmt::format("point {} has a non-finite coordinate ({}); fix or remove it", i / 3, v));
      ++i;
    });
  }

  std::uint64_t point_index(double v, const char* what) {
    if (!(v >= 0) || v >= double(points_) || v != std::floor(v))
      fail(fmt::format("{} names point {}, but the file has {} points (numbered from 0) before it", what, v, points_));
    return std::uint64_t(v);
  }

  void cells(const std::string& keyword) {
    const char* what = keyword == "polygons" ? "POLYGONS" : keyword == "lines" ? "LINES"
                       : keyword == "vertices" ? "VERTICES" : "TRIANGLE_STRIPS";
    const std::uint64_t first = count("the number of cells"), second = count("the size of the cell list");
    cells_ += first;
    if (offsets_layout_) return cells_51(what, first, second);
    // Before VTK 5.1: `second` integers, each cell its size and then its point ids.
    std::uint64_t left_in_cell = 0, cells_done = 0;
    values(second, "int", what, [&](double v) {
      if (left_in_cell > 0) {
        point_index(v, what);
        --left_in_cell;
        return;
      }
      if (cells_done == first) fail(fmt::format("{} has more data than its {} cells", what, first));
      if (!(v >= 0) || v != std::floor(v) || v > double(second))
        fail(fmt::format("{}: cell {} has size {}, which cannot be", what, cells_done, v));
      left_in_cell = std::uint64_t(v);
      ++cells_done;
    });
    if (cells_done != first || left_in_cell != 0)
      fail(fmt::format("{} says {} cells in {} numbers, but the numbers hold {} cells{}", what, first, second,
                       cells_done, left_in_cell ? " and end inside one" : ""));
  }

  // VTK 5.1: OFFSETS (cells + 1 of them) and CONNECTIVITY, each with its own type.
  void cells_51(const char* what, std::uint64_t offsets, std::uint64_t connectivity) {
    if (offsets > 0) --cells_;  // counted as cells by the caller; there is one offset more than cells
    if (lower(token("OFFSETS")) != "offsets")
      fail(fmt::format("{}: expected OFFSETS (files of version 5 and later list cells as OFFSETS and "
                       "CONNECTIVITY)", what));
    const std::string offset_type = lower(token("the offsets' data type"));
    std::uint64_t i = 0;
    double previous = 0;
    values(offsets, offset_type, what, [&](double v) {
      if ((i == 0 && v != 0) || v < previous || v > double(connectivity) || v != std::floor(v))
        fail(fmt::format("{}: offset {} is {}; offsets start at 0, never decrease and end at {}", what, i, v,
                         connectivity));
      previous = v;
      ++i;
    });
    if (offsets > 0 && previous != double(connectivity))
      fail(fmt::format("{}: the offsets end at {}, not at the connectivity's size {}", what, previous, connectivity));
    if (lower(token("CONNECTIVITY")) != "connectivity") fail(fmt::format("{}: expected CONNECTIVITY", what));
    const std::string id_type = lower(token("the connectivity's data type"));
    values(connectivity, id_type, what, [&](double v) { point_index(v, what); });
  }

  void attributes(const std::string& keyword) {
    const bool on_points = keyword == "point_data";
    const std::uint64_t n = count(on_points ? "the POINT_DATA count" : "the CELL_DATA count");
    // VTK sizes the arrays by these counts; readers index them by point and cell.
    if (on_points && n != points_)
      fail(fmt::format("POINT_DATA {} does not match the {} points", n, points_));
    if (!on_points && n != cells_)
      fail(fmt::format("CELL_DATA {} does not match the {} cells", n, cells_));
    // Sections of this block follow until the next dataset keyword.
    for (;;) {
      const std::size_t mark = pos_, mark_line = line_;
      const auto t = next_token();
      if (!t) return;
      const std::string k = lower(*t);
      if (k == "scalars") {
        token("the array name");
        const std::string type = lower(token("the data type"));
        std::uint64_t components = 1;
        const std::size_t mark2 = pos_, mark2_line = line_;
        const auto maybe = next_token();
        long long c;
        if (maybe && parse_integer(*maybe, c)) {
          if (c < 1 || c > 4) fail(fmt::format("SCALARS with {} components; VTK allows 1 to 4", c));
          components = std::uint64_t(c);
        } else {
          pos_ = mark2, line_ = mark2_line;
        }
        const std::size_t mark3 = pos_, mark3_line = line_;
        const auto lut = next_token();
        if (lut && lower(*lut) == "lookup_table") token("the lookup table name");
        else pos_ = mark3, line_ = mark3_line;
        values(n * components, type, "SCALARS", [](double) {});
      } else if (k == "color_scalars") {
        token("the array name");
        const std::uint64_t components = count("the number of values");
        if (components > 4) fail(fmt::format("COLOR_SCALARS with {} values; VTK allows 1 to 4", components));
        values(n * components, binary_ ? "unsigned_char" : "float", "COLOR_SCALARS", [](double) {});
      } else if (k == "lookup_table") {
        token("the table name");
        const std::uint64_t size = count("the table size");
        require_room(size, 4, "LOOKUP_TABLE");
        values(4 * size, binary_ ? "unsigned_char" : "float", "LOOKUP_TABLE", [](double) {});
      } else if (k == "vectors" || k == "normals") {
        token("the array name");
        values(3 * n, lower(token("the data type")), "VECTORS/NORMALS", [](double) {});
      } else if (k == "tensors" || k == "tensors6") {
        token("the array name");
        values((k == "tensors" ? 9 : 6) * n, lower(token("the data type")), "TENSORS", [](double) {});
      } else if (k == "texture_coordinates") {
        token("the array name");
        const std::uint64_t dim = count("the dimension");
        if (dim < 1 || dim > 3) fail(fmt::format("TEXTURE_COORDINATES of dimension {}; VTK allows 1 to 3", dim));
        values(dim * n, lower(token("the data type")), "TEXTURE_COORDINATES", [](double) {});
      } else if (k == "global_ids" || k == "pedigree_ids") {
        token("the array name");
        values(n, lower(token("the data type")), "GLOBAL_IDS/PEDIGREE_IDS", [](double) {});
      } else if (k == "field") {
        field(n);
      } else if (k == "metadata") {
        metadata();
      } else {
        pos_ = mark, line_ = mark_line;  // the next dataset section
        return;
      }
    }
  }

  // FIELD name arrays, then per array: name components tuples type, then the values.
  void field(std::uint64_t tuples_expected) {
    token("the field name");
    const std::uint64_t arrays = count("the number of field arrays");
    require_room(arrays, 8, "FIELD");
    for (std::uint64_t a = 0; a < arrays; ++a) {
      const std::string_view name = token("the array name");
      if (lower(name) == "null_array") continue;
      const std::uint64_t components = count("the number of components");
      const std::uint64_t tuples = count("the number of tuples");
      (void)tuples_expected;
      if (components == 0 || components > 1024 || tuples > remaining())
        fail(fmt::format("field array {} has {} components and {} tuples, which cannot fit in the file",
                         subdiv::quoted(shortened(name)), components, tuples));
      const std::string type = lower(token("the data type"));
      if (type == "string" || type == "utf8_string" || type == "variant")
        fail(fmt::format("field array {} holds {}; SubdivKit reads only numeric arrays", subdiv::quoted(shortened(name)), type));
      values(components * tuples, type, "FIELD array", [](double) {});
      const std::size_t mark = pos_, mark_line = line_;
      const auto t = next_token();
      if (t && lower(*t) == "metadata") metadata();
      else pos_ = mark, line_ = mark_line;
    }
  }

  // METADATA blocks (component names, information keys) are text lines ended by an empty
  // line, as VTK writes and reads them. Inside, VTK's reader follows rules of its own:
  // lines cut at 255 bytes, a line starting with a 0 byte taken as the end, information
  // keys read word by word across lines by key types known only at run time. A check
  // cannot follow all that (a block it ended elsewhere than VTK let VTK read cells past
  // the end of the file: found by fuzz_read_vtk), so SubdivKit, which uses none of it,
  // records the block here and gives VTK the file with the block blanked out
  // (check_legacy_vtk_text). Blocks without their empty line or holding 0 bytes, which
  // VTK would read differently, are refused.
  void metadata() {
    const std::size_t start = pos_ - std::strlen("metadata"), start_line = line_;  // the keyword was just read
    constexpr const char* kUnended = "the METADATA block has no empty line to end it; the file is cut off or damaged";
    if (bytes_.find('\n', pos_) == std::string_view::npos) fail_at(start, start_line, kUnended);
    end_of_line();
    for (;;) {
      if (pos_ >= bytes_.size()) fail_at(start, start_line, kUnended);
      const std::size_t at = pos_, line = line_;
      const std::string_view text = raw_line();
      if (text.find('\0') != std::string_view::npos)
        fail_at(at, line, "a METADATA line holds a 0 byte; METADATA is text (component names, information keys)");
      if (text.empty()) break;
    }
    metadata_.emplace_back(start, pos_);
    blanks_after_data();
  }

  // After an array's data, VTK's reader skips spaces, '\r' and line ends while it looks
  // for METADATA, 256 bytes at a time: 256 spaces or '\r' without a line end in between
  // never end that loop (a hang in VTK 9.1).
  void blanks_after_data() {
    std::size_t run = 0, lines = 0;
    for (std::size_t at = pos_; at < bytes_.size(); ++at) {
      const char c = bytes_[at];
      if (c == '\n') run = 0, ++lines;
      else if (c == ' ' || c == '\r') ++run;
      else break;
      if (run >= 256)
        fail_at(at + 1 - run, line_ + lines,
                "256 or more blanks after an array's data: VTK's reader never gets past them (a hang); remove them");
    }
  }

  const fs::path& file_;
  std::string_view bytes_;
  std::vector<std::pair<std::size_t, std::size_t>> metadata_;
  std::size_t pos_ = 0, line_ = 1;
  bool binary_ = false, in_binary_data_ = false, seen_points_ = false, offsets_layout_ = false;
  std::uint64_t points_ = 0, cells_ = 0;
};

}  // namespace

std::optional<std::string> check_legacy_vtk_text(const fs::path& file, std::string_view bytes) {
  LegacyChecker checker(file, bytes);
  checker.run();
  if (checker.metadata_blocks().empty()) return std::nullopt;
  // Line ends in place of each block: VTK sees empty lines there, and every byte and line
  // after the block stays where the check found it.
  std::string text(bytes);
  for (const auto& [begin, end] : checker.metadata_blocks()) std::fill(text.begin() + begin, text.begin() + end, '\n');
  return text;
}

std::optional<std::string> check_legacy_vtk_file(const fs::path& file) {
  return check_legacy_vtk_text(file, read_whole_file(file));
}

}  // namespace subdiv::io_detail
