// Outputs that read back and leave nothing behind (issue 33): names any text can hold,
// coordinates near the largest double, stale temporaries of killed runs, stale level files
// of an earlier .pvd; and the reader's refusals of what VTK would crash on or misread.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <fmt/format.h>
#include <limits>
#include <sys/file.h>
#include <unistd.h>

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUtilities.h>

#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/util/atomic_file.h"
#include "unit/io/io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// VTK's own reader: an error code or no output fails the check.
vtkSmartPointer<vtkPolyData> vtk_read(const fs::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  CHECK(reader->GetErrorCode() == 0);
  return reader->GetOutput();
}

std::vector<std::string> names_of(const std::vector<DataArray>& arrays) {
  std::vector<std::string> names;
  for (const DataArray& a : arrays) names.push_back(a.name);
  return names;
}

MeshData cube_with_point_array(const std::string& name, int components = 1) {
  MeshData m = cube_mesh();
  DataArray a{name, components, {}, false};
  for (Index v = 0; v < m.vertex_count(); ++v)
    for (int c = 0; c < components; ++c) a.values.push_back(v + 0.25 * c);
  m.point_data.push_back(a);
  return m;
}

}  // namespace

TEST_CASE("VTK XML: array names with quotes, markup and line breaks are written escaped and read back as they were") {
  TempDir dir;
  const std::string name = "a\"b<c>&d\ne\tf";
  const MeshData mesh = cube_with_point_array(name);
  for (const char* file : {"names.vtp", "names.pvd"}) {
    CAPTURE(std::string(file));
    write_mesh(dir / file, mesh);
  }
  const fs::path vtp = dir / "names.vtp";
  vtkSmartPointer<vtkXMLDataElement> parsed;  // the caller owns what ReadElementFromFile returns
  parsed.TakeReference(vtkXMLUtilities::ReadElementFromFile(vtp.c_str()));
  CHECK(parsed != nullptr);  // well-formed XML
  CHECK(names_of(read_mesh(vtp).point_data) == std::vector<std::string>{name});
  const auto poly = vtk_read(vtp);
  REQUIRE(poly->GetPointData()->GetArray(name.c_str()) != nullptr);
  CHECK(names_of(read_mesh(dir / "names_levels" / "level_0.vtp").point_data) == std::vector<std::string>{name});
}

TEST_CASE("VTK XML: names XML cannot hold at all are refused before any file exists") {
  TempDir dir;
  CHECK(contains(error_of([&] { write_mesh(dir / "c.vtp", cube_with_point_array(std::string("a\x01" "b"))); }),
                 "control character 0x01"));
  CHECK(contains(error_of([&] { write_mesh(dir / "u.vtp", cube_with_point_array("a\xff" "b")); }), "not UTF-8"));
  CHECK(contains(error_of([&] { write_mesh(dir / "bad\x02name.pvd", cube_mesh()); }), "control character 0x02"));
  CHECK(dir.entries().empty());
}

TEST_CASE(".pvd: a line break in its name still gives an index that names the level files") {
  TempDir dir;
  const fs::path pvd = dir / "two\nlines.pvd";
  write_mesh(pvd, cube_mesh());
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(vtkXMLUtilities::ReadElementFromFile(pvd.c_str()));
  REQUIRE(root);
  const char* file = root->GetNestedElement(0)->GetNestedElement(0)->GetAttribute("file");
  REQUIRE(file);
  CHECK(fs::exists(dir.path() / file));
}

TEST_CASE("VTK XML: coordinates near the largest double give finite ranges, and the file reads back") {
  TempDir dir;
  MeshData mesh = cube_mesh();
  for (double& x : mesh.positions) x = x < 0 ? -1.5e308 : 1.5e308;
  // A name that needs escaping too: renaming the array must not lose its clamped range.
  mesh.point_data.push_back({"huge & <escaped>", 3, mesh.positions, false});
  const fs::path vtp = dir / "huge.vtp";
  write_mesh(vtp, mesh);
  CHECK(read_text(vtp).find("inf") == std::string::npos);
  CHECK(read_mesh(vtp).positions == mesh.positions);
  CHECK(vtk_read(vtp)->GetNumberOfPoints() == 8);
}

TEST_CASE("PLY: names the header cannot hold are renamed with a note; a point array 'x' is not a second x") {
  TempDir dir;
  MeshData mesh = cube_with_point_array("x");
  DataArray forged{"t\nelement face 0", 1, std::vector<double>(8, 2.0), false};
  DataArray spaced{"two words", 2, std::vector<double>(16, 3.0), false};
  mesh.point_data.push_back(forged);
  mesh.point_data.push_back(spaced);
  const fs::path ply = dir / "names.ply";
  write_mesh(ply, mesh);
  const std::string text = read_text(ply);
  const std::string header = text.substr(0, text.find("end_header"));
  CHECK(header.find("\nelement face 0") == std::string::npos);  // no forged header line
  CHECK(contains(header, "comment point array 'x' written as 'x_v2'"));
  const MeshData back = read_mesh(ply);
  CHECK(back.positions == mesh.positions);
  CHECK(names_of(back.point_data) == std::vector<std::string>{"x_v2", "t_element_face_0", "two_words"});
  REQUIRE(back.point_data.size() == 3);
  CHECK(back.point_data[0].values == mesh.point_data[0].values);
  CHECK(back.point_data[2].components == 2);
}

