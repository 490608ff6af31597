// Stanford PLY (ASCII and binary, either byte order). Hand-written rather than through
// OpenMesh: OpenMesh 9's reader stores coordinates as 32-bit floats even when the file
// holds doubles, and splits non-manifold faces by duplicating vertices; here doubles stay
// doubles and faces stay as written.
//
// Read: element vertex (x, y, z of any numeric type), element face (list property
// vertex_indices or vertex_index); the other scalar properties of vertices and faces become
// point and cell arrays (ply_properties.h: normals, colours, texture coordinates, name_k
// components). List properties besides the faces' indices, and other elements, are skipped.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "framework/io/ply_properties.h"
#include "framework/io/readers.h"
#include "framework/io/text_input.h"
#include "framework/util/error.h"
#include "framework/util/input_file.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class Format { Ascii, LittleEndian, BigEndian };

struct Property {
  std::string name;
  Type type = Type::Float32;
  bool list = false;
  Type count_type = Type::UInt8;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
};

bool parse_type(std::string_view name, Type& type) {
  struct Named {
    std::string_view name;
    Type type;
  };
  static constexpr Named kTypes[] = {
      {"char", Type::Int8},     {"int8", Type::Int8},       {"uchar", Type::UInt8},
      {"uint8", Type::UInt8},   {"short", Type::Int16},     {"int16", Type::Int16},
      {"ushort", Type::UInt16}, {"uint16", Type::UInt16},   {"int", Type::Int32},
      {"int32", Type::Int32},   {"uint", Type::UInt32},     {"uint32", Type::UInt32},
      {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64},
      {"float64", Type::Float64}};
  for (const Named& n : kTypes)
    if (n.name == name) return type = n.type, true;
  return false;
}

std::size_t type_size(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 0;
}

bool is_integer_type(Type t) { return t != Type::Float32 && t != Type::Float64; }

class HeaderParser {
public:
  HeaderParser(const fs::path& file, LineCursor& lines) : file_(file), lines_(lines) {}
  Header parse();

private:
  void format_line(Tokens& tokens);
  void element_line(Tokens& tokens);
  void property_line(Tokens& tokens);
  Type type(Tokens& tokens);
  [[noreturn]] void fail(std::string_view message) const {
    fail_at(file_, lines_.line_number(), message);
  }

  const fs::path& file_;
  LineCursor& lines_;
  Header header_;
  bool have_format_ = false;
};

Header HeaderParser::parse() {
  std::string_view line;
  if (!lines_.next(line) || line != "ply") fail("a PLY file must start with the line 'ply'");
  while (lines_.next(line)) {
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword) || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (!have_format_) fail("the header has no 'format' line");
      // Elements without properties take no bytes, so nothing bounds their count: a
      // count of 5e14 kept the reader busy for days (found by fuzz_read_ply).
      for (const Element& e : header_.elements)
        if (e.count > 0 && e.properties.empty())
          fail(fmt::format("element {} has {} entries but no properties; give its properties or leave it out",
                           subdiv::quoted(e.name), e.count));
      return std::move(header_);
    }
    if (keyword == "format") format_line(tokens);
    else if (keyword == "element") element_line(tokens);
    else if (keyword == "property") property_line(tokens);
    else fail(fmt::format("unknown header keyword {}; expected element, property, comment "
                          "or end_header", subdiv::quoted(keyword)));
  }
  fail("the header has no 'end_header' line");
}

void HeaderParser::format_line(Tokens& tokens) {
  std::string_view name;
  tokens.next(name);
  if (name == "ascii") header_.format = Format::Ascii;
  else if (name == "binary_little_endian") header_.format = Format::LittleEndian;
  else if (name == "binary_big_endian") header_.format = Format::BigEndian;
  else fail(fmt::format("unknown format {}; expected ascii, binary_little_endian or "
                        "binary_big_endian", subdiv::quoted(name)));
  have_format_ = true;
}

void HeaderParser::element_line(Tokens& tokens) {
  std::string_view name, count;
  Element e;
  if (!tokens.next(name) || !tokens.next(count) || !parse_integer(count, e.count) || e.count < 0)
    fail("expected 'element <name> <count>'");
  e.name = name;
  header_.elements.push_back(std::move(e));
}

Type HeaderParser::type(Tokens& tokens) {
  std::string_view name;
  Type t;
  if (!tokens.next(name) || !parse_type(name, t))
    fail(fmt::format("unknown property type {}; expected char, uchar, short, ushort, int, "
                     "uint, float or double", subdiv::quoted(name)));
  return t;
}

