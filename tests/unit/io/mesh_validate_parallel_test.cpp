// validate_mesh_data checks large meshes on every core first (framework/io/mesh_validate.cpp);
// when something is wrong, the message still names the first problem in order, as the
// element-by-element walk names it.
#include <cmath>
#include <limits>
#include <utility>

#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>

#include "framework/io/mesh_validate.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// A strip of n quads: enough elements for many parallel ranges.
MeshData strip(int n) {
  MeshData m;
  for (int i = 0; i <= n; ++i) m.positions.insert(m.positions.end(), {double(i), 0, 0, double(i), 1, 0});
  for (int i = 0; i < n; ++i) {
    m.face_vertices.insert(m.face_vertices.end(), {2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
    m.face_offsets.push_back(Index(m.face_vertices.size()));
  }
  DataArray id{"id", 1, {}, true};
  for (int i = 0; i < n; ++i) id.values.push_back(i);
  m.cell_data.push_back(id);
  return m;
}

std::string problem(const MeshData& m) {
  return error_of([&] { validate_mesh_data(m, "ctx"); });
}

}  // namespace

TEST_CASE("validate_mesh_data on a large mesh: valid passes, and the first of several problems is named") {
  const int n = 200000;
  CHECK(problem(strip(n)) == "<no error>");

  MeshData m = strip(n);
  m.face_vertices[4 * 150000 + 2] = -1;
  m.face_vertices[4 * 120000 + 1] = 2 * n + 2;  // the first
  CHECK(problem(m) == "ctx: face 120000 refers to vertex 400002, but the mesh has 400002 vertices (numbered from 0)");

  m = strip(n);
  m.face_offsets[170001] = m.face_offsets[170000] + 2;  // face 170000 has 2 vertices, 170001 six
  CHECK(problem(m) == "ctx: face 170000 has 2 vertices; a face needs at least 3");

  m = strip(n);
  m.positions[3 * 300000 + 1] = std::numeric_limits<double>::infinity();
  m.positions[3 * 250000 + 2] = std::nan("");
  CHECK(contains(problem(m), "ctx: vertex 250000 has a non-finite coordinate"));

  m = strip(n);
  m.cell_data[0].values[190000] = 0.5;
  m.cell_data[0].values[180000] = 3e10;
  CHECK(contains(problem(m), "integer face data array 'id' holds 30000000000 at face 180000"));
}

// The ranges validate_mesh_data reports on its way are the ones VTK computes itself
// (vtkDataArray::GetRange: the points' Euclidean norms, the connectivity's values), which
// write_vtp puts into the file's headers.
TEST_CASE("validate_mesh_data's value ranges are VTK's own ranges of the same arrays") {
  MeshData m = strip(50000);
  for (std::size_t i = 0; i < m.positions.size(); ++i) m.positions[i] = std::sin(0.37 * double(i)) * 1e3 + 0.1 * double(i % 7);
  std::swap(m.face_vertices[7], m.face_vertices[40001]);  // extremes away from the ends
  MeshValueRanges ranges;
  validate_mesh_data(m, "ctx", &ranges);

  vtkNew<vtkDoubleArray> points;
  points->SetNumberOfComponents(3);
  points->SetArray(m.positions.data(), vtkIdType(m.positions.size()), 1);
  double norms[2];
  points->GetRange(norms, -1);
  REQUIRE(ranges.point_norms_known);
  CHECK(ranges.point_norm_min == norms[0]);
  CHECK(ranges.point_norm_max == norms[1]);

  vtkNew<vtkIntArray> faces;
  faces->SetArray(m.face_vertices.data(), vtkIdType(m.face_vertices.size()), 1);
  double values[2];
  faces->GetRange(values, 0);
  REQUIRE(ranges.face_vertices_known);
  CHECK(double(ranges.face_vertex_min) == values[0]);
  CHECK(double(ranges.face_vertex_max) == values[1]);

  // Squares that overflow (coordinates of finite 1e200): valid, the norms left to a scaled computation.
  m.positions[4] = 1e200;
  validate_mesh_data(m, "ctx", &ranges);
  CHECK_FALSE(ranges.point_norms_known);
  CHECK(ranges.face_vertices_known);

  MeshData empty;
  validate_mesh_data(empty, "ctx", &ranges);
  CHECK_FALSE(ranges.point_norms_known);
  CHECK_FALSE(ranges.face_vertices_known);
}