TEST_CASE("round trip: every output format reads back with SubdivKit, the XML ones with VTK too") {
  TempDir dir;
  const MeshData mesh = cube_with_point_array("weight & <value>");
  for (const char* ext : {".obj", ".off", ".ply", ".stl", ".vtp", ".pvd"}) {
    const std::string format = ext;
    CAPTURE(format);
    const fs::path file = dir / ("out" + format);
    write_mesh(file, mesh);
    const fs::path data = format == ".pvd" ? dir / "out_levels" / "level_0.vtp" : file;
    const MeshData back = read_mesh(data);
    CHECK(back.vertex_count() == (format == ".stl" ? 8 : mesh.vertex_count()));
    if (format == ".stl") continue;  // triangles of float coordinates (round_trip_test.cpp)
    check_same_positions(mesh, back, 0);
    check_same_faces(mesh, back);
    if (format == ".ply" || format == ".vtp" || format == ".pvd") {
      REQUIRE(back.point_data.size() == 1);
      CHECK(back.point_data[0].values == mesh.point_data[0].values);
    }
    if (format == ".vtp" || format == ".pvd") CHECK(vtk_read(data)->GetNumberOfPolys() == 6);
  }
}

TEST_CASE("atomic writes: a killed run's temporary is removed when its target is written again, a live one is not") {
  TempDir dir;
  const fs::path target = dir / "out.obj";
  write_text(dir / ".out.obj.1f2e-7.tmp", "half a file from a killed run");
  write_text(dir / ".out.obj.notours.tmp", "not a temporary of SubdivKit's naming");
  write_text(dir / ".other.obj.1f2e-7.tmp", "another target's");
  StagedFiles live;
  const fs::path held = live.stage(target);  // a concurrent writer of the same target
  write_mesh(target, cube_mesh());
  CHECK(fs::exists(target));
  CHECK(!fs::exists(dir / ".out.obj.1f2e-7.tmp"));
  CHECK(fs::exists(held));
  CHECK(fs::exists(dir / ".out.obj.notours.tmp"));
  CHECK(fs::exists(dir / ".other.obj.1f2e-7.tmp"));
}

TEST_CASE(".pvd: rewriting with fewer levels removes the earlier run's extra level files") {
  TempDir dir;
  const MeshData mesh = cube_mesh();
  std::vector<OutputLevel> levels(3);
  for (int k = 0; k < 3; ++k) levels[size_t(k)].mesh = &mesh, levels[size_t(k)].level = k;
  write_text(dir / "keep.txt", "unrelated");
  const fs::path pvd = dir / "run.pvd";
  write_pvd(pvd, levels);
  write_text(dir / "run_levels" / "notes.txt", "the user's own file");
  write_pvd(pvd, std::span(levels.data(), 1));
  CHECK(dir.entries() ==
        std::vector<std::string>{"keep.txt", "run.pvd", "run_levels", "run_levels/level_0.vtp", "run_levels/notes.txt"});
  CHECK(!contains(read_text(pvd), "level_1"));
}

TEST_CASE(".vtp reader: what VTK crashes on or misreads is refused with the file, the place and the array") {
  TempDir dir;
  const std::string head =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      "<PolyData><Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\">\n"
      "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray>"
      "</Points>\n";
  const auto polys = [](const std::string& type, const std::string& connectivity) {
    return "<Polys><DataArray type=\"" + type + "\" Name=\"connectivity\" format=\"ascii\">" + connectivity +
           "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3</DataArray></Polys>\n";
  };
  const std::string tail = "</Piece></PolyData></VTKFile>\n";
  write_text(dir / "good.vtp", head + polys("Int64", "0 1 2") + tail);
  REQUIRE(read_mesh(dir / "good.vtp").face_count() == 1);

  // One string for three points: VTK's reader crashed (SIGSEGV) on it.
  write_text(dir / "string.vtp", head + "<PointData><DataArray type=\"String\" Name=\"label\" format=\"ascii\">"
                                            "97 0</DataArray></PointData>\n" +
                                        polys("Int64", "0 1 2") + tail);
  const std::string s = error_of([&] { read_mesh(dir / "string.vtp"); });
  CHECK(contains(s, "string.vtp:5: point array 'label' is not numeric (a String array)"));

  // Strings in field data (labels) are VTK's business: read, and left out as before.
  write_text(dir / "field.vtp", head + "<FieldData><DataArray type=\"String\" Name=\"note\" NumberOfTuples=\"1\" "
                                           "format=\"ascii\">97 0</DataArray></FieldData>\n" +
                                       polys("Int64", "0 1 2") + tail);
  CHECK(read_mesh(dir / "field.vtp").face_count() == 1);

  write_text(dir / "wrap.vtp", head + polys("Int64", "0 1 4294967298") + tail);
  CHECK(contains(error_of([&] { read_mesh(dir / "wrap.vtp"); }), "polygon 0 refers to point 4294967298"));

  write_text(dir / "float.vtp", head + polys("Float64", "0 1 1.7") + tail);
  CHECK(contains(error_of([&] { read_mesh(dir / "float.vtp"); }),
                 "float.vtp:5: <Polys> array 'connectivity' has type Float64"));
}

