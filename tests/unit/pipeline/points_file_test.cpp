// Points files for `subdiv evaluate --at` (framework/pipeline/points_file.h), parsed from
// text: every refusal names the file, the line (counting blank lines and the header) and
// the row (counting points), and CRLF files read as LF files.
#include <doctest/doctest.h>

#include <cmath>
#include <fmt/format.h>
#include <filesystem>
#include <string>
#include <sys/stat.h>

#include "framework/io/mesh_level.h"
#include "framework/limit/limit_surface.h"
#include "framework/pipeline/points_file.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// Faces 0..9, (u, v) in the unit square.
std::string unit_square_check(Index face, double u, double v) {
  if (face < 0 || face > 9) return "no such face";
  return u < 0 || u > 1 || v < 0 || v > 1 ? "(u, v) is outside" : "";
}

TEST_CASE("rows become points in order; blank lines and CRLF endings are skipped") {
  const SurfacePoints p = parse_points("face,u,v\r\n3, 0.25,0.5\r\n\r\n9,1,0\r\n", "pts.csv", unit_square_check);
  REQUIRE(p.size() == 2);
  CHECK(p.faces == std::vector<Index>{3, 9});
  CHECK(p.uv == std::vector<double>{0.25, 0.5, 1, 0});
}

TEST_CASE("each refusal names the file, the line and the row") {
  struct Bad {
    const char* text;
    const char* message;
  };
  for (const Bad& bad : {Bad{"", "pts.csv: empty file"}, Bad{"x,y,z\n0,0,0\n", "pts.csv line 1: the header is 'x,y,z'"},
                         Bad{"face,u,v\n", "pts.csv: no points after the header"},
                         Bad{"face,u,v\n\n0,0.5\n", "pts.csv line 3 (row 1): 2 fields"},
                         Bad{"face,u,v\n0,0,0\n1.5,0,0\n", "pts.csv line 3 (row 2): face '1.5' is not a whole number"},
                         Bad{"face,u,v\n0,nan?,0\n", "pts.csv line 2 (row 1): u = 'nan?' is not a number"},
                         Bad{"face,u,v\n0,0,1e999\n", "pts.csv line 2 (row 1): v = '1e999' is out of range"},
                         Bad{"face,u,v\n0,0,0\n\n12,0,0\n", "pts.csv line 4 (row 2): no such face"},
                         Bad{"face,u,v\n0,2,0\n", "pts.csv line 2 (row 1): (u, v) is outside"},
                         Bad{"face,u,v\n99999999999,0,0\n", "face '99999999999' is out of range"}}) {
    CAPTURE(bad.text);
    CHECK_THROWS_WITH_AS(parse_points(bad.text, "pts.csv", unit_square_check), doctest::Contains(bad.message), Error);
  }
}

TEST_CASE("a face number written as a decimal with a whole value (pandas, R) is that face; others are refused") {
  // pandas writes an integer column holding a missing value as floats ("3.0"), R's write.csv
  // a double column; they name face 3. A fraction or a value beyond Index is still refused.
  const SurfacePoints p = parse_points("face,u,v\n3.0,0.5,0.5\n\"1e0\",0,0\n+2.00,1,1\n-0.0,0,1\n", "pts.csv",
                                       unit_square_check);
  CHECK(p.faces == std::vector<Index>{3, 1, 2, 0});
  for (const auto& bad : {std::pair{"3.5", "is not a whole number"}, std::pair{"1e30", "is out of range"},
                           std::pair{"inf", "is not a whole number"}, std::pair{"nan", "is not a whole number"},
                           std::pair{"3.0.0", "is not a whole number"}}) {
    CAPTURE(bad.first);
    CHECK_THROWS_WITH_AS(parse_points(std::string("face,u,v\n") + bad.first + ",0,0\n", "pts.csv", unit_square_check),
                         doctest::Contains(fmt::format("face '{}' {}", bad.first, bad.second).c_str()), Error);
  }
}

TEST_CASE("a spreadsheet's header: a byte-order mark and spaces around the names are accepted") {
  // Excel's "CSV UTF-8" starts the file with EF BB BF; hand-written files often say "face, u, v".
  for (const char* text : {"\xEF\xBB\xBF" "face,u,v\r\n1,0.5,0.25\r\n", "face, u, v\n1, 0.5, 0.25\n"}) {
    CAPTURE(text);
    const SurfacePoints p = parse_points(text, "pts.csv", unit_square_check);
    REQUIRE(p.size() == 1);
    CHECK(p.faces[0] == 1);
    CHECK(p.uv == std::vector<double>{0.5, 0.25});
  }
  CHECK_THROWS_WITH_AS(parse_points("\xEF\xBB\xBF" "face,v,u\n0,0,0\n", "pts.csv", unit_square_check),
                       doctest::Contains("must be 'face,u,v'"), Error);
}

