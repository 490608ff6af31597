// What SubdivKit writes as OBJ, OFF, PLY and STL reads back (issue 33): with SubdivKit bit
// for bit (the text formats print each double in its shortest round-trip form, PLY stores
// doubles), and with VTK's own readers (vtkOBJReader, vtkPLYReader, vtkSTLReader), which
// store 32-bit floats: there every coordinate is the float nearest the written double.
// Extreme values (near the largest double, subnormals, -0), many faces and n-gons. OBJ and
// STL refuse numbers beyond float range (VTK's OBJ reader reads -1.8e308 as 0); PLY
// declares its doubles, and VTK's float points then hold them as infinities of their sign.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "unit/io/io_test_support.h"

#if SUBDIV_HAVE_VTK_GEOMETRY_READERS
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#endif

using namespace subdiv;
using namespace subdiv::test;

namespace {

constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kSubnormal = std::numeric_limits<double>::denorm_min();

// A quad and a triangle whose coordinates are the extreme doubles; `within_float`: those
// beyond float range replaced by float-sized ones.
MeshData extreme_mesh(bool within_float = false) {
  MeshData m;
  m.positions = {1e308,       -kMax,
                 kSubnormal,  //
                 -0.0,        std::numeric_limits<double>::min() / 3,
                 1e-300,  //
                 0.1,         -0.0,
                 -kSubnormal,  //
                 1,           1,
                 1,  //
                 3e38,        -3e38,
                 1e-45};
  if (within_float) m.positions[0] = 3.4e38, m.positions[1] = -3.4e38;
  m.face_offsets = {0, 4, 7};
  m.face_vertices = {0, 1, 2, 3, 2, 1, 4};
  return m;
}

// One face of n sides around a circle, and an n x n grid of quads beside it.
MeshData ngon_and_grid(int sides, int n) {
  MeshData m;
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * M_PI * i / sides;
    m.positions.insert(m.positions.end(), {std::cos(a), std::sin(a), 0.0});
    m.face_vertices.push_back(i);
  }
  m.face_offsets.push_back(sides);
  const Index first = sides;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.insert(m.positions.end(), {3.0 + i * 0.01, j * 0.01, 0.25});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index a = first + j * (n + 1) + i;
      m.face_vertices.insert(m.face_vertices.end(), {a, a + 1, a + n + 2, a + n + 1});
      m.face_offsets.push_back(Index(m.face_vertices.size()));
    }
  return m;
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void check_same_bits(const MeshData& a, const MeshData& b) {
  REQUIRE(a.positions.size() == b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    CAPTURE(i);
    CHECK(same_bits(a.positions[i], b.positions[i]));
  }
  CHECK(a.face_offsets == b.face_offsets);
  CHECK(a.face_vertices == b.face_vertices);
}

}  // namespace

TEST_CASE("OBJ, OFF and PLY read back bit for bit near the largest double, at subnormals and at -0") {
  TempDir dir;
  for (const bool within_float : {false, true}) {
    const MeshData mesh = extreme_mesh(within_float);
    for (const char* ext : {".obj", ".off", ".ply"}) {
      const std::string format = ext;
      CAPTURE(format);
      CAPTURE(within_float);
      if (format == ".obj" && !within_float) continue;  // refused, below
      write_mesh(dir / ("extreme" + format), mesh);
      check_same_bits(mesh, read_mesh(dir / ("extreme" + format)));
    }
  }
}

TEST_CASE("OBJ: numbers beyond 32-bit float range are refused before any file exists, naming the vertex") {
  TempDir dir;
  CHECK_THROWS_WITH_AS(write_mesh(dir / "x.obj", extreme_mesh()),
                       doctest::Contains("vertex 0 has the value 1e+308, beyond the 32-bit float range OBJ readers "
                                         "use"),
                       Error);
  MeshData uv = extreme_mesh(true);
  uv.point_data.push_back({"uv", 2, {0, 0, 1, 0, 1, 1, 0, 1, 0, -1e39}, false, ArrayRole::TextureCoordinates});
  CHECK_THROWS_WITH_AS(write_mesh(dir / "x.obj", uv), doctest::Contains("texture coordinate 4 has the value -1e+39"),
                       Error);
  CHECK(dir.entries().empty());
}

TEST_CASE("OBJ, OFF and PLY read back a 1000-gon beside 40,000 quads; PLY counts the big face in an int") {
  TempDir dir;
  const MeshData mesh = ngon_and_grid(1000, 200);
  for (const char* ext : {".obj", ".off", ".ply"}) {
    const std::string format = ext;
    CAPTURE(format);
    write_mesh(dir / ("big" + format), mesh);
    check_same_bits(mesh, read_mesh(dir / ("big" + format)));
  }
  // STL: one triangle per side of each polygon but two (fans), floats equal to the doubles.
  write_mesh(dir / "big.stl", mesh);
  const MeshData stl = read_mesh(dir / "big.stl");
  CHECK(stl.face_count() == 998 + 2 * 200 * 200);
}