void HeaderParser::property_line(Tokens& tokens) {
  if (header_.elements.empty()) fail("a property line must follow an 'element' line");
  Property p;
  Tokens peek = tokens;
  std::string_view first;
  if (peek.next(first) && first == "list") {
    tokens = peek;
    p.list = true;
    p.count_type = type(tokens);
    if (!is_integer_type(p.count_type)) fail("a list's count type must be an integer type");
  }
  p.type = type(tokens);
  std::string_view name;
  if (!tokens.next(name)) fail("expected 'property <type> <name>'");
  p.name = name;
  header_.elements.back().properties.push_back(std::move(p));
}

// The values after the header, one at a time, in either encoding.
class Values {
public:
  Values(const fs::path& file, Format format, LineCursor& lines)
      : file_(file), format_(format), lines_(lines), bytes_(lines.remaining()) {}

  void set_context(const Element& e, long long index) {
    element_ = &e;
    index_ = index;
  }
  double next(Type type) { return format_ == Format::Ascii ? next_text(type) : next_binary(type); }
  // How many more values of `type` the data can hold at most (2 bytes a value in text: a
  // digit and a separator): a bound for reserving arrays that a hostile count cannot inflate.
  std::size_t most_values(Type type) const {
    const std::size_t bytes = format_ == Format::Ascii ? lines_.remaining().size() : bytes_.size();
    return bytes / (format_ == Format::Ascii ? 2 : type_size(type));
  }
  // "vertex 12": the element being read, for messages.
  std::string subject() const { return fmt::format("{} {}", element_->name, index_); }
  [[noreturn]] void fail(std::string_view message) const;

private:
  double next_text(Type type);
  double next_binary(Type type);

  const fs::path& file_;
  Format format_;
  LineCursor& lines_;
  Tokens tokens_{std::string_view()};
  std::string_view bytes_;
  const Element* element_ = nullptr;
  long long index_ = 0;
};

void Values::fail(std::string_view message) const {
  const std::string where = format_ == Format::Ascii
                                ? fmt::format("{}:{}", escaped(file_.string()), lines_.line_number())
                                : fmt::format("{} (binary data)", escaped(file_.string()));
  throw Error(fmt::format("{}: {}", where, message));
}

double Values::next_text(Type type) {
  std::string_view token;
  while (!tokens_.next(token)) {
    std::string_view line;
    if (!lines_.next(line))
      fail(fmt::format("the file ends inside {}; the header announces {} {} elements",
                       subject(), element_->count, element_->name));
    tokens_ = Tokens(line);
  }
  long long i;
  double d;
  if (is_integer_type(type) ? parse_integer(token, i) : parse_double(token, d))
    return is_integer_type(type) ? double(i) : d;
  fail(fmt::format("expected {} in {}, got {}",
                   is_integer_type(type) ? "an integer" : "a number", subject(), subdiv::quoted(token)));
}

template <typename T>
T load(const char* p, bool swap) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, p, sizeof(T));
  if (swap) std::reverse(raw, raw + sizeof(T));
  T value;
  std::memcpy(&value, raw, sizeof(T));
  return value;
}

double Values::next_binary(Type type) {
  const std::size_t size = type_size(type);
  if (bytes_.size() < size)
    fail(fmt::format("the file ends inside {}; the header announces {} {} elements",
                     subject(), element_->count, element_->name));
  const bool swap = (format_ == Format::LittleEndian) != (std::endian::native == std::endian::little);
  const char* p = bytes_.data();
  bytes_.remove_prefix(size);
  switch (type) {
    case Type::Int8: return load<std::int8_t>(p, swap);
    case Type::UInt8: return load<std::uint8_t>(p, swap);
    case Type::Int16: return load<std::int16_t>(p, swap);
    case Type::UInt16: return load<std::uint16_t>(p, swap);
    case Type::Int32: return load<std::int32_t>(p, swap);
    case Type::UInt32: return load<std::uint32_t>(p, swap);
    case Type::Float32: return load<float>(p, swap);
    case Type::Float64: return load<double>(p, swap);
  }
  return 0;
}