TEST_CASE("quoted fields (R's write.csv, spreadsheets) and a header in another case are read as written plain") {
  // R writes "face","u","v"; a hand-made header says Face,U,V. Both were refused as "the
  // header is ...", and quoted numbers as "not a number".
  for (const char* text : {"\"face\",\"u\",\"v\"\n1,0.5,0.25\n", "Face,U,V\r\n1,0.5,0.25\r\n",
                           "FACE, \"u\" ,V\n\"1\",\"0.5\", \"0.25\"\n"}) {
    CAPTURE(text);
    const SurfacePoints p = parse_points(text, "pts.csv", unit_square_check);
    REQUIRE(p.size() == 1);
    CHECK(p.faces[0] == 1);
    CHECK(p.uv == std::vector<double>{0.5, 0.25});
  }
  // What quotes may not hide: a quote left open, or R's row-name column in front.
  CHECK_THROWS_WITH_AS(parse_points("face,u,v\n\"1,0.5,0.25\n", "pts.csv", unit_square_check),
                       doctest::Contains("line 2 (row 1): face '\"1' is not a whole number"), Error);
  CHECK_THROWS_WITH_AS(parse_points("\"\",\"face\",\"u\",\"v\"\n\"1\",1,0.5,0.25\n", "pts.csv", unit_square_check),
                       doctest::Contains("must be 'face,u,v'"), Error);
}

TEST_CASE("a header separated by semicolons (a spreadsheet with decimal commas) is named as such") {
  CHECK_THROWS_WITH_AS(parse_points("face;u;v\n0;0,5;0,5\n", "pts.csv", unit_square_check),
                       doctest::Contains("the fields are separated by ';': save the file with ',' between fields and "
                                         "'.' as the decimal point"),
                       Error);
}

TEST_CASE("a leading '+' is a sign, and a file of CR line endings is named as such") {
  const SurfacePoints p = parse_points("face,u,v\n+3,+0.25,0.5\n", "pts.csv", unit_square_check);
  CHECK(p.faces == std::vector<Index>{3});
  CHECK(p.uv == std::vector<double>{0.25, 0.5});
  CHECK_THROWS_WITH_AS(parse_points("face,u,v\n+-3,0,0\n", "pts.csv", unit_square_check),
                       doctest::Contains("face '+-3' is not a whole number"), Error);
  CHECK_THROWS_WITH_AS(parse_points("face,u,v\r0,0.5,0.5\r", "pts.csv", unit_square_check),
                       doctest::Contains("pts.csv line 1: the lines end in a carriage return alone"), Error);
}

TEST_CASE("a u or v too small for a double is 0, as a subnormal is; one too large is refused") {
  // 4e-320 (subnormal) was accepted while 1e-400 was refused as out of range: both are 0 to
  // double precision and lie in the face's domain, whatever the mantissa's zeros.
  const std::string tiny_by_mantissa = "0." + std::string(500, '0') + "1e100";
  const SurfacePoints p = parse_points("face,u,v\n0,1e-400,4e-320\n1,-1e-400,+2e-324\n2,1e-99999999999999999999,0\n3," +
                                           tiny_by_mantissa + ",0.5\n",
                                       "pts.csv", unit_square_check);
  REQUIRE(p.size() == 4);
  CHECK(p.uv == std::vector<double>{0, 4e-320, 0, 0, 0, 0, 0, 0.5});
  CHECK_FALSE(std::signbit(p.uv[2]));  // -1e-400 is the parameter 0, as -0 is (no "-0" echoed)
  for (const char* big : {"1e400", "-1e400", "1e+99999999999999999999", "0.001e312"}) {
    CAPTURE(big);
    const std::string expected = std::string("v = '") + big + "' is out of range: larger than a double holds";
    CHECK_THROWS_WITH_AS(parse_points(std::string("face,u,v\n0,0.5,") + big + "\n", "pts.csv", unit_square_check),
                         doctest::Contains(expected.c_str()), Error);
  }
  // A tiny u that is negative in a domain that starts at 0 is 0, inside: the check sees 0.
  CHECK_NOTHROW(parse_points("face,u,v\n0,-1e-400,-1e-400\n", "pts.csv", unit_square_check));
}

