// Inputs a hostile or unlucky user gives the readers: files that are not regular
// files, CR-only line ends, NaN in STL, broken STL, cut-off or absurd VTK files, deep or
// out-of-range JSON in feature files. Each must end in a subdiv::Error that names the file
// (and the place), never a crash, a hang, another exception type, or silently bad data.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/OMFormat.hh>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>

#include "framework/io/feature_file.h"
#include "framework/io/mesh_read.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/io/vtk/vtk_polydata.h"
#include "framework/util/input_errors.h"
#include "unit/io/io_test_support.h"
#include "unit/io/appended_vtp.h"
#include "support/cli_checks.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// Reading must either succeed or throw subdiv::Error; anything else fails the test.
bool reads_or_refuses_cleanly(const fs::path& file, std::string& message) {
  try {
    read_mesh(file);
    message.clear();
    return true;
  } catch (const Error& e) {
    message = e.what();
    return true;
  } catch (const std::exception& e) {
    message = std::string("not a subdiv::Error: ") + e.what();
    return false;
  }
}

constexpr const char* kLegacyAscii =
    "# vtk DataFile Version 3.0\n"
    "a square\n"
    "ASCII\n"
    "DATASET POLYDATA\n"
    "POINTS 4 float\n"
    "0 0 0 1 0 0 1 1 0 0 1 0\n"
    "POLYGONS 1 5\n"
    "4 0 1 2 3\n"
    "POINT_DATA 4\n"
    "SCALARS corner_sharpness float 1\n"
    "LOOKUP_TABLE default\n"
    "0 0 2 0\n";

// The same square in BINARY: big-endian floats and ints.
std::string legacy_binary() {
  std::string s = "# vtk DataFile Version 3.0\nbinary square\nBINARY\nDATASET POLYDATA\nPOINTS 4 float\n";
  auto put32 = [&s](std::uint32_t v) {
    for (int i = 3; i >= 0; --i) s.push_back(char((v >> (8 * i)) & 0xFF));
  };
  const float xyz[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  for (float f : xyz) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    put32(bits);
  }
  s += "\nPOLYGONS 1 5\n";
  for (std::uint32_t v : {4u, 0u, 1u, 2u, 3u}) put32(v);
  s += "\n";
  return s;
}

// The line (from 1) that byte `at` of `text` is on.
std::size_t line_of(const std::string& text, std::size_t at) {
  return 1 + std::size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
}

}  // namespace

TEST_CASE("a FIFO, a character device and a symlink to /dev/zero are refused at once, naming the file") {
  TempDir dir;
  const fs::path fifo = dir / "pipe.obj";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const std::string m = error_of([&] { read_mesh(fifo); });
  CHECK(contains(m, "cannot open '" + fifo.string() + "'"));
  CHECK(contains(m, "FIFO"));
  CHECK(contains(m, "regular mesh file"));

  const fs::path zero = dir / "zero.obj";
  fs::create_symlink("/dev/zero", zero);
  CHECK(contains(error_of([&] { read_mesh(zero); }), "it is a character device"));
  CHECK(contains(error_of([&] { read_feature_file(zero); }), "regular feature file"));
  CHECK(contains(error_of([&] { read_mesh("/dev/null.obj"); }), "no such file"));
}

