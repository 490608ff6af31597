// The hand-written OFF and PLY readers.
#include <bit>
#include <cstdint>
#include <cstring>

#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

std::string error_reading(const TempDir& dir, const std::string& name, const std::string& text) {
  write_text(dir / name, text);
  return error_of([&] { read_mesh(dir / name); });
}

}  // namespace

TEST_CASE("off: polygons of any size in file order, comments, counts on the keyword line") {
  TempDir dir;
  write_text(dir / "m.off",
             "OFF 5 2 0\n"
             "# comment\n"
             "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1e-3\n"
             "\n"
             "4 3 2 1 0\n"
             "5 0 1 2 3 4\n");
  const MeshData m = read_mesh(dir / "m.off");
  CHECK(m.vertex_count() == 5);
  CHECK(m.positions[14] == 1e-3);
  CHECK(m.face_offsets == std::vector<Index>{0, 4, 9});
  CHECK(m.face_vertices == std::vector<Index>{3, 2, 1, 0, 0, 1, 2, 3, 4});
}

TEST_CASE("off: COFF vertex colours and face colours become colour arrays") {
  TempDir dir;
  write_text(dir / "m.off",
             "COFF\n3 1 3\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n"
             "3 0 1 2 0.5 0.5 0.5\n");
  const MeshData m = read_mesh(dir / "m.off");
  CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  CHECK(m.face_vertices == std::vector<Index>{0, 1, 2});
  REQUIRE(m.point_data.size() == 1);
  CHECK(m.point_data[0].name == "color");
  CHECK(m.point_data[0].role == ArrayRole::Color);
  CHECK(m.point_data[0].components == 4);
  CHECK(m.point_data[0].integer);  // whole numbers beyond 1: 0..255 colours
  CHECK(m.point_data[0].values == std::vector<double>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255});
  REQUIRE(m.cell_data.size() == 1);
  CHECK_FALSE(m.cell_data[0].integer);  // 0..1 floats
  CHECK(m.cell_data[0].values == std::vector<double>{0.5, 0.5, 0.5});
}

TEST_CASE("off: NOFF normals and STOFF texture coordinates, in Geomview's order; a short line is refused") {
  TempDir dir;
  write_text(dir / "m.off", "STCNOFF\n3 1 0\n0 0 0 0 0 1 1 0 0 0.25 0.5\n1 0 0 0 0 1 0 1 0 0.75 0.5\n"
                            "0 1 0 0 0 1 0 0 1 0.5 1\n3 0 1 2\n");
  const MeshData m = read_mesh(dir / "m.off");
  REQUIRE(m.point_data.size() == 3);
  CHECK(m.point_data[0].role == ArrayRole::Normals);
  CHECK(m.point_data[1].role == ArrayRole::Color);
  CHECK(m.point_data[1].components == 3);
  CHECK(m.point_data[2].role == ArrayRole::TextureCoordinates);
  CHECK(m.point_data[2].values == std::vector<double>{0.25, 0.5, 0.75, 0.5, 0.5, 1});
  CHECK(m.cell_data.empty());
  CHECK(contains(error_reading(dir, "s.off", "COFF\n3 1 0\n0 0 0 1 0\n1 0 0 1 0 0\n0 1 0 1 0 0\n3 0 1 2\n"),
                 "s.off:3: vertex 0 has 2 values after x y z"));
}

TEST_CASE("ply and off: point and cell arrays survive a write and a read") {
  TempDir dir;
  MeshData m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  m.face_offsets = {0, 4};
  m.face_vertices = {0, 1, 2, 3};
  m.point_data = {{"temperature", 1, {1.5, -2, 3.25, 1e-300}, false},
                  {"seven", 7, std::vector<double>(28, 0.125), false},
                  {"uv", 2, {0, 0, 1, 0, 1, 1, 0, 1}, false, ArrayRole::TextureCoordinates},
                  {"color", 3, {255, 0, 0, 0, 255, 0, 0, 0, 255, 9, 9, 9}, true, ArrayRole::Color},
                  {"label", 1, {-7, 0, 7, 100000}, true}};
  m.cell_data = {{"material", 1, {12}, true}, {"weight", 2, {0.5, 0.25}, false}};
  write_mesh(dir / "m.ply", m);
  const MeshData p = read_mesh(dir / "m.ply");
  REQUIRE(p.point_data.size() == m.point_data.size());
  for (size_t i = 0; i < m.point_data.size(); ++i) {
    CAPTURE(m.point_data[i].name);
    CHECK(p.point_data[i].name == m.point_data[i].name);
    CHECK(p.point_data[i].components == m.point_data[i].components);
    CHECK(p.point_data[i].values == m.point_data[i].values);
    CHECK(p.point_data[i].integer == m.point_data[i].integer);
    CHECK(p.point_data[i].role == m.point_data[i].role);
  }
  REQUIRE(p.cell_data.size() == 2);
  CHECK(p.cell_data[0].values == m.cell_data[0].values);
  CHECK(p.cell_data[1].name == "weight");
  CHECK(p.cell_data[1].values == m.cell_data[1].values);
  // OFF holds colours, normals and texture coordinates only.
  write_mesh(dir / "m.off", m);
  const MeshData o = read_mesh(dir / "m.off");
  REQUIRE(o.point_data.size() == 2);
  CHECK(o.point_data[0].name == "color");
  CHECK(o.point_data[0].values == m.point_data[3].values);
  CHECK(o.point_data[1].name == "uv");
  CHECK(o.point_data[1].values == m.point_data[2].values);
}

