#include "framework/io/vtk/vtp_layout.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <utility>

#include "framework/io/text_input.h"

namespace subdiv::io_detail {
namespace {

struct Decline {};  // anything the strict parser does not take: VTK's reader reads the file

void require(bool ok) {
  if (!ok) throw Decline{};
}

constexpr long long kMaxCount = std::numeric_limits<std::int32_t>::max();

bool blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool name_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool name_char(char c) { return name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.'; }

struct Tag {
  std::string_view name;
  std::vector<std::pair<std::string_view, std::string_view>> attributes;
  bool empty = false;  // <name ... />
  std::optional<std::string_view> get(std::string_view key) const {
    for (const auto& a : attributes)
      if (a.first == key) return a.second;
    return std::nullopt;
  }
};

class Parser {
public:
  explicit Parser(std::string_view text) : s_(text) {}

  VtpLayout run() {
    if (s_.substr(0, 5) == "<?xml") {
      constexpr std::string_view kProlog = "<?xml version=\"1.0\"?>";
      require(s_.substr(0, kProlog.size()) == kProlog);
      p_ = kProlog.size();
    }
    skip_blanks();
    const Tag root = open();
    require(root.name == "VTKFile" && !root.empty);
    file_attributes(root);
    skip_blanks();
    const Tag poly = open();
    require(poly.name == "PolyData" && poly.attributes.empty() && !poly.empty);
    bool piece_seen = false;
    for (;;) {
      skip_blanks();
      if (closing("PolyData")) break;
      const Tag tag = open();
      if (tag.name == "FieldData" && !piece_seen && layout_.field.empty()) {
        require(tag.attributes.empty());
        if (!tag.empty) layout_.field = arrays_until("FieldData", Where::Field);
        require(!layout_.field.empty());
      } else {
        require(tag.name == "Piece" && !piece_seen && !tag.empty);
        piece_seen = true;
        piece(tag);
      }
    }
    require(piece_seen);
    skip_blanks();
    if (closing("VTKFile")) {
      skip_blanks();
      require(p_ == s_.size());
      require(appended_ == 0);
    } else {
      appended(open());
    }
    resolve_offsets();
    return std::move(layout_);
  }

private:
  enum class Where { Field, Point, Cell, Points, Cells };

  void file_attributes(const Tag& root) {
    require(root.get("type") == "PolyData");
    const auto version = root.get("version");
    require(version == "1.0" || version == "0.1");
    require(root.get("byte_order") == "LittleEndian");
    const auto header = root.get("header_type");
    require(!header || header == "UInt32" || header == "UInt64");
    layout_.header_bytes = header == "UInt64" ? 8 : 4;
    const auto compressor = vtp_compressor_named(root.get("compressor").value_or(""));
    require(compressor.has_value());
    layout_.compressor = *compressor;
  }

  void piece(const Tag& tag) {
    layout_.points = count(tag, "NumberOfPoints");
    layout_.verts = count(tag, "NumberOfVerts");
    layout_.lines = count(tag, "NumberOfLines");
    layout_.strips = count(tag, "NumberOfStrips");
    layout_.polys = count(tag, "NumberOfPolys");
    std::set<std::string_view> seen;
    for (;;) {
      skip_blanks();
      if (closing("Piece")) return;
      const Tag section = open();
      require(seen.insert(section.name).second);
      if (section.name == "PointData" || section.name == "CellData") {
        VtpSection& out = section.name == "PointData" ? layout_.point_data : layout_.cell_data;
        attribute_names(section, out);
        if (!section.empty)
          out.arrays = arrays_until(section.name, section.name == "PointData" ? Where::Point : Where::Cell);
      } else if (section.name == "Points") {
        require(section.attributes.empty() && !section.empty);
        std::vector<VtpArray> arrays = arrays_until("Points", Where::Points);
        require(arrays.size() == 1 && arrays[0].components == 3);
        layout_.coordinates = std::move(arrays[0]);
      } else {
        static constexpr std::string_view kCells[] = {"Verts", "Lines", "Strips", "Polys"};
        const auto kind = std::find(std::begin(kCells), std::end(kCells), section.name);
        require(kind != std::end(kCells) && section.attributes.empty() && !section.empty);
        VtpCells& cells = layout_.cells[kind - std::begin(kCells)];
        cells.present = true;
        const std::vector<VtpArray> arrays = arrays_until(section.name, Where::Cells);
        require(arrays.size() == 2 && arrays[0].name != arrays[1].name);
        for (const VtpArray& a : arrays) {
          require(a.components == 1 && !vtp_type_is_float(a.type));
          if (a.name == "connectivity") cells.connectivity = a;
          else if (a.name == "offsets") cells.offsets = a;
          else throw Decline{};
        }
      }
    }
  }

  // VTK makes these active (vtkXMLDataReader::ReadAttributeIndices); only the roles the
  // conversion uses are kept, the others must be absent.
  void attribute_names(const Tag& section, VtpSection& out) {
    for (const auto& [key, value] : section.attributes) {
      if (key == "Normals") out.normals = value;
      else if (key == "TCoords") out.tcoords = value;
      else if (key == "Scalars") out.scalars = value;
      else throw Decline{};
    }
  }

  static long long count(const Tag& tag, std::string_view key) {
    const auto text = tag.get(key);
    long long v = 0;
    require(text && parse_integer(*text, v) && v >= 0 && v <= kMaxCount);
    return v;
  }

  std::vector<VtpArray> arrays_until(std::string_view section, Where where) {
    std::vector<VtpArray> out;
    std::set<std::string> names;
    for (;;) {
      skip_blanks();
      if (closing(section)) return out;
      const Tag tag = open();
      require(tag.name == "DataArray");
      out.push_back(array(tag, where));
      require(names.insert(out.back().name).second);
    }
  }

  VtpArray array(const Tag& tag, Where where) {
    VtpArray a;
    const auto type = vtp_type_named(tag.get("type").value_or(""));
    require(type.has_value());
    a.type = *type;
    // VTK's reader fails on some unnamed arrays: those are left to it.
    a.name = std::string(tag.get("Name").value_or(""));
    require(!a.name.empty());
    if (const auto c = tag.get("NumberOfComponents")) {
      long long v = 0;
      require(parse_integer(*c, v) && v >= 1 && v <= 64);
      a.components = int(v);
    }
    const auto tuples = tag.get("NumberOfTuples");
    require(bool(tuples) == (where == Where::Field));
    if (tuples) a.tuples = count(tag, "NumberOfTuples");
    const auto format = tag.get("format");
    if (const auto offset = tag.get("offset")) {
      long long v = 0;
      require(format == "appended" && parse_integer(*offset, v) && v >= 0);
      a.at = std::size_t(v);  // from the appended data's start, resolved at the end
      a.inline_text = false;
      ++appended_;
      if (!tag.empty) information_until_close();
      return a;
    }
    require(format == "binary" && !tag.empty);
    a.inline_text = true;
    skip_blanks();
    a.at = p_;
    const std::size_t lt = s_.find('<', p_);
    require(lt != std::string_view::npos);
    a.end = lt;
    p_ = lt;
    information_until_close();
    return a;
  }

  // VTK's writer puts the L2 norm range of point coordinates after the data
  // (vtkDataArray::L2_NORM_RANGE); the fast reader takes only that form.
  void information_until_close() {
    for (;;) {
      skip_blanks();
      if (closing("DataArray")) return;
      const Tag key = open();
      require(key.name == "InformationKey" && !key.empty);
      const auto name = key.get("name");
      require((name == "L2_NORM_RANGE" || name == "L2_NORM_FINITE_RANGE") && key.get("location") == "vtkDataArray" &&
              key.get("length") == "2" && key.attributes.size() == 3);
      for (const char* index : {"0", "1"}) {
        skip_blanks();
        const Tag value = open();
        require(value.name == "Value" && !value.empty && value.attributes.size() == 1 && value.get("index") == index);
        const std::size_t lt = s_.find('<', p_);
        require(lt != std::string_view::npos);
        require(plain_number(trimmed(s_.substr(p_, lt - p_))));
        p_ = lt;
        require(closing("Value"));
      }
      skip_blanks();
      require(closing("InformationKey"));
    }
  }

  // A number VTK's stream reads as it is: no sign '+', nothing out of range (VTK refuses an
  // overflow, e.g. "0.8e540378"), no nan or inf. Anything else is left to VTK's reader.
  static bool plain_number(std::string_view t) {
    double x;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    return ec == std::errc() && end == t.data() + t.size() && !t.empty() && std::isfinite(x);
  }

  static std::string_view trimmed(std::string_view t) {
    while (!t.empty() && blank(t.front())) t.remove_prefix(1);
    while (!t.empty() && blank(t.back())) t.remove_suffix(1);
    return t;
  }

  // <AppendedData encoding="raw|base64"> then blanks and '_' (where VTK's
  // vtkXMLDataParser::FindAppendedDataPosition starts the data).
  void appended(const Tag& tag) {
    require(tag.name == "AppendedData" && !tag.empty && tag.attributes.size() == 1);
    const auto encoding = tag.get("encoding");
    require(encoding == "raw" || encoding == "base64");
    appended_base64_ = encoding == "base64";
    skip_blanks();
    require(p_ < s_.size() && s_[p_] == '_');
    appended_start_ = p_ + 1;
  }

  void resolve_offsets() {
    if (appended_ == 0) return;
    require(appended_start_ != std::string_view::npos);
    const auto fix = [&](VtpArray& a) {
      if (a.inline_text) return;
      require(a.at <= s_.size() - appended_start_);
      a.at += appended_start_;
      a.end = s_.size();
      a.base64 = appended_base64_;
    };
    for (VtpArray& a : layout_.field) fix(a);
    for (VtpArray& a : layout_.point_data.arrays) fix(a);
    for (VtpArray& a : layout_.cell_data.arrays) fix(a);
    if (layout_.coordinates) fix(*layout_.coordinates);
    for (VtpCells& c : layout_.cells)
      if (c.present) fix(c.connectivity), fix(c.offsets);
  }

  void skip_blanks() {
    while (p_ < s_.size() && blank(s_[p_])) ++p_;
  }

  bool closing(std::string_view name) {
    if (s_.compare(p_, 2, "</") != 0 || s_.compare(p_ + 2, name.size(), name) != 0) return false;
    std::size_t q = p_ + 2 + name.size();
    while (q < s_.size() && blank(s_[q])) ++q;
    require(q < s_.size() && s_[q] == '>');
    p_ = q + 1;
    return true;
  }

  std::string_view name_at() {
    require(p_ < s_.size() && name_start(s_[p_]));
    const std::size_t from = p_;
    while (p_ < s_.size() && name_char(s_[p_])) ++p_;
    return s_.substr(from, p_ - from);
  }

  // A start tag: name, attributes (double- or single-quoted, no entities, no '<'), no
  // attribute twice, blanks between them, '>' or '/>'.
  Tag open() {
    require(p_ < s_.size() && s_[p_] == '<');
    ++p_;
    Tag tag;
    tag.name = name_at();
    for (;;) {
      const std::size_t before = p_;
      skip_blanks();
      require(p_ < s_.size());
      if (s_[p_] == '>') return ++p_, tag;
      if (s_[p_] == '/') {
        require(s_.compare(p_, 2, "/>") == 0);
        p_ += 2;
        tag.empty = true;
        return tag;
      }
      require(p_ > before);  // XML needs a blank before each attribute
      const std::string_view key = name_at();
      skip_blanks();
      require(p_ < s_.size() && s_[p_] == '=');
      ++p_;
      skip_blanks();
      require(p_ < s_.size() && (s_[p_] == '"' || s_[p_] == '\''));
      const char quote = s_[p_++];
      const std::size_t end = s_.find(quote, p_);
      require(end != std::string_view::npos);
      const std::string_view value = s_.substr(p_, end - p_);
      // Printable ASCII without markup: vtk_xml_check.cpp's scan of the tags (each up to its
      // first '>', attributes found by name and '=') then sees the same attributes.
      for (const char c : value)
        require(c >= 0x20 && c < 0x7f && c != '<' && c != '>' && c != '&' && c != '=' && c != '"' && c != '\'');
      require(!tag.get(key));
      tag.attributes.emplace_back(key, value);
      p_ = end + 1;
    }
  }

  std::string_view s_;
  std::size_t p_ = 0;
  VtpLayout layout_;
  std::size_t appended_ = 0;
  std::size_t appended_start_ = std::string_view::npos;
  bool appended_base64_ = true;
};

}  // namespace

std::size_t vtp_type_size(VtpType type) {
  switch (type) {
    case VtpType::Int8: case VtpType::UInt8: return 1;
    case VtpType::Int16: case VtpType::UInt16: return 2;
    case VtpType::Int32: case VtpType::UInt32: case VtpType::Float32: return 4;
    default: return 8;
  }
}

bool vtp_type_is_float(VtpType type) { return type == VtpType::Float32 || type == VtpType::Float64; }

std::optional<VtpType> vtp_type_named(std::string_view name) {
  static constexpr std::pair<std::string_view, VtpType> kTypes[] = {
      {"Int8", VtpType::Int8},     {"UInt8", VtpType::UInt8},   {"Int16", VtpType::Int16},
      {"UInt16", VtpType::UInt16}, {"Int32", VtpType::Int32},   {"UInt32", VtpType::UInt32},
      {"Int64", VtpType::Int64},   {"UInt64", VtpType::UInt64}, {"Float32", VtpType::Float32},
      {"Float64", VtpType::Float64}};
  const auto found = std::find_if(std::begin(kTypes), std::end(kTypes), [&](const auto& t) { return t.first == name; });
  if (found == std::end(kTypes)) return std::nullopt;
  return found->second;
}

std::optional<VtpCompressor> vtp_compressor_named(std::string_view name) {
  if (name.empty()) return VtpCompressor::None;
  if (name == "vtkZLibDataCompressor") return VtpCompressor::ZLib;
  if (name == "vtkLZ4DataCompressor") return VtpCompressor::LZ4;
  if (name == "vtkLZMADataCompressor") return VtpCompressor::LZMA;
  return std::nullopt;
}

std::optional<VtpLayout> parse_vtp_layout(std::string_view file) {
  try {
    return Parser(file).run();
  } catch (const Decline&) {
    return std::nullopt;
  }
}

}  // namespace subdiv::io_detail