TEST_CASE("a huge field or header is quoted by its beginning and its length, not echoed whole") {
  const std::string digits(1000000, '5');
  for (const std::string& text : {"face,u,v\n0,0.5," + digits + "\n", "face,u,v\n" + digits + ",0.5,0.5\n",
                                  "face,u,v" + digits + "\n0,0.5,0.5\n"}) {
    std::string message;
    try {
      parse_points(text, "pts.csv", unit_square_check);
    } catch (const Error& e) {
      message = e.what();
    }
    CAPTURE(message.substr(0, 300));
    CHECK(message.find("pts.csv line ") == 0);
    CHECK(message.find(" characters)") != std::string::npos);
    CHECK(message.find("'... (100000") != std::string::npos);  // the field's or the header's length
    CHECK(message.size() < 400);
  }
}

TEST_CASE("a missing file is refused with its name") {
  CHECK_THROWS_WITH_AS(read_points_file("/no/such/points.csv", unit_square_check),
                       doctest::Contains("cannot open '/no/such/points.csv': no such file"), Error);
}

TEST_CASE("a FIFO, a link to /dev/zero and a directory are refused for what they are, without reading") {
  // A FIFO blocked until killed; /dev/zero was read as one endless line until memory ran
  // out ("empty file"); a directory read as an empty file.
  const auto dir = std::filesystem::temp_directory_path() / "subdivkit-points-file-kinds";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "folder.csv");
  REQUIRE(::mkfifo((dir / "pipe.csv").c_str(), 0600) == 0);
  std::filesystem::create_symlink("/dev/zero", dir / "zero.csv");
  struct Bad {
    const char* name;
    const char* message;
  };
  for (const Bad& b : {Bad{"pipe.csv", "pipe.csv': it is a FIFO (named pipe); give the path of a regular points (.csv) file"},
                       Bad{"zero.csv", "zero.csv': it is a character device"},
                       Bad{"folder.csv", "folder.csv': it is a directory, not a points (.csv) file"}}) {
    CAPTURE(b.name);
    CHECK_THROWS_WITH_AS(read_points_file((dir / b.name).string(), unit_square_check), doctest::Contains(b.message),
                         Error);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("a triangle under a quad scheme refuses a u far beyond its tiles (found by fuzz_points_file)") {
  // A triangle's domain under Catmull-Clark is Bfr's sub-face grid (2 x 2 tiles). u = 2e10
  // used to be cast to int before the range check: undefined behaviour (UBSan's
  // float-cast-overflow), now a refusal like any point outside the tiles.
  MeshData m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  m.face_offsets = {0, 3, 6};
  m.face_vertices = {0, 1, 2, 1, 3, 2};
  const LimitSurface surface(load_scheme("catmull-clark"), level_from_mesh(m, "two triangles"));
  const auto check = [&surface](Index face, double u, double v) { return surface.check(face, u, v); };
  for (const char* text : {"face,u,v\n0,21474836470.25,0.55\n", "face,u,v\n1,0.25,-3e9\n", "face,u,v\n0,1e308,1e308\n"}) {
    CAPTURE(text);
    CHECK_THROWS_WITH_AS(parse_points(text, "pts.csv", check), doctest::Contains("outside the face's sub-face tiles"),
                         Error);
  }
  CHECK(parse_points("face,u,v\n0,0.25,0.25\n", "pts.csv", check).size() == 1);
}

}  // namespace
}  // namespace subdiv

namespace subdiv {

TEST_CASE("u or v written -0.0 is the parameter 0: messages and outputs echo it as 0, not -0") {
  const SurfacePoints p = parse_points("face,u,v\n0,-0.0,-0\n", "pts.csv", unit_square_check);
  REQUIRE(p.uv.size() == 2);
  CHECK_FALSE(std::signbit(p.uv[0]));
  CHECK_FALSE(std::signbit(p.uv[1]));
  CHECK_THROWS_WITH_AS(parse_points("face,u,v\n0,-0.0,1.5\n", "pts.csv",
                                    [](Index, double u, double v) {
                                      return u >= 0 && v <= 1 ? std::string() : fmt::format("({}, {}) is out", u, v);
                                    }),
                       doctest::Contains("(0, 1.5) is out"), Error);
}

}  // namespace subdiv
