// Formats read through libraries (OpenMesh: STL, OM; VTK: .vtp, .vtk) and the dispatch
// in read_mesh.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>

#include "framework/io/formats.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

std::string ascii_stl(const std::vector<std::array<const char*, 3>>& triangles) {
  std::string s = "solid test\n";
  for (const auto& t : triangles) {
    s += "facet normal 0 0 0\nouter loop\n";
    for (const char* v : t) s += std::string("vertex ") + v + "\n";
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid test\n";
}

}  // namespace

TEST_CASE("read_mesh: missing file, directory and unknown extension") {
  TempDir dir;
  const std::string missing = error_of([&] { read_mesh(dir / "missing.obj"); });
  CHECK(contains(missing, "cannot open '"));
  CHECK(contains(missing, "missing.obj': no such file"));
  fs::create_directory(dir / "folder.obj");
  CHECK(contains(error_of([&] { read_mesh(dir / "folder.obj"); }), "is a directory"));
  write_text(dir / "mesh.xyz", "1 2 3\n");
  const std::string unknown = error_of([&] { read_mesh(dir / "mesh.xyz"); });
  CHECK(contains(unknown, "mesh.xyz"));
  CHECK(contains(unknown, "'.xyz'"));
  CHECK(contains(unknown, supported_input_formats()));
}

TEST_CASE("read_mesh: extensions are case-insensitive") {
  TempDir dir;
  write_text(dir / "TRI.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK(read_mesh(dir / "TRI.OBJ").face_count() == 1);
}

TEST_CASE("stl: ASCII triangles share vertices with equal coordinates") {
  TempDir dir;
  write_text(dir / "quad.stl", ascii_stl({{"0 0 0", "1 0 0", "1 1 0"}, {"0 0 0", "1 1 0", "0 1 0"}}));
  const MeshData m = read_mesh(dir / "quad.stl");
  CHECK(m.vertex_count() == 4);
  CHECK(m.face_count() == 2);
  // Both triangles keep their corner order: each one's first corner is the origin.
  for (Index f = 0; f < 2; ++f) {
    const Index v = m.face_vertices[m.face_offsets[f]];
    CHECK(m.positions[3 * v] == 0.0);
    CHECK(m.positions[3 * v + 1] == 0.0);
  }
}

TEST_CASE("stl: a non-manifold edge is refused, not silently split") {
  TempDir dir;
  write_text(dir / "fin.stl", ascii_stl({{"0 0 0", "1 0 0", "0 1 0"},
                                         {"1 0 0", "0 0 0", "0 -1 0"},
                                         {"0 0 0", "1 0 0", "0 0 1"}}));
  const std::string e = error_of([&] { read_mesh(dir / "fin.stl"); });
  CHECK(contains(e, "fin.stl"));
  CHECK(contains(e, "not manifold"));
}

TEST_CASE("om: OpenMesh's own format keeps vertices and faces") {
  TempDir dir;
  struct Traits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
  };
  OpenMesh::PolyMesh_ArrayKernelT<Traits> mesh;
  const MeshData cube = cube_mesh();
  std::vector<OpenMesh::VertexHandle> v;
  for (Index i = 0; i < cube.vertex_count(); ++i)
    v.push_back(mesh.add_vertex({cube.positions[3 * i], cube.positions[3 * i + 1],
                                 cube.positions[3 * i + 2]}));
  for (Index f = 0; f < cube.face_count(); ++f) {
    std::vector<OpenMesh::VertexHandle> face;
    for (Index k = cube.face_offsets[f]; k < cube.face_offsets[f + 1]; ++k)
      face.push_back(v[cube.face_vertices[k]]);
    mesh.add_face(face);
  }
  ::omlog().disable();  // OpenMesh's writer logs the byte count
  const bool written = OpenMesh::IO::write_mesh(mesh, (dir / "cube.om").string());
  ::omlog().enable();
  REQUIRE(written);
  const MeshData m = read_mesh(dir / "cube.om");
  check_same_positions(m, cube, 0);
  check_same_faces(m, cube);
}

TEST_CASE("vtk: legacy POLYDATA polygons, strips and lines") {
  TempDir dir;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 5; ++i) points->InsertNextPoint(i, i * i, 0.5 * i);
  vtkNew<vtkCellArray> polys, strips, lines;
  const vtkIdType quad[] = {0, 1, 2, 3}, strip[] = {0, 1, 2, 3}, line[] = {4, 0, 1};
  polys->InsertNextCell(4, quad);
  strips->InsertNextCell(4, strip);
  lines->InsertNextCell(3, line);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->SetStrips(strips);
  poly->SetLines(lines);
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->SetFileName((dir / "m.vtk").c_str());
  writer->SetFileTypeToBinary();
  REQUIRE(writer->Write() == 1);

  const MeshData m = read_mesh(dir / "m.vtk");
  CHECK(m.vertex_count() == 5);
  CHECK(m.positions[3 * 4 + 1] == 16.0);
  // The quad, then the strip as two triangles with the strip's orientation.
  CHECK(m.face_offsets == std::vector<Index>{0, 4, 7, 10});
  CHECK(m.face_vertices == std::vector<Index>{0, 1, 2, 3, 0, 1, 2, 2, 1, 3});
  CHECK(m.line_vertices == std::vector<Index>{4, 0, 1});
}

TEST_CASE("vtk: a file that is not PolyData is refused with its name") {
  TempDir dir;
  write_text(dir / "junk.vtp", "<VTKFile type=\"ImageData\"></VTKFile>\n");
  const std::string xml = error_of([&] { read_mesh(dir / "junk.vtp"); });
  CHECK(contains(xml, "junk.vtp"));
  CHECK(contains(xml, "not a VTK XML PolyData file"));
  write_text(dir / "grid.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET STRUCTURED_POINTS\n");
  const std::string legacy = error_of([&] { read_mesh(dir / "grid.vtk"); });
  CHECK(contains(legacy, "grid.vtk"));
  CHECK(contains(legacy, "POLYDATA"));
}

TEST_CASE("vtk: a truncated .vtp is refused with the reason, without VTK's boilerplate") {
  TempDir dir;
  MeshData big;
  for (int i = 0; i < 3000; ++i) {
    big.positions.insert(big.positions.end(), {std::sin(i * 1.0), std::cos(i * 2.0), i * 1e-3});
    if (i >= 2) big.face_vertices.insert(big.face_vertices.end(), {i - 2, i - 1, i});
    if (i >= 2) big.face_offsets.push_back(Index(big.face_vertices.size()));
  }
  write_mesh(dir / "whole.vtp", big);
  const std::string bytes = read_text(dir / "whole.vtp");
  write_text(dir / "cut.vtp", bytes.substr(0, bytes.size() / 2));
  const std::string e = error_of([&] { read_mesh(dir / "cut.vtp"); });
  // The data headers are checked before VTK reads (vtk_xml_blocks.h): the place is named.
  CHECK(contains(e, "cut.vtp:"));
  CHECK(contains(e, "the file is cut off"));
  CHECK_FALSE(contains(e, "ERROR: In"));
  CHECK_FALSE(contains(e, "\n"));
}
