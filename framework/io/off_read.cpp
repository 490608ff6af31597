// Object File Format (ASCII). Hand-written for the same reason as the OBJ reader: vertex
// and face order and non-manifold faces must reach the engine untouched.
//
// Layout: a header keyword ending in OFF, the counts "V F E" (on the keyword's line or the
// next), V vertex lines, F face lines "n i0 ... i(n-1) [colour]" with 0-based indices. The
// keyword's prefixes announce extra values per vertex, after x y z in Geomview's order:
// N a normal (nx ny nz), C a colour (r g b [a]), ST texture coordinates (s t); they become
// point arrays "normal", "color" and "uv". Face colours (3 or 4 values after the indices,
// on every face) become the cell array "color".
// '#' starts a comment. One vertex or face per line, as every writer produces, so that
// messages can name the line.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "framework/io/readers.h"
#include "framework/io/text_input.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

class OffReader {
public:
  explicit OffReader(const fs::path& file) : file_(file) {}
  MeshData read();

private:
  bool next_line(Tokens& tokens);  // skips blank and comment lines
  void header();
  void vertex(Tokens& tokens, Index number);
  void face(Tokens& tokens);
  long long integer(Tokens& tokens, std::string_view what);
  [[noreturn]] void fail(std::string_view message) const { fail_at(file_, line_, message); }

  void finish_arrays();

  const fs::path& file_;
  std::string text_;
  LineCursor lines_{std::string_view()};
  std::size_t line_ = 0;
  long long vertex_count_ = 0, face_count_ = 0;
  bool normals_ = false, colors_ = false, uvs_ = false;  // the keyword's N, C, ST
  std::vector<double> normal_, color_, uv_, face_color_;
  int color_components_ = 0, face_color_components_ = -1;  // -1: not seen yet
  bool face_colors_ = true;
  MeshData mesh_;
};

bool OffReader::next_line(Tokens& tokens) {
  std::string_view raw;
  while (lines_.next(raw)) {
    line_ = lines_.line_number();
    const std::string_view line = strip_comment(raw);
    if (!line.empty()) {
      tokens = Tokens(line);
      return true;
    }
  }
  return false;
}

long long OffReader::integer(Tokens& tokens, std::string_view what) {
  std::string_view token;
  long long value;
  if (!tokens.next(token)) fail(fmt::format("expected {}, but the line ends", what));
  if (!parse_integer(token, value)) fail(fmt::format("expected {}, got {}", what, subdiv::quoted(token)));
  return value;
}

void OffReader::header() {
  Tokens tokens{std::string_view()};
  std::string_view keyword;
  if (!next_line(tokens) || !tokens.next(keyword) || keyword.size() < 3 ||
      keyword.substr(keyword.size() - 3) != "OFF")
    fail("expected the header keyword OFF (or COFF, NOFF, STOFF...) on the first line");
  if (keyword.find('4') != std::string_view::npos || keyword.find('n') != std::string_view::npos)
    fail(fmt::format("{} (homogeneous or n-dimensional OFF) is not supported; write plain "
                     "3D OFF",
                     subdiv::quoted(keyword)));
  const std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  normals_ = prefix.find('N') != std::string_view::npos;
  colors_ = prefix.find('C') != std::string_view::npos;
  uvs_ = prefix.find("ST") != std::string_view::npos;
  std::string_view token;
  Tokens counts = tokens;
  if (counts.empty() && !next_line(counts)) fail("expected the counts 'vertices faces edges'");
  if (Tokens peek = counts; peek.next(token) && token == "BINARY")
    fail("binary OFF is not supported; save the mesh as ASCII OFF, OBJ or PLY");
  vertex_count_ = integer(counts, "the vertex count");
  face_count_ = integer(counts, "the face count");
  if (vertex_count_ < 0 || face_count_ < 0 ||
      vertex_count_ > std::numeric_limits<Index>::max() ||
      face_count_ > std::numeric_limits<Index>::max())
    fail(fmt::format("counts {} {} are out of range", vertex_count_, face_count_));
}