// The scalar properties of an element that become arrays: their values as read, per
// property, then grouped into DataArrays.
class PropertyColumns {
public:
  PropertyColumns(const Element& e, const std::vector<bool>& skip) : element_(e), skip_(skip), columns_(skip.size()) {}
  void add(std::size_t property, double value) {
    if (!skip_[property]) columns_[property].push_back(value);
  }
  std::vector<DataArray> arrays(long long count) const;

private:
  const Element& element_;
  std::vector<bool> skip_;
  std::vector<std::vector<double>> columns_;
};

std::vector<DataArray> PropertyColumns::arrays(long long count) const {
  std::vector<std::string> names;
  for (const Property& p : element_.properties) names.push_back(p.name);
  std::vector<DataArray> out;
  for (const PropertyGroup& g : group_properties(names, skip_)) {
    DataArray a{g.name, int(g.properties.size()), {}, true, g.role};
    for (int p : g.properties) a.integer = a.integer && is_integer_type(element_.properties[size_t(p)].type);
    a.values.resize(std::size_t(count) * g.properties.size());
    for (std::size_t k = 0; k < g.properties.size(); ++k)
      for (long long i = 0; i < count; ++i) a.values[std::size_t(i) * g.properties.size() + k] = columns_[std::size_t(g.properties[k])][std::size_t(i)];
    out.push_back(std::move(a));
  }
  return out;
}

class PlyReader {
public:
  explicit PlyReader(const fs::path& file) : file_(file) {}
  MeshData read();

private:
  void read_vertices(Values& values, const Element& e);
  void read_faces(Values& values, const Element& e);
  void skip(Values& values, const Element& e);

  const fs::path& file_;
  long long vertex_count_ = 0;
  MeshData mesh_;
};

int find_property(const Element& e, std::string_view name, bool list) {
  for (std::size_t i = 0; i < e.properties.size(); ++i)
    if (e.properties[i].name == name && e.properties[i].list == list) return int(i);
  return -1;
}

void skip_property(Values& values, const Property& p) {
  const long long n = p.list ? (long long)values.next(p.count_type) : 1;
  for (long long i = 0; i < n; ++i) values.next(p.type);
}

void PlyReader::read_vertices(Values& values, const Element& e) {
  const int axis[3] = {find_property(e, "x", false), find_property(e, "y", false),
                       find_property(e, "z", false)};
  for (int a : axis)
    if (a < 0)
      throw Error(fmt::format("{}: element vertex lacks one of the properties x, y, z",
                              escaped(file_.string())));
  std::vector<bool> not_data(e.properties.size());
  for (std::size_t i = 0; i < e.properties.size(); ++i)
    not_data[i] = e.properties[i].list || int(i) == axis[0] || int(i) == axis[1] || int(i) == axis[2];
  PropertyColumns data(e, not_data);
  // Grown once, not by doubling: each doubling of a 100 MB array copies it and faults in new pages.
  mesh_.positions.reserve(3 * std::min(std::size_t(e.count), values.most_values(e.properties[size_t(axis[0])].type)));
  for (long long v = 0; v < e.count; ++v) {
    values.set_context(e, v);
    double xyz[3] = {0, 0, 0};
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const Property& p = e.properties[i];
      if (p.list) { skip_property(values, p); continue; }
      const double value = values.next(p.type);
      data.add(i, value);
      for (int k = 0; k < 3; ++k)
        if (axis[k] == int(i)) xyz[k] = value;
    }
    for (double c : xyz)
      if (!std::isfinite(c))
        values.fail(fmt::format("vertex {} has a non-finite coordinate ({}); fix or remove it",
                                v, c));
    mesh_.positions.insert(mesh_.positions.end(), xyz, xyz + 3);
  }
  mesh_.point_data = data.arrays(e.count);
}

