// Object File Format (ASCII). Hand-written for the same reason as the OBJ reader: vertex
// and face order and non-manifold faces must reach the engine untouched.
//
// Layout: a header keyword ending in OFF (ST, C and N prefixes announce extra values per
// vertex, which are ignored), the counts "V F E" (on the keyword's line or the next), V
// vertex lines "x y z ...", F face lines "n i0 ... i(n-1) [colour]" with 0-based indices.
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

  const fs::path& file_;
  std::string text_;
  LineCursor lines_{std::string_view()};
  std::size_t line_ = 0;
  long long vertex_count_ = 0, face_count_ = 0;
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
  if (!parse_integer(token, value)) fail(fmt::format("expected {}, got '{}'", what, token));
  return value;
}

void OffReader::header() {
  Tokens tokens{std::string_view()};
  std::string_view keyword;
  if (!next_line(tokens) || !tokens.next(keyword) || keyword.size() < 3 ||
      keyword.substr(keyword.size() - 3) != "OFF")
    fail("expected the header keyword OFF (or COFF, NOFF, STOFF...) on the first line");
  if (keyword.find('4') != std::string_view::npos || keyword.find('n') != std::string_view::npos)
    fail(fmt::format("'{}' (homogeneous or n-dimensional OFF) is not supported; write plain "
                     "3D OFF",
                     keyword));
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
    if (!parse_double(token, c)) fail(fmt::format("expected a coordinate, got '{}'", token));
  }
  for (double c : xyz)
    if (!std::isfinite(c))
      fail(fmt::format("vertex {} has a non-finite coordinate ({}); fix or remove it", number, c));
  mesh_.positions.insert(mesh_.positions.end(), xyz, xyz + 3);
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
  // Anything after the indices is a colour, which the engine does not use.
  mesh_.face_offsets.push_back(Index(mesh_.face_vertices.size()));
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
  return std::move(mesh_);
}

}  // namespace

MeshData read_off(const fs::path& file) { return OffReader(file).read(); }

}  // namespace subdiv::io_detail