TEST_CASE("OBJ: unknown statements are warned about with their lines; the spec's other statements are skipped quietly") {
  TempDir dir;
  std::string text = "mtllib a.mtl\no cube\ng side\nusemtl red\ns 1\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  text += "f 1 2 3 4\nF 1 2 3\n";
  text += std::string("\0f 1 2 3\n", 9);
  text += "F 2 3 4\nF 1 3 4\nF 1 2 4\nF 1 2 3\nF 2 3 4\nF 1 3 4\n";
  write_text(dir / "unknown.obj", text);
  const MeshData mesh = read_mesh(dir / "unknown.obj");
  CHECK(mesh.face_count() == 1);
  REQUIRE(mesh.warnings.size() == 2);
  CHECK(contains(mesh.warnings[0], "unknown.obj: lines 11, 13, 14, 15, 16 and 2 more: skipped the unknown statement 'F'"));
  CHECK(contains(mesh.warnings[1], "unknown.obj: line 12: skipped the unknown statement '\\x00f'"));

  write_text(dir / "quiet.obj", "mtllib a.mtl\no cube\ng side\nusemtl red\ns 1\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
  CHECK(read_mesh(dir / "quiet.obj").warnings.empty());
}

TEST_CASE("OBJ: a large file takes the same warnings (its parallel path declines unknown statements)") {
  TempDir dir;
  std::string text;
  for (int i = 0; i < 60000; ++i) text += "v 0.125 0.25 0.5\n";
  for (int i = 0; i + 3 <= 60000; i += 3) text += fmt::format("f {} {} {}\n", i + 1, i + 2, i + 3);
  text += "F 1 2 3\n";
  REQUIRE(text.size() > (1u << 20));
  write_text(dir / "large.obj", text);
  const MeshData mesh = read_mesh(dir / "large.obj");
  CHECK(mesh.face_count() == 20000);
  REQUIRE(mesh.warnings.size() == 1);
  CHECK(contains(mesh.warnings[0], "line 80001: skipped the unknown statement 'F'"));
}

TEST_CASE("holes: a mesh whose faces are all holes is refused, not refined to nothing") {
  MeshData mesh = cube_mesh();
  mesh.holes = {0, 1, 2, 3, 4, 5};
  CHECK(contains(error_of([&] { level_from_mesh(mesh, "cube.obj"); }), "cube.obj: all 6 faces are holes"));
  mesh.holes.pop_back();
  CHECK(level_from_mesh(mesh, "cube.obj").face_count() == 6);
}

TEST_CASE("OFF: colours of any finite value read back (fuzz_write_read: a whole 6e293 was taken for an int)") {
  TempDir dir;
  MeshData mesh = cube_mesh();
  DataArray colour{"color", 3, std::vector<double>(18, 6.367880534469101e+293), false, ArrayRole::Color};
  mesh.cell_data.push_back(colour);
  write_mesh(dir / "colours.off", mesh);
  const MeshData back = read_mesh(dir / "colours.off");
  REQUIRE(back.cell_data.size() == 1);
  CHECK(!back.cell_data[0].integer);
  CHECK(back.cell_data[0].values == colour.values);
}

TEST_CASE("VTK XML: subnormal values give ranges that read back") {
  TempDir dir;
  MeshData mesh = cube_mesh();
  DataArray tiny{"tiny", 3, {}, false};
  for (Index v = 0; v < mesh.vertex_count(); ++v) tiny.values.insert(tiny.values.end(), {1e-320, -3e-315, 0.0});
  DataArray single{"single", 1, std::vector<double>(8, 4.9406564584124654e-324), false};
  mesh.point_data = {tiny, single};
  write_mesh(dir / "tiny.vtp", mesh);
  const MeshData back = read_mesh(dir / "tiny.vtp");
  REQUIRE(back.point_data.size() == 2);
  CHECK(back.point_data[0].values == tiny.values);
  CHECK(back.point_data[1].values == single.values);
  CHECK(vtk_read(dir / "tiny.vtp")->GetNumberOfPoints() == 8);
}

TEST_CASE("PLY: a property name holding the word end_header reads back (fuzz_write_read)") {
  TempDir dir;
  MeshData mesh = cube_with_point_array("vtkCompoend_header");
  write_mesh(dir / "word.ply", mesh);
  const MeshData back = read_mesh(dir / "word.ply");
  REQUIRE(back.point_data.size() == 1);
  CHECK(back.point_data[0].name == "vtkCompoend_header");
}
