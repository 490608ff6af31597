#include "framework/io/stl_check.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fmt/format.h>
#include <string>

#include "framework/io/text_input.h"
#include "framework/util/error.h"
#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kBinaryHeader = 84, kBinaryTriangle = 50;

std::uint32_t little_endian_u32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

float little_endian_f32(std::string_view bytes, std::size_t at) {
  const std::uint32_t bits = little_endian_u32(bytes, at);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// A binary STL is exactly its header plus 50 bytes per triangle (OpenMesh decides the
// same way).
bool is_binary(std::string_view bytes) {
  if (bytes.size() < kBinaryHeader) return false;
  const std::uint64_t triangles = little_endian_u32(bytes, 80);
  return bytes.size() == kBinaryHeader + kBinaryTriangle * triangles;
}

void check_binary(const fs::path& file, std::string_view bytes) {
  const std::size_t triangles = (bytes.size() - kBinaryHeader) / kBinaryTriangle;
  if (triangles == 0) throw Error(fmt::format("{}: the binary STL file has no triangles", escaped(file.string())));
  for (std::size_t t = 0; t < triangles; ++t)
    for (int c = 0; c < 9; ++c) {  // the 12 bytes of the normal are not used
      const float x = little_endian_f32(bytes, kBinaryHeader + t * kBinaryTriangle + 12 + 4 * c);
      if (!std::isfinite(x))
        throw Error(fmt::format("{}: triangle {} (0-based) has a non-finite coordinate ({}) at its vertex {}; fix "
                                "or remove the triangle",
                                escaped(file.string()), t, x, c / 3));
    }
}

// The ASCII grammar, one keyword per line:
//   solid NAME / facet normal nx ny nz / outer loop / vertex x y z (three times) /
//   endloop / endfacet / ... / endsolid NAME
class AsciiChecker {
public:
  AsciiChecker(const fs::path& file, std::string_view text) : file_(file), lines_(text) {}

  void run() {
    std::string_view line;
    while (lines_.next(line)) {
      Tokens tokens(line);
      std::string_view keyword;
      if (!tokens.next(keyword)) continue;
      step(keyword, tokens, line);
    }
    if (state_ != State::Outside && state_ != State::InSolid)
      fail(lines_.line_number(), fmt::format("the file ends inside a facet (after line {}); the file is cut off",
                                             lines_.line_number()));
    if (facets_ == 0)
      throw Error(fmt::format("{}: the ASCII STL file has no facets (each is 'facet normal nx ny nz', 'outer "
                              "loop', three 'vertex x y z' lines, 'endloop', 'endfacet')",
                              escaped(file_.string())));
  }

private:
  enum class State { Outside, InSolid, InFacet, InLoop, LoopDone };

  [[noreturn]] void fail(std::size_t line, const std::string& problem) const { fail_at(file_, line, problem); }

  void expect(bool ok, std::string_view line, const char* wanted) const {
    if (!ok)
      fail(lines_.line_number(), fmt::format("expected {}, found {}", wanted, subdiv::quoted(shortened(line))));
  }

  // Three numbers; coordinates must be finite, normals only well-formed (they are not used).
  void numbers(Tokens& tokens, std::string_view line, const char* what, bool finite) const {
    for (int i = 0; i < 3; ++i) {
      std::string_view token;
      double value;
      if (!tokens.next(token) || !parse_double(token, value))
        fail(lines_.line_number(), fmt::format("{} needs three numbers: {}", what, subdiv::quoted(shortened(line))));
      if (finite && !std::isfinite(value))
        fail(lines_.line_number(), fmt::format("{} coordinate {} is not a finite number; fix or remove the facet",
                                               what, subdiv::quoted(shortened(token))));
    }
    if (!tokens.empty())
      fail(lines_.line_number(), fmt::format("{} has more than three numbers: {}", what, subdiv::quoted(shortened(line))));
  }

  void step(std::string_view keyword, Tokens& tokens, std::string_view line) {
    switch (state_) {
      case State::Outside:
        expect(keyword == "solid", line, "'solid NAME' (an ASCII STL file starts with it)");
        state_ = State::InSolid;
        return;
      case State::InSolid:
        if (keyword == "endsolid") {
          state_ = State::Outside;
          return;
        }
        expect(keyword == "facet", line, "'facet normal nx ny nz' or 'endsolid'");
        {
          std::string_view normal;
          expect(tokens.next(normal) && normal == "normal", line, "'facet normal nx ny nz'");
        }
        numbers(tokens, line, "the facet normal", false);
        state_ = State::InFacet;
        return;
      case State::InFacet: {
        std::string_view loop;
        expect(keyword == "outer" && tokens.next(loop) && loop == "loop", line, "'outer loop'");
        state_ = State::InLoop;
        vertices_ = 0;
        return;
      }
      case State::InLoop:
        if (keyword == "endloop") {
          if (vertices_ != 3)
            fail(lines_.line_number(),
                 fmt::format("the facet has {} vertices; an STL facet is a triangle with exactly 3", vertices_));
          state_ = State::LoopDone;
          return;
        }
        expect(keyword == "vertex", line, "'vertex x y z' or 'endloop'");
        numbers(tokens, line, "vertex", true);
        ++vertices_;
        return;
      case State::LoopDone:
        expect(keyword == "endfacet", line, "'endfacet'");
        ++facets_;
        state_ = State::InSolid;
        return;
    }
  }

  const fs::path& file_;
  LineCursor lines_;
  State state_ = State::Outside;
  int vertices_ = 0;
  std::size_t facets_ = 0;
};

}  // namespace

void check_stl_text(const fs::path& file, std::string_view bytes) {
  if (is_binary(bytes)) return check_binary(file, bytes);
  if (without_utf8_bom(bytes).size() != bytes.size())
    throw Error(fmt::format("{}: the file starts with a UTF-8 byte-order mark (bytes EF BB BF), which STL readers "
                            "(OpenMesh's, ParaView's) take for a binary header; save the file without it (plain "
                            "ASCII or UTF-8 without BOM)",
                            escaped(file.string())));
  std::size_t start = 0;
  while (start < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[start]))) ++start;
  if (bytes.substr(start, 5) != "solid")
    throw Error(fmt::format("{}: not an STL file: an ASCII STL starts with 'solid', and a binary STL has an 84-byte "
                            "header and 50 bytes per triangle ({} bytes do not fit that); the file may be cut off",
                            escaped(file.string()), bytes.size()));
  AsciiChecker(file, bytes).run();
}

void check_stl_file(const fs::path& file) { check_stl_text(file, read_whole_file(file)); }

}  // namespace subdiv::io_detail