void PlyReader::read_faces(Values& values, const Element& e) {
  int list = find_property(e, "vertex_indices", true);
  if (list < 0) list = find_property(e, "vertex_index", true);
  if (list < 0)
    throw Error(fmt::format("{}: element face lacks the list property vertex_indices",
                            escaped(file_.string())));
  std::vector<bool> not_data(e.properties.size());
  for (std::size_t i = 0; i < e.properties.size(); ++i) not_data[i] = e.properties[i].list;
  PropertyColumns data(e, not_data);
  const Property& indices = e.properties[size_t(list)];
  mesh_.face_offsets.reserve(std::min(std::size_t(e.count), values.most_values(indices.count_type)) + 1);
  mesh_.face_vertices.reserve(std::min(4 * std::size_t(e.count), values.most_values(indices.type)));
  for (long long f = 0; f < e.count; ++f) {
    values.set_context(e, f);
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const Property& p = e.properties[i];
      if (!p.list) { data.add(i, values.next(p.type)); continue; }
      if (int(i) != list) { skip_property(values, p); continue; }
      const long long size = (long long)values.next(p.count_type);
      if (size < 3)
        values.fail(fmt::format("face {} has {} vertices; a face needs at least 3", f, size));
      for (long long k = 0; k < size; ++k) {
        const double v = values.next(p.type);
        if (v < 0 || v >= double(vertex_count_) || v != std::floor(v))
          values.fail(fmt::format("face {} refers to vertex {}, but the file has {} vertices "
                                  "(numbered from 0)", f, v, vertex_count_));
        mesh_.face_vertices.push_back(Index(v));
      }
      mesh_.face_offsets.push_back(Index(mesh_.face_vertices.size()));
    }
  }
  mesh_.cell_data = data.arrays(e.count);
}

void PlyReader::skip(Values& values, const Element& e) {
  for (long long i = 0; i < e.count; ++i) {
    values.set_context(e, i);
    for (const Property& p : e.properties) skip_property(values, p);
  }
}

// The most bytes the data of a binary PLY with this header can take, or nothing when no
// useful bound exists (ASCII text, lists counted by 16-bit or wider integers).
std::optional<double> largest_binary_data(const Header& header) {
  if (header.format == Format::Ascii) return std::nullopt;
  double bytes = 0;
  for (const Element& e : header.elements) {
    double per = 0;
    for (const Property& p : e.properties) {
      if (!p.list) {
        per += double(type_size(p.type));
        continue;
      }
      if (type_size(p.count_type) > 1) return std::nullopt;
      per += double(type_size(p.count_type)) + 255.0 * double(type_size(p.type));
    }
    bytes += double(e.count) * per;
  }
  return bytes;
}

// The header alone, read before the whole file: a file far larger than its header can
// describe (a 1 GB sparse file behind a three-vertex header) is refused before it is read.
void check_size_against_header(const fs::path& file) {
  check_input_file(file, "mesh");
  std::ifstream in(file, std::ios::binary);
  std::string head(64 * 1024, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  // The line "end_header" itself, not the word inside a property name (found by
  // fuzz_write_read: a property "vtkCompoend_header" cut the header short).
  std::size_t end = head.find("\nend_header\n");
  if (end == std::string::npos) end = head.find("\nend_header\r\n");
  if (end == std::string::npos) return;  // the full read reports it
  const std::size_t data = head.find('\n', end + 1);
  LineCursor lines(std::string_view(head).substr(0, data + 1));
  const Header header = HeaderParser(file, lines).parse();
  const std::optional<double> largest = largest_binary_data(header);
  std::error_code ec;
  const double size = double(fs::file_size(file, ec));
  if (largest && !ec && size > double(data + 1) + *largest + 4096)
    throw Error(fmt::format("{}: the file has {:.0f} bytes, but its header describes at most {:.0f} bytes of binary "
                            "data after the {}-byte header; the counts in the header are wrong or the file has data "
                            "that is not part of this mesh",
                            escaped(file.string()), size, *largest, data + 1));
}

MeshData PlyReader::read() {
  check_size_against_header(file_);
  const std::string text = read_whole_file(file_);
  LineCursor lines(text);
  const Header header = HeaderParser(file_, lines).parse();
  const auto has = [&](std::string_view name) {
    return std::any_of(header.elements.begin(), header.elements.end(),
                       [&](const Element& e) { return e.name == name; });
  };
  if (!has("vertex"))
    throw Error(fmt::format("{}: the header declares no 'element vertex'", escaped(file_.string())));
  for (const Element& e : header.elements)
    if (e.name == "vertex") vertex_count_ = e.count;
  if (vertex_count_ > std::numeric_limits<Index>::max())
    throw Error(fmt::format("{}: {} vertices are more than SubdivKit's 32-bit indices hold",
                            escaped(file_.string()), vertex_count_));
  Values values(file_, header.format, lines);
  for (const Element& e : header.elements) {
    if (e.name == "vertex") read_vertices(values, e);
    else if (e.name == "face") read_faces(values, e);
    else skip(values, e);
  }
  return std::move(mesh_);
}

}  // namespace

MeshData read_ply(const fs::path& file) { return PlyReader(file).read(); }

}  // namespace subdiv::io_detail
