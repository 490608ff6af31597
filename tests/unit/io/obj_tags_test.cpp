// Every OBJ tag OpenSubdiv reads and writes (regression/common/shape_utils.cpp): read into
// MeshData, refused with file and line when malformed, and written back so that a round
// trip keeps each one.
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// A quad strip of three faces with every tag OpenSubdiv knows.
const char* kTagged =
    "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nv 3 1 0\n"
    "f 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n"
    "t crease 2/1/0 1 5 2.5\n"
    "t corner 1/1/0 0 10\n"
    "t hole 1/0/0 1\n"
    "t interpolateboundary 1/0/0 2\n"
    "t creasemethod 0/0/1 chaikin\n"
    "t smoothtriangles 0/0/1 smooth\n"
    "t facevaryinginterpolateboundary 1/0/0 3\n"
    "t facevaryingpropagatecorners 1/0/0 1\n";

void check_every_tag(const MeshData& m) {
  REQUIRE(m.creases.size() == 1);
  CHECK(m.creases[0].v0 == 1);
  CHECK(m.creases[0].v1 == 5);
  CHECK(m.creases[0].sharpness == 2.5);
  REQUIRE(m.corners.size() == 1);
  CHECK(m.corners[0].v == 0);
  CHECK(m.corners[0].sharpness == 10);
  CHECK(m.holes == std::vector<Index>{1});
  CHECK(m.options.interpolate_boundary == 2);
  CHECK(m.options.crease_method == "chaikin");
  CHECK(m.options.smooth_triangles == "smooth");
  CHECK(m.options.fvar_interpolate_boundary == 3);
  CHECK(m.options.fvar_propagate_corners == 1);
}

std::string obj_error(const TempDir& dir, const std::string& text) {
  write_text(dir / "bad.obj", text);
  return error_of([&] { read_mesh(dir / "bad.obj"); });
}

}  // namespace

TEST_CASE("obj tags: every OpenSubdiv tag is read") {
  TempDir dir;
  write_text(dir / "m.obj", kTagged);
  check_every_tag(read_mesh(dir / "m.obj"));
}

TEST_CASE("obj tags: a round trip through OBJ keeps every tag") {
  TempDir dir;
  write_text(dir / "m.obj", kTagged);
  const MeshData first = read_mesh(dir / "m.obj");
  write_mesh(dir / "again.obj", first);
  const MeshData second = read_mesh(dir / "again.obj");
  check_every_tag(second);
  CHECK(second.face_vertices == first.face_vertices);
  CHECK(second.positions == first.positions);
}

TEST_CASE("obj tags: Hbr-era smoothtriangles with an integer") {
  TempDir dir;
  write_text(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt smoothtriangles 1/0/0 1\n");
  CHECK(read_mesh(dir / "m.obj").options.smooth_triangles == "smooth");
}

TEST_CASE("obj tags: malformed tags are refused with file, line and the values allowed") {
  TempDir dir;
  const std::string t = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  CHECK(contains(obj_error(dir, t + "t hole 1/0/0 4\n"), "bad.obj:5: hole tag names face 4"));
  CHECK(contains(obj_error(dir, t + "t interpolateboundary 1/0/0 7\n"), "bad.obj:5: tag 'interpolateboundary' takes one integer from 0 to 2"));
  CHECK(contains(obj_error(dir, t + "t creasemethod 0/0/1 sharp\n"), "normal or chaikin"));
  CHECK(contains(obj_error(dir, t + "t smoothtriangles 0/0/1 maybe\n"), "smooth or catmark"));
  for (const char* edit : {"vertexedit", "edgeedit", "faceedit"})
    CHECK(contains(obj_error(dir, t + "t " + edit + " 1/0/0 0\n"), "hierarchical edit"));
}
