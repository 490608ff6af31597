// The OBJ reader's parallel fast path (framework/io/obj_fast_parse.h): for every file it
// takes, the same MeshData as the line-by-line reader, for any number of chunks; everything
// else it declines, so that read_obj's result and error messages (file and line) are the
// line-by-line reader's.
#include <algorithm>
#include <iterator>
#include <optional>
#include <random>
#include <string>

#include <fmt/format.h>

#include "framework/io/obj_fast_parse.h"
#include "framework/io/readers.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

void check_same(const MeshData& a, const MeshData& b) {
  CHECK(a.positions == b.positions);
  CHECK(a.face_offsets == b.face_offsets);
  CHECK(a.face_vertices == b.face_vertices);
  CHECK(a.line_offsets == b.line_offsets);
  CHECK(a.line_vertices == b.line_vertices);
  CHECK(a.creases.size() == b.creases.size());
  CHECK(a.corners.size() == b.corners.size());
  CHECK(a.holes == b.holes);
  CHECK(a.options.any() == b.options.any());
  CHECK(a.point_data.size() == b.point_data.size());
  CHECK(a.cell_data.size() == b.cell_data.size());
  CHECK(a.warnings == b.warnings);
  REQUIRE(a.face_varying.size() == b.face_varying.size());
  for (std::size_t i = 0; i < a.face_varying.size(); ++i) {
    CHECK(a.face_varying[i].name == b.face_varying[i].name);
    CHECK(a.face_varying[i].components == b.face_varying[i].components);
    CHECK(a.face_varying[i].values == b.face_varying[i].values);
    CHECK(a.face_varying[i].indices == b.face_varying[i].indices);
    CHECK(a.face_varying[i].role == b.face_varying[i].role);
  }
}

// The fast path takes `text` on 1 to 7 chunks and gives the line-by-line reader's mesh.
void check_taken(const std::string& text) {
  TempDir dir;
  write_text(dir / "m.obj", text);
  const MeshData reference = io_detail::read_obj_line_by_line(dir / "m.obj");
  for (std::size_t chunks = 1; chunks <= 7; ++chunks) {
    CAPTURE(chunks);
    const std::optional<MeshData> fast = io_detail::parse_obj_fast(text, chunks);
    REQUIRE(fast.has_value());
    check_same(*fast, reference);
  }
  check_same(io_detail::read_obj(dir / "m.obj"), reference);
}

// The fast path declines `text` on any chunking, and read_obj gives what the line-by-line
// reader gives: the same mesh (and warnings), or the same error message.
void check_declined(const std::string& text) {
  TempDir dir;
  write_text(dir / "m.obj", text);
  for (std::size_t chunks = 1; chunks <= 7; ++chunks) {
    CAPTURE(chunks);
    CHECK_FALSE(io_detail::parse_obj_fast(text, chunks).has_value());
  }
  const std::string expected = error_of([&] { io_detail::read_obj_line_by_line(dir / "m.obj"); });
  CHECK(error_of([&] { io_detail::read_obj(dir / "m.obj"); }) == expected);
  if (expected == "<no error>") check_same(io_detail::read_obj(dir / "m.obj"), io_detail::read_obj_line_by_line(dir / "m.obj"));
}

// An n x n grid of quads with texture coordinates and a normal per face corner, with
// comments, groups and the reference forms mixed in; `crlf` ends lines with "\r\n".
std::string grid(int n, bool crlf) {
  const char* eol = crlf ? "\r\n" : "\n";
  std::string text = fmt::format("# grid {}{}mtllib grid.mtl{}o grid{}", n, eol, eol, eol);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      text += fmt::format("v {} {} {:.9f}{}", i, j, 0.001 * i * j, eol);
      text += fmt::format("vt {} +{}{}", i / double(n), j / double(n), eol);
    }
  text += fmt::format("vn 0 0 1{}vn 0 0 -1e-0   # two normals{}", eol, eol);
  const auto v = [&](int i, int j) { return j * (n + 1) + i + 1; };
  for (int j = 0; j < n; ++j) {
    if (j % 7 == 0) text += fmt::format("g row{}{}s off{}", j, eol, eol);
    for (int i = 0; i < n; ++i) {
      const int a = v(i, j), b = v(i + 1, j), c = v(i + 1, j + 1), d = v(i, j + 1);
      if ((i + j) % 3 == 0)  // a relative vt number: counts back from the last vt
        text += fmt::format("f {}/{}/1 {}/{}/1 {}/{}/2 {}/{}/2{}", a, a, b, b, c, c - v(n, n) - 1, d, d, eol);
      else
        text += fmt::format("f\t{}/{}/1  {}/{}/1 {}/{}/2 {}/{}/2 # face{}", a, a, b, b, c, c, d, d, eol);
    }
  }
  return text;
}

}  // namespace