TEST_CASE("off: errors name file and line") {
  TempDir dir;
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  CHECK(contains(error_reading(dir, "b.off", head + "3 0 1 3\n"), "b.off:6: face refers to vertex 3"));
  CHECK(contains(error_reading(dir, "b.off", head + "2 0 1\n"), "b.off:6: a face needs at least 3"));
  CHECK(contains(error_reading(dir, "b.off", "OFF\n3 1 0\n0 0 0\n"),
                 "the file ends after 1 of the 3 vertices"));
  CHECK(contains(error_reading(dir, "b.off", "OFF\n1 0 0\n0 inf 0\n"),
                 "b.off:3: vertex 0 has a non-finite coordinate"));
  CHECK(contains(error_reading(dir, "b.off", "PLY\n"), "b.off:1: expected the header keyword OFF"));
  CHECK(contains(error_reading(dir, "b.off", "OFF BINARY\n"), "binary OFF is not supported"));
}

TEST_CASE("ply: ASCII with extra properties and elements") {
  TempDir dir;
  write_text(dir / "m.ply",
             "ply\nformat ascii 1.0\ncomment made by hand\n"
             "element vertex 4\nproperty float nx\nproperty double x\nproperty double y\n"
             "property double z\nproperty uchar red\n"
             "element face 2\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
             "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
             "end_header\n"
             "9 0.1 0.2 0.3 255\n9 1 0 0 0\n9 1 1 0 0\n9 0 1 0 0\n"
             "7 3 0 1 2\n7 3 0 2 3\n"
             "0 1\n");
  const MeshData m = read_mesh(dir / "m.ply");
  CHECK(m.positions == std::vector<double>{0.1, 0.2, 0.3, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  CHECK(m.face_vertices == std::vector<Index>{0, 1, 2, 0, 2, 3});
}

TEST_CASE("ply: binary big-endian with float coordinates and a ushort face count") {
  TempDir dir;
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list ushort uint vertex_indices\nend_header\n";
  auto put = [&](auto value) {
    unsigned char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    if (std::endian::native == std::endian::little) std::reverse(raw, raw + sizeof value);
    bytes.append(reinterpret_cast<char*>(raw), sizeof value);
  };
  for (float c : {0.5f, 0.25f, -1.0f, 2.0f, 0.0f, 0.0f, 0.0f, 4.0f, 8.0f}) put(c);
  put(std::uint16_t(3));
  for (std::uint32_t v : {2u, 1u, 0u}) put(v);
  write_text(dir / "m.ply", bytes);
  const MeshData m = read_mesh(dir / "m.ply");
  CHECK(m.positions == std::vector<double>{0.5, 0.25, -1, 2, 0, 0, 0, 4, 8});
  CHECK(m.face_vertices == std::vector<Index>{2, 1, 0});

  SUBCASE("a truncated file is reported, not read past its end") {
    write_text(dir / "cut.ply", bytes.substr(0, bytes.size() - 3));
    const std::string e = error_of([&] { read_mesh(dir / "cut.ply"); });
    CHECK(contains(e, "cut.ply"));
    CHECK(contains(e, "ends inside face 0"));
  }
}

TEST_CASE("ply: errors name file, line and element") {
  TempDir dir;
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n";
  CHECK(contains(error_reading(dir, "b.ply", head + "3 0 1 5\n"),
                 "b.ply:13: face 0 refers to vertex 5"));
  CHECK(contains(error_reading(dir, "b.ply", head + "2 0 1\n"), "b.ply:13: face 0 has 2 vertices"));
  CHECK(contains(error_reading(dir, "b.ply", head + "3 0 x 2\n"), "b.ply:13: expected an integer"));
  const std::string nan_head = head.substr(0, head.find("0 0 0\n")) + "0 0 0\nnan 0 0\n0 1 0\n";
  CHECK(contains(error_reading(dir, "b.ply", nan_head + "3 0 1 2\n"),
                 "b.ply:11: vertex 1 has a non-finite coordinate"));
  CHECK(contains(error_reading(dir, "b.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                             "property float x\nend_header\n0\n"),
                 "lacks one of the properties x, y, z"));
  CHECK(contains(error_reading(dir, "b.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                             "property quad x\nend_header\n"),
                 "b.ply:4: unknown property type 'quad'"));
  CHECK(contains(error_reading(dir, "b.ply", "solid\n"), "b.ply:1: a PLY file must start"));
}

TEST_CASE("ply and off keep non-manifold faces as written") {
  TempDir dir;
  write_text(dir / "nm.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n"
                             "3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  const MeshData m = read_mesh(dir / "nm.off");
  CHECK(m.face_vertices == std::vector<Index>{0, 1, 2, 1, 0, 3, 0, 1, 4});
}