TEST_CASE("CR-only line ends (classic Mac OS) are line ends, with the right line numbers") {
  TempDir dir;
  write_text(dir / "cr.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
  const MeshData m = read_mesh(dir / "cr.obj");
  CHECK(m.vertex_count() == 3);
  CHECK(m.face_count() == 1);
  write_text(dir / "cr-bad.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 7\r");
  CHECK(contains(error_of([&] { read_mesh(dir / "cr-bad.obj"); }), (dir / "cr-bad.obj").string() + ":4:"));
  write_text(dir / "cr.off", "OFF\r3 1 0\r0 0 0\r1 0 0\r0 1 0\r3 0 1 2\r");
  CHECK(read_mesh(dir / "cr.off").face_count() == 1);
  write_text(dir / "mixed.obj", "v 0 0 0\r\nv 1 0 0\rv 0 1 0\nf 1 2 3\n");
  CHECK(read_mesh(dir / "mixed.obj").face_count() == 1);
}

TEST_CASE("ASCII STL: NaN coordinates and broken structure are reported with the line") {
  TempDir dir;
  const std::string facet_head = "solid t\nfacet normal 0 0 1\nouter loop\n";
  write_text(dir / "nan.stl", facet_head + "vertex 0 0 0\nvertex nan 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
  const std::string nan = error_of([&] { read_mesh(dir / "nan.stl"); });
  CHECK(contains(nan, (dir / "nan.stl").string() + ":5: vertex coordinate 'nan' is not a finite number"));

  write_text(dir / "inf.stl", facet_head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1e999 0\nendloop\nendfacet\nendsolid t\n");
  CHECK(contains(error_of([&] { read_mesh(dir / "inf.stl"); }), ":6: vertex coordinate '1e999' is not a finite"));

  write_text(dir / "broken.stl", facet_head + "vertex 0 0 0\nvertex 1 0 0\nvertx 0 1 0\nendloop\nendfacet\nendsolid t\n");
  const std::string broken = error_of([&] { read_mesh(dir / "broken.stl"); });
  CHECK(contains(broken, (dir / "broken.stl").string() + ":6: expected 'vertex x y z' or 'endloop', found 'vertx 0 1 0'"));

  write_text(dir / "cut.stl", facet_head + "vertex 0 0 0\nvertex 1 0 0\n");
  CHECK(contains(error_of([&] { read_mesh(dir / "cut.stl"); }), "the file ends inside a facet"));

  write_text(dir / "two.stl", facet_head + "vertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid t\n");
  CHECK(contains(error_of([&] { read_mesh(dir / "two.stl"); }), ":6: the facet has 2 vertices"));

  write_text(dir / "garbage.stl", "this is not an STL file at all");
  CHECK(contains(error_of([&] { read_mesh(dir / "garbage.stl"); }), "not an STL file"));
}

TEST_CASE("binary STL: a NaN coordinate names the triangle") {
  TempDir dir;
  std::string bytes(80, ' ');
  const std::uint32_t one = 1;
  bytes.append(reinterpret_cast<const char*>(&one), 4);  // little-endian on the machines we build for
  float values[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  values[7] = std::nanf("");
  bytes.append(reinterpret_cast<const char*>(values), sizeof values);
  bytes.append(2, '\0');
  write_text(dir / "nan-binary.stl", bytes);
  CHECK(contains(error_of([&] { read_mesh(dir / "nan-binary.stl"); }),
                 (dir / "nan-binary.stl").string() + ": triangle 0 (0-based) has a non-finite coordinate"));
}

TEST_CASE("legacy .vtk cut off at every byte: never a crash, always a subdiv::Error naming the file") {
  TempDir dir;
  for (const std::string& full : {std::string(kLegacyAscii), legacy_binary()}) {
    write_text(dir / "whole.vtk", full);
    REQUIRE(read_mesh(dir / "whole.vtk").face_count() == 1);
    for (size_t cut = 0; cut + 1 < full.size(); ++cut) {
      const fs::path file = dir / "cut.vtk";
      write_text(file, full.substr(0, cut));
      std::string message;
      CHECK_MESSAGE(reads_or_refuses_cleanly(file, message), message);
      if (!message.empty()) CHECK_MESSAGE(contains(message, file.string()), message);
    }
  }
  // Counts larger than the data: refused before VTK allocates or reads past the end.
  write_text(dir / "huge.vtk", std::string(kLegacyAscii).replace(std::string(kLegacyAscii).find("POINTS 4"), 8, "POINTS 2000000000"));
  CHECK(contains(error_of([&] { read_mesh(dir / "huge.vtk"); }),
                 (dir / "huge.vtk").string() + ":5: POINTS says 6000000000 values, but only"));
  std::string bad_index = kLegacyAscii;
  bad_index.replace(bad_index.find("4 0 1 2 3"), 9, "4 0 1 2 9");
  write_text(dir / "index.vtk", bad_index);
  CHECK(contains(error_of([&] { read_mesh(dir / "index.vtk"); }), ":8: POLYGONS names point 9, but the file has 4 points"));
  std::string nan_point = kLegacyAscii;
  nan_point.replace(nan_point.find("1 1 0"), 5, "1 nan 0");
  write_text(dir / "nan.vtk", nan_point);
  CHECK(contains(error_of([&] { read_mesh(dir / "nan.vtk"); }), ":6: point 2 has a non-finite coordinate"));
}

TEST_CASE(".vtp with absurd sizes or a corrupt compression header: a subdiv::Error naming the file") {
  TempDir dir;
  const MeshData cube = cube_mesh();
  // Raw appended data, as ParaView writes it: its compression headers are damaged below.
  write_appended_vtp(dir / "cube.vtp", cube);
  const std::string good = read_text(dir / "cube.vtp");
  REQUIRE(read_mesh(dir / "cube.vtp").face_count() == 6);

  std::string absurd = good;
  absurd.replace(absurd.find("NumberOfPoints=\"8\""), 18, "NumberOfPoints=\"2000000000\"");
  write_text(dir / "absurd.vtp", absurd);
  const std::string m = error_of([&] { read_mesh(dir / "absurd.vtp"); });
  CHECK(contains(m, "cannot read '" + (dir / "absurd.vtp").string() + "'"));
  CHECK(contains(m, "GiB of memory is available"));

  // Field data without NumberOfTuples made VTK's reader leak the array: refused first.
  std::string untold = good;
  const size_t tuples = untold.find("NumberOfTuples=", untold.find("<FieldData"));
  REQUIRE(tuples != std::string::npos);
  untold.replace(tuples, 6, "Nymber");
  write_text(dir / "untold.vtp", untold);
  CHECK(contains(error_of([&] { read_mesh(dir / "untold.vtp"); }), "a field data array needs NumberOfTuples"));

  std::string beyond = good;
  beyond.replace(beyond.find("NumberOfPoints=\"8\""), 18, "NumberOfPoints=\"99999999999\"");
  write_text(dir / "beyond.vtp", beyond);
  CHECK(contains(error_of([&] { read_mesh(dir / "beyond.vtp"); }), "is more than SubdivKit's 32-bit indices hold"));

  // A block size no compressor can produce from the bytes there (200 GB asked of VTK before).
  REQUIRE(contains(good, "<AppendedData encoding=\"raw\">"));
  const size_t data = good.find('_', good.find("<AppendedData")) + 1;
  const size_t word = contains(good, "header_type=\"UInt64\"") ? 8 : 4;
  std::string huge_block = good;
  huge_block[data + 2 * word - 1] = char(0x30);  // most significant byte of the block size
  write_text(dir / "huge-block.vtp", huge_block);
  CHECK(contains(error_of([&] { read_mesh(dir / "huge-block.vtp"); }),
                 "more than vtkZLibDataCompressor can produce; the header is damaged"));
  std::string many_blocks = good;
  many_blocks[data + word - 1] = char(0x7f);  // most significant byte of the block count
  write_text(dir / "many-blocks.vtp", many_blocks);
  CHECK(contains(error_of([&] { read_mesh(dir / "many-blocks.vtp"); }), "compressed blocks, more than the rest of the file"));
  // The same in an <Array> element, which VTK reads as it reads <DataArray> (the check
  // looked at <DataArray> only, and VTK asked for 14 GB: found by fuzz_read_vtp).
  std::string renamed = many_blocks;
  const std::size_t first = renamed.find("<DataArray");
  renamed.replace(first, 10, "<Array");
  write_text(dir / "array-element.vtp", renamed);
  CHECK(contains(error_of([&] { read_mesh(dir / "array-element.vtp"); }),
                 (dir / "array-element.vtp").string() + ":" + std::to_string(line_of(renamed, first)) +
                     ": array 'level' says 9151314442816847873 compressed blocks"));

  // No blocks but a partial last block: VTK computed the data's size as 0 - block size +
  // last block, wrapped round, and read the size of a block that does not exist.
  std::string no_blocks = good;
  REQUIRE(no_blocks[data] == char(1));  // the first array: one block, least significant byte first
  no_blocks[data] = char(0);
  write_text(dir / "no-blocks.vtp", no_blocks);
  const std::string first_array = std::to_string(line_of(good, good.find("<DataArray")));
  CHECK(contains(error_of([&] { read_mesh(dir / "no-blocks.vtp"); }),
                 (dir / "no-blocks.vtp").string() + ":" + first_array + ": array 'level': its data header gives no compressed blocks but a last block"));

  // A field data array without a type: VTK reads it all the same, gets no array and
  // dereferences it (found by fuzz_read_vtp once only <DataArray>s with a type were checked).
  std::string untyped = good;
  const std::size_t type = untyped.find(" type=", untyped.find("<FieldData"));
  untyped.replace(type, 6, " typj=");
  write_text(dir / "untyped.vtp", untyped);
  CHECK(contains(error_of([&] { read_mesh(dir / "untyped.vtp"); }),
                 (dir / "untyped.vtp").string() + ":" + std::to_string(line_of(untyped, type)) +
                     ": DataArray type=\"\" is not a VTK type"));

  // Two cell arrays of one name: VTK created one and read both, the second into an array
  // it never made (a null dereference, found by fuzz_read_vtp).
  std::string twice = good;
  const std::size_t second = twice.find("Name=\"cell_kind\"");
  REQUIRE(twice.find("Name=\"sharpness\"") < second);  // the cell array before it
  twice.replace(second, 16, "Name=\"sharpness\"");
  write_text(dir / "twice.vtp", twice);
  const std::string twice_error = error_of([&] { read_mesh(dir / "twice.vtp"); });
  CHECK_MESSAGE(contains(twice_error, (dir / "twice.vtp").string() + ":" + std::to_string(line_of(twice, second)) +
                                          ": a second array named 'sharpness' in the same <CellData>"),
                twice_error);

  // VTK reads an array with an offset from the appended data whatever its format says:
  // a damaged header there is refused even when the format is not "appended".
  std::string misnamed = huge_block;
  const std::size_t format = misnamed.find("format=\"appended\"");
  misnamed.replace(format, 18, "format=\"appendedJ\"");
  write_text(dir / "misnamed.vtp", misnamed);
  CHECK(contains(error_of([&] { read_mesh(dir / "misnamed.vtp"); }),
                 (dir / "misnamed.vtp").string() + ":" + std::to_string(line_of(misnamed, format)) +
                     ": array 'level': its data header claims"));

  // Flip every byte of the appended data's start (the compression headers) in turn.
  for (size_t at = data; at < data + 64 && at < good.size(); ++at) {
    std::string corrupt = good;
    corrupt[at] = char(~corrupt[at]);
    const fs::path file = dir / "corrupt.vtp";
    write_text(file, corrupt);
    std::string message;
    CHECK_MESSAGE(reads_or_refuses_cleanly(file, message), message);
    if (!message.empty()) CHECK_MESSAGE(contains(message, file.string()), message);
  }
}

TEST_CASE("feature files: deep nesting and numbers beyond double's range name the place") {
  TempDir dir;
  write_text(dir / "deep.json", std::string(100000, '[') + std::string(100000, ']'));
  const std::string deep = error_of([&] { read_feature_file(dir / "deep.json"); });
  CHECK(contains(deep, (dir / "deep.json").string() + ":1:101: JSON nested deeper than 100 levels"));
  write_text(dir / "big.json", "{\"creases\": [\n  {\"edge\": [0, 1], \"sharpness\": 1e400}]}");
  CHECK(contains(error_of([&] { read_feature_file(dir / "big.json"); }),
                 (dir / "big.json").string() + ":2:33: the number 1e400 is out of range"));
  // nlohmann keeps the last of two equal keys: the crease on edge 0-1 became one on 1-2 silently.
  write_text(dir / "twice.json", "{\"creases\": [{\"edge\": [0, 1],\n  \"edge\": [1, 2]}]}");
  CHECK(contains(error_of([&] { read_feature_file(dir / "twice.json"); }),
                 (dir / "twice.json").string() + ":2:3: the key \"edge\" appears twice in one object (first at line 1, "
                                                  "column 15)"));
  write_text(dir / "deep-value.json", "{\"creases\": " + std::string(90, '[') + std::string(90, ']') + "}");
  const std::string shown = error_of([&] { read_feature_file(dir / "deep-value.json"); });
  CHECK(shown.size() < 400);  // the value is quoted shortened, not dumped whole
}

TEST_CASE("any standard exception while reading becomes a subdiv::Error naming the file") {
  const auto length = error_of([] { naming_file_on_failure("m.vtp", []() -> int { throw std::length_error("vector"); }); });
  CHECK(contains(length, "cannot read 'm.vtp': a size in it is impossible (vector)"));
  const auto range = error_of([] { naming_file_on_failure("m.om", []() -> int { throw std::out_of_range("at"); }); });
  CHECK(contains(range, "cannot read 'm.om': an index or offset in it is out of range"));
  const auto memory = error_of([] { naming_file_on_failure("m.ply", []() -> int { throw std::bad_alloc(); }); });
  CHECK(contains(memory, "cannot read 'm.ply': out of memory while reading it"));
  CHECK(contains(memory, "raise the limit"));
}

TEST_CASE("OpenMesh .om: cut off anywhere or with damaged chunks, a subdiv::Error and never an abort") {
  TempDir dir;
  const std::string good = read_text(fs::path(SUBDIV_SOURCE_DIR) / "tests/fuzz/seeds/om/cube.om");
  write_text(dir / "cube.om", good);
  REQUIRE(read_mesh(dir / "cube.om").face_count() == 6);
  for (size_t cut = 0; cut < good.size(); ++cut) {
    write_text(dir / "cut.om", good.substr(0, cut));
    std::string message;
    CHECK_MESSAGE(reads_or_refuses_cleanly(dir / "cut.om", message), message);
  }
  // The first chunk (vertex positions) with two components: OpenMesh would assert() and abort.
  std::string flat = good;
  flat[16 + 1] = char(flat[16 + 1] & ~0x38);  // the chunk header's dimension bits (11..13)
  write_text(dir / "flat.om", flat);
  CHECK(contains(error_of([&] { read_mesh(dir / "flat.om"); }), (dir / "flat.om").string() + ": byte 16: a chunk"));
  // A colour chunk: how OpenMesh 9 reads it is not documented, so it is refused, not guessed.
  std::string coloured = good;
  coloured[16] = char(coloured[16] | 0x80);  // type bits 5..8: 4, colours
  write_text(dir / "coloured.om", coloured);
  CHECK(contains(error_of([&] { read_mesh(dir / "coloured.om"); }), "positions and connectivity only"));
  // A vertex count beyond the file.
  std::string many = good;
  many[7] = char(0x7f);
  write_text(dir / "many.om", many);
  CHECK(contains(error_of([&] { read_mesh(dir / "many.om"); }), "more than the file's"));
}

TEST_CASE("legacy .vtk: a version VTK cannot read is refused, not guessed") {
  TempDir dir;
  std::string v = kLegacyAscii;
  v.replace(v.find("3.0"), 3, "5.");
  write_text(dir / "v.vtk", v);
  CHECK(contains(error_of([&] { read_mesh(dir / "v.vtk"); }), (dir / "v.vtk").string() + ":1: the first line must be"));
}

TEST_CASE("fuzz findings stay fixed: PLY elements without properties, unknown VTK array types") {
  TempDir dir;
  // 5e14 entries of nothing: the reader looped over them for days.
  write_text(dir / "empty-element.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                        "property float z\nelement nothing 555555555555555\nend_header\n0 0 0\n1 0 0\n0 1 0\n");
  CHECK(contains(error_of([&] { read_mesh(dir / "empty-element.ply"); }),
                 "element 'nothing' has 555555555555555 entries but no properties"));
  // type="Int31" made VTK's XML reader dereference a null array.
  const MeshData cube = cube_mesh();
  OutputLevel level;
  level.mesh = &cube;
  write_vtp(dir / "cube.vtp", level);
  std::string typo = read_text(dir / "cube.vtp");
  typo.replace(typo.find("type=\"Int32\""), 12, "type=\"Int31\"");
  write_text(dir / "typo.vtp", typo);
  CHECK(contains(error_of([&] { read_mesh(dir / "typo.vtp"); }), "DataArray type=\"Int31\" is not a VTK type"));
}

TEST_CASE("legacy .vtk BINARY: text after a keyword line, or no line end, is refused before VTK's getline fails") {
  TempDir dir;
  write_text(dir / "unterminated.vtk", legacy_binary() + "VERTICES 0 0 1");
  CHECK(contains(error_of([&] { read_mesh(dir / "unterminated.vtk"); }), "the file ends before the binary data"));
  write_text(dir / "junk.vtk", legacy_binary() + "VERTICES 0 0 junk\n");
  CHECK(contains(error_of([&] { read_mesh(dir / "junk.vtk"); }), "unexpected text after the keyword line"));
}

namespace {

// A legacy .vtk file as VTK's own writer makes it, METADATA blocks included: component
// names, and the coordinate range VTK caches in the array's information and writes as an
// INFORMATION key.
void write_legacy_with_metadata(const fs::path& file, const MeshData& mesh, bool binary) {
  OutputLevel level;
  level.mesh = &mesh;
  vtkSmartPointer<vtkPolyData> poly = io_detail::make_polydata(level);
  vtkDataArray* points = poly->GetPoints()->GetData();
  for (int c = 0; c < 3; ++c) points->SetComponentName(c, c == 0 ? "x" : c == 1 ? "y" : "z");
  double range[2];
  points->GetRange(range, -1);
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->SetFileName(file.c_str());
  if (binary) writer->SetFileTypeToBinary();
  else writer->SetFileTypeToASCII();
  REQUIRE(writer->Write() == 1);
}

}  // namespace

TEST_CASE("legacy .vtk METADATA: read as VTK writes it, and never parsed by VTK where the check could disagree") {
  TempDir dir;
  const MeshData cube = cube_mesh();
  for (const bool binary : {false, true}) {
    const fs::path file = dir / (binary ? "binary.vtk" : "ascii.vtk");
    write_legacy_with_metadata(file, cube, binary);
    const std::string text = read_text(file);
    REQUIRE(contains(text, "METADATA\nCOMPONENT_NAMES\n"));
    REQUIRE(contains(text, "INFORMATION"));
    const MeshData read = read_mesh(file);
    CHECK(read.face_count() == cube.face_count());
    REQUIRE(read.vertex_count() == cube.vertex_count());
    for (std::size_t v = 0; v < cube.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c) CHECK(read.positions[3 * v + c] == doctest::Approx(cube.positions[3 * v + c]));
  }

  // The fuzz finding: in a METADATA block, a line starting with a 0 byte ends the block for
  // VTK but was a line like any other for the check, so VTK went on to read cells the
  // check had never seen, past the end of the file, and crashed.
  std::string zero = legacy_binary();
  const std::size_t cells = zero.find("POLYGONS");
  zero.insert(cells, std::string("METADATA\nCOMPONENT_NAMES\n") + '\0' + "x\nPOLYGONS 1 5\n" + std::string(8, '\0') + "\n\n");
  write_text(dir / "zero.vtk", zero);
  CHECK(contains(error_of([&] { read_mesh(dir / "zero.vtk"); }),
                 (dir / "zero.vtk").string() + ": byte " + std::to_string(cells + 25) + ": a METADATA line holds a 0 byte"));
  check_refused("refine " + (dir / "zero.vtk").string() + " -l 1 -q", dir / "zero-out.obj", "a METADATA line holds a 0 byte");

  // A block VTK would end at the end of the file, the check nowhere: refused.
  write_text(dir / "unended.vtk", std::string(kLegacyAscii) + "METADATA\nINFORMATION 1\n");
  CHECK(contains(error_of([&] { read_mesh(dir / "unended.vtk"); }),
                 (dir / "unended.vtk").string() + ":13: the METADATA block has no empty line to end it"));

  // 256 spaces after an array's data: VTK's search for METADATA never ends (a hang).
  std::string spaces = kLegacyAscii;
  spaces.insert(spaces.find("\nPOLYGONS"), std::string(300, ' '));
  write_text(dir / "spaces.vtk", spaces);
  CHECK(contains(error_of([&] { read_mesh(dir / "spaces.vtk"); }),
                 (dir / "spaces.vtk").string() + ":6: 256 or more blanks after an array's data"));
  const CliResult hang = run_subdiv_with_prefix("timeout 60 ", "refine " + (dir / "spaces.vtk").string() + " -l 1 -q -o " +
                                                                   (dir / "spaces-out.obj").string());
  CHECK(hang.exit_code == 1);
  CHECK_FALSE(fs::exists(dir / "spaces-out.obj"));
}

TEST_CASE(".vtp: the appended data starts where VTK starts it, not at the first '_' in the file") {
  TempDir dir;
  write_appended_vtp(dir / "cube.vtp", cube_mesh());
  std::string vtp = read_text(dir / "cube.vtp");
  // VTK takes the first character after the blanks as the data when it is not '_'. Eight
  // bytes there say 2^49 compressed blocks: VTK allocated 2^52 bytes for their sizes, as
  // the check read the headers after the '_' that followed (found by fuzz_read_vtp).
  const std::size_t underscore = vtp.find('_', vtp.find("<AppendedData"));
  REQUIRE(underscore != std::string::npos);
  vtp.insert(underscore, "\xff\xff\xff\xff\xff\xff\x01\x00");
  write_text(dir / "shifted.vtp", vtp);
  const std::string first_array = std::to_string(line_of(vtp, vtp.find("<DataArray")));
  const std::string m = error_of([&] { read_mesh(dir / "shifted.vtp"); });
  CHECK_MESSAGE(contains(m, (dir / "shifted.vtp").string() + ":" + first_array + ": array '"), m);
  CHECK_MESSAGE(contains(m, "header is damaged"), m);
  check_refused("refine " + (dir / "shifted.vtp").string() + " -l 1 -q", dir / "shifted-out.obj", "header is damaged");
}

TEST_CASE(".om: vertex topology before the vertex positions is refused (OpenMesh wrote through a null pointer)") {
  TempDir dir;
  const std::string good = read_text(fs::path(SUBDIV_SOURCE_DIR) / "tests/fuzz/seeds/om/cube.om");
  // The first chunk (the positions) relabelled as vertex topology with 32-bit ids: the
  // reader would set the halfedge of vertices that do not exist yet.
  namespace omf = OpenMesh::IO::OMFormat;
  omf::Chunk::Header chunk{};
  chunk.entity_ = omf::Chunk::Entity_Vertex;
  chunk.type_ = omf::Chunk::Type_Topology;
  chunk.bits_ = omf::Chunk::Integer_32;
  omf::uint16 word = 0;
  word << chunk;
  std::string early = good;
  early[16] = char(word & 0xFF);
  early[17] = char(word >> 8);
  write_text(dir / "early.om", early);
  CHECK(contains(error_of([&] { read_mesh(dir / "early.om"); }),
                 (dir / "early.om").string() + ": byte 16: the vertex topology chunk comes before the vertex positions"));
  check_refused("refine " + (dir / "early.om").string() + " -l 1 -q", dir / "early-out.obj",
                "the vertex topology chunk comes before the vertex positions");
}

TEST_CASE("legacy .vtk: a word longer than VTK's 255-character buffer is refused, not split") {
  TempDir dir;
  std::string named = kLegacyAscii;
  named.replace(named.find("corner_sharpness"), 16, std::string(300, 'n'));
  write_text(dir / "long-name.vtk", named);
  CHECK(contains(error_of([&] { read_mesh(dir / "long-name.vtk"); }),
                 (dir / "long-name.vtk").string() + ":10: a word of 300 characters"));
}

TEST_CASE("legacy .vtk: a FIELD bit array whose values are not numbers is refused (VTK crashed on it)") {
  TempDir dir;
  write_text(dir / "bits.vtk", std::string(kLegacyAscii) + "FIELD FieldData 1\nlevel 2 2 bit\n0\nr\n1 0\n");
  CHECK(contains(error_of([&] { read_mesh(dir / "bits.vtk"); }), (dir / "bits.vtk").string() + ":16: FIELD array: 'r' is not a bit"));
}