TEST_CASE("obj fast path: the line-by-line reader's mesh on simple files, any chunking") {
  check_taken("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  check_taken("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3");  // no final line end
  check_taken("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
  check_taken("# only a comment\n\n   \n");
  check_taken("");
  check_taken("v 0 0 0\nv +1.5 -2e-3 4 0.5 0.5 0.5\nv 0 1 0#c\nf 1 2 3#c\nf -3 -2 -1\n");
  check_taken("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");  // forward references
  check_taken("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/-1/-1\n");
  check_taken("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 2//1 3//1/9\n");
  check_taken("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n");
  check_taken("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\n# vt unused by faces\nf 1 2 3\n");
  check_taken("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\ncstype bspline\nvp 0.5\nf 1 2 3\n");
  check_taken("v 1e-320 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");  // a denormal is a number
}

TEST_CASE("obj fast path: a rational weight (v x y z w) is left to the line-by-line reader") {
  // The weights become the point array "weight" (pipeline/rational_weights.h); only the
  // line-by-line reader makes it, naming the line of a weight that is not positive.
  CHECK_FALSE(io_detail::parse_obj_fast("v 0 0 0 2\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 1).has_value());
  TempDir dir;
  write_text(dir / "w.obj", "v 0 0 0\nv 1 0 0 2.5\nv 0 1 0\nf 1 2 3\n");
  const MeshData m = io_detail::read_obj(dir / "w.obj");
  REQUIRE(m.point_data.size() == 1);
  CHECK(m.point_data[0].name == "weight");
  CHECK(m.point_data[0].values == std::vector<double>{1, 2.5, 1});  // 1 where a line has no w (the OBJ spec)
  write_text(dir / "bad.obj", "v 0 0 0\nv 1 0 0 -1\nv 0 1 0\nf 1 2 3\n");
  CHECK(error_of([&] { io_detail::read_obj(dir / "bad.obj"); }).find("bad.obj:2: vertex 2 has the weight w = -1") !=
        std::string::npos);
}

TEST_CASE("obj fast path: a large grid with vt, vn, comments, groups and relative numbers, LF and CRLF") {
  for (bool crlf : {false, true}) {
    CAPTURE(crlf);
    const std::string text = grid(60, crlf);
    check_taken(text);
    TempDir dir;
    write_text(dir / "grid.obj", text);
    const MeshData m = io_detail::read_obj(dir / "grid.obj");
    CHECK(m.face_count() == 3600);
    REQUIRE(m.face_varying.size() == 2);
    CHECK(m.face_varying[0].name == "uv");
    CHECK(m.face_varying[1].name == "normal");
  }
}

TEST_CASE("obj fast path: declines what only the line-by-line reader handles, which gives the same result") {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  // Not errors: tags, polylines, continuations, lone '\r', out-of-range numbers, a
  // channel some faces give and others not (a warning).
  check_declined(tri + "f 1 2 3\nt crease 2/1/0 0 1 10\n");
  check_declined(tri + "f 1 2 3\nl 1 2\n");
  check_declined(tri + "f 1 2 \\\n 3\n");
  check_declined(tri + "g a \\\nb\nf 1 2 3\n");
  check_declined(tri + "# comment\rf 1 2 3\n");
  check_declined("v 0 0 0\rv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  check_declined(tri + "f 1 2 3\r\r\n");
  // A lone '\r' inside the comment after a statement starts a new line for that reader.
  check_declined(tri + "f 1 2 3 # c\rx 1\n");
  check_declined(tri + "vt 0.75 0.3\t# End\ri 0.3\n");
  check_declined("v 0 0 0 # c\rf 1 2 3\nv 1 0 0\nv 0 1 0\n");
  check_declined("v 1e-400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  check_declined(tri + "vt 0 0\nf 1/1 2/1 3/1\nf 1 2 3\n");
  // Errors: the same message, naming the same line.
  check_declined(tri + "f 1 2 x\n");
  check_declined(tri + "f 1 2 0\n");
  check_declined(tri + "f 1 2 4\n");
  check_declined(tri + "f -4 -2 -1\n");
  check_declined(tri + "f 1 2\n");
  check_declined("v 0 0\n");
  check_declined("v 0 nan 0\n");
  check_declined("v 0 1e999 0\n");
  check_declined("v 0 +-1 0\n");  // a '+' before a sign: not a number to either reader
  check_declined(tri + "vt 0 0\nvt 0 0 0\nf 1/1 2/1 3/1\n");
  check_declined(tri + "vt 0 0\nf 1/2 2/1 3/1\n");
  check_declined(tri + "vt 0 0\nf 1/-2 2/1 3/1\n");
  check_declined(tri + "f 1/x 2 3\n");
  check_declined(tri + "f 99999999999 2 3\n");
}

TEST_CASE("obj fast path: an error deep in a large file names its line, whatever the chunks") {
  std::string text = grid(60, false);
  const std::size_t lines = std::size_t(std::count(text.begin(), text.end(), '\n'));
  text += "f 1 2 3 4\nf 1 2 bad\nf 1 2 3\n";
  TempDir dir;
  write_text(dir / "bad.obj", text);
  for (std::size_t chunks = 1; chunks <= 7; ++chunks) CHECK_FALSE(io_detail::parse_obj_fast(text, chunks).has_value());
  const std::string message = error_of([&] { io_detail::read_obj(dir / "bad.obj"); });
  CHECK(message.find(fmt::format("bad.obj:{}:", lines + 2)) != std::string::npos);
  CHECK(message.find("'bad'") != std::string::npos);
}

TEST_CASE("obj fast path: random files from valid and broken lines, against the line-by-line reader") {
  // Lines the fast path takes, lines it declines, and errors; joined in random order with
  // "\n" or "\r\n", cut into random chunk counts. Whenever the fast path answers, it must
  // be the line-by-line reader's mesh; read_obj must always give that reader's result.
  const char* pool[] = {"v 1 2 3",       "v -1e5 +2 3.25 1", "v 0 0 0",         "vt 0.5 0.25",   "vt 1",
                        "vn 0 0 1",      "f 1 2 3",          "f -1 -2 -3",      "f 1/1 2/2 3/3", "f 1//1 2//1 3//1",
                        "f 1/1/1 2/-1/1 3/1/1", "f 4 5 6 7",  "# comment",       "g a b",         "",
                        "   ",           "s off",            "v 1 2",           "f 1 2",         "f 1/0 2 3",
                        "v nan 0 0",     "f 99 1 2",         "vt 1 2 3",        "f 1 2 3 \\",    "t crease 2/1/0 0 1 1",
                        "l 1 2",         "f 0 1 2",          "v 1 2 3 # c",     "f 1 2 3#c",     "v 1\r2 3",
                        "vt 0 1 # c\rx"};
  // Every other file from plain-geometry lines only, so that the fast path answers often.
  const char* plain[] = {"v 1 2 3", "v -1e5 +2 3.25", "v 0 0 0", "# comment", "g a b", "", "   ", "s off",
                         "f 1 2 3", "f -1 -2 -3", "f 1 2 3#c", "v 1 2 3 # c", "vt 0.5 0.25", "vn 0 0 1"};
  std::mt19937 random(6);
  TempDir dir;
  int answered = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string text;
    const int lines = 1 + int(random() % 30);
    const char* eol = random() % 4 == 0 ? "\r\n" : "\n";
    for (int i = 0; i < lines; ++i)
      text += std::string(trial % 2 ? pool[random() % std::size(pool)] : plain[random() % std::size(plain)]) + eol;
    CAPTURE(text);
    write_text(dir / "r.obj", text);
    std::optional<MeshData> reference;
    const std::string error = error_of([&] { reference = io_detail::read_obj_line_by_line(dir / "r.obj"); });
    const std::size_t chunks = 1 + random() % 5;
    if (const std::optional<MeshData> fast = io_detail::parse_obj_fast(text, chunks)) {
      ++answered;
      REQUIRE(reference.has_value());
      CHECK(reference->warnings.empty());
      check_same(*fast, *reference);
    }
    if (reference) check_same(io_detail::read_obj(dir / "r.obj"), *reference);
    else CHECK(error_of([&] { io_detail::read_obj(dir / "r.obj"); }) == error);
  }
  CHECK(answered > 100);
}
