// write_mesh then read_mesh, for every output format.
#include <algorithm>
#include <array>
#include <map>

#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

TEST_CASE("round trip: OBJ keeps coordinates bit for bit, faces, polylines and tags") {
  TempDir dir;
  const MeshData original = sample_mesh();
  write_mesh(dir / "m.obj", original);
  const MeshData m = read_mesh(dir / "m.obj");
  CHECK(m.positions == original.positions);  // exact: shortest round-trip printing
  check_same_faces(m, original);
  CHECK(m.line_offsets == original.line_offsets);
  CHECK(m.line_vertices == original.line_vertices);
  REQUIRE(m.creases.size() == original.creases.size());
  for (size_t i = 0; i < m.creases.size(); ++i) {
    CHECK(m.creases[i].v0 == original.creases[i].v0);
    CHECK(m.creases[i].v1 == original.creases[i].v1);
    CHECK(m.creases[i].sharpness == original.creases[i].sharpness);
  }
  REQUIRE(m.corners.size() == 1);
  CHECK(m.corners[0].v == original.corners[0].v);
  CHECK(m.corners[0].sharpness == original.corners[0].sharpness);
}

TEST_CASE("round trip: OFF and PLY keep double coordinates and polygons") {
  TempDir dir;
  const MeshData original = sample_mesh();
  for (const char* name : {"m.off", "m.ply", "M.PLY"}) {
    CAPTURE(name);
    write_mesh(dir / name, original);
    const MeshData m = read_mesh(dir / name);
    check_same_positions(m, original, 1e-12);
    check_same_faces(m, original);
    CHECK(m.line_count() == 0);  // these formats have no polylines or tags
    CHECK(m.creases.empty());
  }
}

TEST_CASE("round trip: PLY with a polygon of more than 255 vertices") {
  TempDir dir;
  MeshData disk;
  const int n = 300;
  for (int i = 0; i < n; ++i) {
    disk.positions.insert(disk.positions.end(), {std::cos(i * 0.02), std::sin(i * 0.02), 0.0});
    disk.face_vertices.push_back(i);
  }
  disk.face_offsets = {0, n};
  write_mesh(dir / "disk.ply", disk);
  const MeshData m = read_mesh(dir / "disk.ply");
  check_same_positions(m, disk, 1e-12);
  check_same_faces(m, disk);
}

TEST_CASE("round trip: STL stores triangle fans in 32-bit floats") {
  TempDir dir;
  MeshData original = cube_mesh();
  original.positions[0] = 0.1;  // not a float: comes back as float(0.1)
  write_mesh(dir / "cube.stl", original);
  const MeshData m = read_mesh(dir / "cube.stl");
  CHECK(m.vertex_count() == 8);
  CHECK(m.face_count() == 12);  // 6 quads, 2 triangles each

  // STL does not store vertex order, so match vertices by their float-rounded positions.
  using Point = std::array<double, 3>;
  auto point = [](const MeshData& mesh, Index v, bool round) {
    Point p{mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
    if (round)
      for (double& c : p) c = double(float(c));
    return p;
  };
  std::map<Point, Index> original_vertex;
  for (Index v = 0; v < original.vertex_count(); ++v) original_vertex[point(original, v, true)] = v;
  std::vector<Index> to_original(m.vertex_count());
  for (Index v = 0; v < m.vertex_count(); ++v) {
    const auto it = original_vertex.find(point(m, v, false));
    REQUIRE(it != original_vertex.end());
    to_original[v] = it->second;
  }
  // Every triangle read is the fan triangle (v0, vk, vk+1) of an original face, in order.
  std::vector<std::array<Index, 3>> fans;
  for (Index f = 0; f < original.face_count(); ++f) {
    const Index first = original.face_offsets[f];
    for (Index k = first + 1; k + 1 < original.face_offsets[f + 1]; ++k)
      fans.push_back({original.face_vertices[first], original.face_vertices[k],
                      original.face_vertices[k + 1]});
  }
  for (Index f = 0; f < m.face_count(); ++f) {
    const std::array<Index, 3> t{to_original[m.face_vertices[3 * f]],
                                 to_original[m.face_vertices[3 * f + 1]],
                                 to_original[m.face_vertices[3 * f + 2]]};
    CHECK(std::find(fans.begin(), fans.end(), t) != fans.end());
  }
}

TEST_CASE("round trip: VTP keeps polylines, creases and corners through write_mesh") {
  TempDir dir;
  const MeshData original = sample_mesh();
  write_mesh(dir / "m.vtp", original);
  const MeshData m = read_mesh(dir / "m.vtp");
  CHECK(m.positions == original.positions);
  check_same_faces(m, original);
  CHECK(m.line_offsets == original.line_offsets);
  CHECK(m.line_vertices == original.line_vertices);
  REQUIRE(m.creases.size() == 2);
  CHECK(m.creases[1].v0 == 2);
  CHECK(m.creases[1].v1 == 3);
  CHECK(m.creases[1].sharpness == 0.5);
  REQUIRE(m.corners.size() == 1);
  CHECK(m.corners[0].v == 4);
  CHECK(m.corners[0].sharpness == 2.25);
}

TEST_CASE("round trip: OBJ keeps texture coordinates with their seams; arrays of the wrong length are refused") {
  TempDir dir;
  // Two quads sharing the edge 1-4, cut along it in UV space (vertices 1 and 4 have two vt).
  MeshData m;
  m.positions = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
  m.face_offsets = {0, 4, 8};
  m.face_vertices = {0, 1, 4, 3, 1, 2, 5, 4};
  m.face_varying.push_back({"uv", 2, {0, 0, .5, 0, .5, 1, 0, 1, .6, 0, 1, 0, 1, 1, .6, 1},
                            {0, 1, 2, 3, 4, 5, 6, 7}, ArrayRole::TextureCoordinates});
  write_mesh(dir / "uv.obj", m);
  const MeshData back = read_mesh(dir / "uv.obj");
  REQUIRE(back.face_varying.size() == 1);
  CHECK(back.face_varying[0].role == ArrayRole::TextureCoordinates);
  CHECK(back.face_varying[0].indices == m.face_varying[0].indices);
  CHECK(back.face_varying[0].values == m.face_varying[0].values);
  // The seam: the corners of vertex 1 in the two faces use different values.
  CHECK(back.face_varying[0].indices[1] != back.face_varying[0].indices[4]);

  MeshData bad = m;
  bad.point_data.push_back({"t", 1, {1, 2, 3}, false});
  CHECK_THROWS_WITH_AS(write_mesh(dir / "bad.ply", bad), doctest::Contains("point data array 't' has 3 values"), Error);
  CHECK_FALSE(std::filesystem::exists(dir / "bad.ply"));
  bad = m;
  bad.face_varying[0].indices.pop_back();
  CHECK_THROWS_WITH_AS(write_mesh(dir / "bad.obj", bad), doctest::Contains("has 7 corner indices for 8 face corners"),
                       Error);
}