void OffReader::vertex(Tokens& tokens, Index number) {
  double xyz[3];
  std::string_view token;
  for (double& c : xyz) {
    if (!tokens.next(token))
      fail(fmt::format("vertex {} needs 3 coordinates 'x y z'", number));
    if (!parse_double(token, c)) fail(fmt::format("expected a coordinate, got {}", subdiv::quoted(token)));
  }
  for (double c : xyz)
    if (!std::isfinite(c))
      fail(fmt::format("vertex {} has a non-finite coordinate ({}); fix or remove it", number, c));
  mesh_.positions.insert(mesh_.positions.end(), xyz, xyz + 3);
  if (!normals_ && !colors_ && !uvs_) return;
  std::vector<double> extra;
  while (tokens.next(token)) {
    double x;
    if (!parse_double(token, x)) fail(fmt::format("vertex {}: expected a number, got {}", number, subdiv::quoted(token)));
    extra.push_back(x);
  }
  const std::size_t needed = (normals_ ? 3 : 0) + (colors_ ? 3 : 0) + (uvs_ ? 2 : 0);
  if (extra.size() < needed || extra.size() > needed + (colors_ ? 1 : 0))
    fail(fmt::format("vertex {} has {} values after x y z; the keyword announces {}{}{}", number, extra.size(),
                     normals_ ? "a normal (3) " : "", colors_ ? "a colour (3 or 4) " : "", uvs_ ? "s t (2)" : ""));
  auto at = extra.begin();
  if (normals_) normal_.insert(normal_.end(), at, at + 3), at += 3;
  if (colors_) {
    const int components = int(extra.end() - at) - (uvs_ ? 2 : 0);
    if (color_components_ && components != color_components_)
      fail(fmt::format("vertex {} has a colour of {} values, the vertices before it {}", number, components,
                       color_components_));
    color_components_ = components;
    color_.insert(color_.end(), at, at + components), at += components;
  }
  if (uvs_) uv_.insert(uv_.end(), at, at + 2);
}

void OffReader::face(Tokens& tokens) {
  const long long size = integer(tokens, "the face's vertex count");
  if (size < 3)
    fail(fmt::format("a face needs at least 3 vertices, this one has {}", size));
  for (long long k = 0; k < size; ++k) {
    const long long v = integer(tokens, fmt::format("{} vertex indices", size));
    if (v < 0 || v >= vertex_count_)
      fail(fmt::format("face refers to vertex {}, but the file has {} vertices (OFF numbers "
                       "them from 0)",
                       v, vertex_count_));
    mesh_.face_vertices.push_back(Index(v));
  }
  mesh_.face_offsets.push_back(Index(mesh_.face_vertices.size()));
  // After the indices: a colour (r g b [a]) when every face has one; else nothing is kept.
  std::vector<double> colour;
  std::string_view token;
  double x;
  while (tokens.next(token) && parse_double(token, x)) colour.push_back(x);
  const int components = colour.size() == 3 || colour.size() == 4 ? int(colour.size()) : 0;
  if (face_color_components_ < 0) face_color_components_ = components;
  face_colors_ = face_colors_ && components > 0 && components == face_color_components_;
  if (face_colors_) face_color_.insert(face_color_.end(), colour.begin(), colour.end());
}

// Whole numbers above 1 are colours on the 0..255 scale; integers only where an int holds
// them (a whole 6e293 taken for an integer was refused by the checks of integer arrays:
// found by fuzz_write_read, an OFF that SubdivKit wrote and could not read back).
bool integer_colours(const std::vector<double>& values) {
  bool whole = true, above_one = false;
  for (double c : values)
    whole = whole && c == std::floor(c) && std::abs(c) <= 2147483647.0, above_one = above_one || c > 1;
  return whole && above_one;
}

void OffReader::finish_arrays() {
  if (normals_) mesh_.point_data.push_back({"normal", 3, std::move(normal_), false, ArrayRole::Normals});
  if (colors_) {
    const bool integer = integer_colours(color_);
    mesh_.point_data.push_back({"color", color_components_, std::move(color_), integer, ArrayRole::Color});
  }
  if (uvs_) mesh_.point_data.push_back({"uv", 2, std::move(uv_), false, ArrayRole::TextureCoordinates});
  if (face_colors_ && face_count_ > 0)
    mesh_.cell_data.push_back({"color", face_color_components_, face_color_, integer_colours(face_color_),
                               ArrayRole::Color});
}

MeshData OffReader::read() {
  text_ = read_whole_file(file_);
  lines_ = LineCursor(text_);
  header();
  Tokens tokens{std::string_view()};
  // A lying header must not make us reserve gigabytes: a vertex line has at least 6 bytes.
  mesh_.positions.reserve(std::size_t(std::min<long long>(vertex_count_, text_.size() / 6)) * 3);
  for (Index v = 0; v < vertex_count_; ++v) {
    if (!next_line(tokens))
      fail_at(file_, lines_.line_number(),
              fmt::format("the file ends after {} of the {} vertices its header announces", v,
                          vertex_count_));
    vertex(tokens, v);
  }
  for (Index f = 0; f < face_count_; ++f) {
    if (!next_line(tokens))
      fail_at(file_, lines_.line_number(),
              fmt::format("the file ends after {} of the {} faces its header announces", f,
                          face_count_));
    face(tokens);
  }
  finish_arrays();
  return std::move(mesh_);
}

}  // namespace

MeshData read_off(const fs::path& file) { return OffReader(file).read(); }

}  // namespace subdiv::io_detail