TEST_CASE("STL: coordinates beyond 32-bit floats are refused before any file exists; subnormals become floats") {
  TempDir dir;
  CHECK_THROWS_WITH_AS(write_mesh(dir / "x.stl", extreme_mesh()),
                       doctest::Contains("too large for STL's 32-bit floats"), Error);
  CHECK(dir.entries().empty());
  write_mesh(dir / "small.stl", extreme_mesh(true));
  const MeshData back = read_mesh(dir / "small.stl");
  CHECK(back.face_count() == 3);  // the quad as two triangles, and the triangle
  for (double x : back.positions) CHECK(std::isfinite(x));
}

#if SUBDIV_HAVE_VTK_GEOMETRY_READERS
namespace {

template <typename Reader>
vtkSmartPointer<vtkPolyData> vtk_read(const fs::path& file) {
  vtkNew<Reader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

vtkSmartPointer<vtkPolyData> vtk_read_any(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".obj") return vtk_read<vtkOBJReader>(file);
  if (ext == ".ply") return vtk_read<vtkPLYReader>(file);
  return vtk_read<vtkSTLReader>(file);
}

// VTK's point as the float nearest each written double within float range (a float reader's
// best); beyond it the float is infinite with the double's sign, which is VTK's storage,
// not the file.
void check_vtk_points(const MeshData& mesh, vtkPolyData* data) {
  REQUIRE(data->GetNumberOfPoints() == mesh.vertex_count());
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    double p[3];
    data->GetPoint(v, p);
    for (int c = 0; c < 3; ++c) {
      const double x = mesh.positions[3 * std::size_t(v) + std::size_t(c)];
      CAPTURE(v);
      CAPTURE(x);
      if (std::abs(x) <= std::numeric_limits<float>::max())
        CHECK(float(p[c]) == float(x));
      else
        CHECK((std::isinf(p[c]) && std::signbit(p[c]) == std::signbit(x)));
    }
  }
}

}  // namespace

void check_vtk_faces(const MeshData& mesh, vtkPolyData* data) {
  REQUIRE(data->GetNumberOfPolys() == mesh.face_count());
  vtkCellArray* polys = data->GetPolys();
  for (Index f = 0; f < mesh.face_count(); ++f) {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    polys->GetCellAtId(f, size, ids);
    REQUIRE(size == mesh.face_offsets[f + 1] - mesh.face_offsets[f]);
    for (vtkIdType k = 0; k < size; ++k) CHECK(ids[k] == mesh.face_vertices[std::size_t(mesh.face_offsets[f] + k)]);
  }
}

TEST_CASE("VTK's OBJ and PLY readers read SubdivKit's files: every point and face, extreme values as floats") {
  TempDir dir;
  for (const char* ext : {".obj", ".ply"}) {
    const std::string format = ext;
    CAPTURE(format);
    // OBJ refuses what float readers misread; PLY's doubles beyond float range become
    // infinities of their sign in VTK's float points.
    const MeshData mesh = extreme_mesh(format == ".obj");
    write_mesh(dir / ("extreme" + format), mesh);
    const auto data = vtk_read_any(dir / ("extreme" + format));
    check_vtk_points(mesh, data);
    check_vtk_faces(mesh, data);
  }
  // Many faces and a 255-gon: vtkPLYReader keeps a face's size in one byte (VTK 9.1,
  // vtkPLYReader.cxx's plyFace), so a PLY face of more corners, which SubdivKit writes with
  // an int count and reads back, is beyond VTK (docs/formats.md).
  const MeshData big = ngon_and_grid(255, 100);
  for (const char* ext : {".obj", ".ply"}) {
    const std::string format = ext;
    CAPTURE(format);
    write_mesh(dir / ("big" + format), big);
    const auto data = vtk_read_any(dir / ("big" + format));
    check_vtk_points(big, data);
    check_vtk_faces(big, data);
  }
  write_mesh(dir / "ngon.obj", ngon_and_grid(1000, 2));
  check_vtk_faces(ngon_and_grid(1000, 2), vtk_read_any(dir / "ngon.obj"));
}

TEST_CASE("VTK's STL reader reads SubdivKit's binary STL: the triangles, subnormals and -0 as floats") {
  TempDir dir;
  const MeshData mesh = extreme_mesh(true);
  write_mesh(dir / "out.stl", mesh);
  const auto data = vtk_read<vtkSTLReader>(dir / "out.stl");
  CHECK(data->GetNumberOfPolys() == 3);
  // vtkSTLReader merges equal points: every one of its points is a written vertex as float.
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    bool found = false;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
      bool same = true;
      for (int c = 0; c < 3; ++c)
        same = same && float(p[c]) == float(mesh.positions[3 * std::size_t(v) + std::size_t(c)]);
      found = found || same;
    }
    CHECK(found);
  }
}
#endif
