// The hand-written OBJ reader: syntax it accepts, tags, order and non-manifold input kept
// intact, and every error naming file and line.
#include "framework/io/mesh_read.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

MeshData read_obj_text(const TempDir& dir, const std::string& text, const char* name = "m.obj") {
  write_text(dir / name, text);
  return read_mesh(dir / name);
}

std::string obj_error(const TempDir& dir, const std::string& text) {
  write_text(dir / "bad.obj", text);
  return error_of([&] { read_mesh(dir / "bad.obj"); });
}

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("obj: vertices, faces in every reference form, comments and groups") {
  TempDir dir;
  const MeshData m = read_obj_text(dir,
                                   "# a comment\n"
                                   "mtllib x.mtl\n"
                                   "o thing\n"
                                   "v 0 0 0\n"
                                   "v 1.5 -2e-3 +4   # trailing comment\n"
                                   "v 1 1 0 1.0\n"  // w is allowed and ignored
                                   "v 0 1 0 0.5 0.5 0.5\n"  // vertex colours too
                                   "vt 0 0\nvn 0 0 1\n"
                                   "g group\nusemtl red\ns 1\n"
                                   "f 1/1/1 2/1/1 3/1/1\n"
                                   "f 1//1 3//1 4//1\n"
                                   "f 4/2 3/2 2/2 1/2\n");
  CHECK(m.vertex_count() == 4);
  CHECK(m.positions[3] == 1.5);
  CHECK(m.positions[4] == -2e-3);
  CHECK(m.positions[5] == 4.0);
  CHECK(m.face_offsets == std::vector<Index>{0, 3, 6, 10});
  CHECK(m.face_vertices == std::vector<Index>{0, 1, 2, 0, 2, 3, 3, 2, 1, 0});
}

TEST_CASE("obj: negative indices count back from the last vertex defined so far") {
  TempDir dir;
  const MeshData m = read_obj_text(dir, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
                                        "v 1 1 0\nf -4 -2 -1\n");
  CHECK(m.face_vertices == std::vector<Index>{0, 1, 2, 0, 2, 3});
}

TEST_CASE("obj: faces may refer to vertices defined further down") {
  TempDir dir;
  const MeshData m = read_obj_text(dir, "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  CHECK(m.face_count() == 1);
  CHECK(m.face_vertices == std::vector<Index>{0, 1, 2});
}

TEST_CASE("obj: CRLF line endings and backslash continuation lines") {
  TempDir dir;
  const MeshData m =
      read_obj_text(dir, "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf 1 2 \\\r\n 3 4\r\n");
  CHECK(m.face_count() == 1);
  CHECK(m.face_vertices == std::vector<Index>{0, 1, 2, 3});
}

TEST_CASE("obj: polylines, crease and corner tags in Pixar's format") {
  TempDir dir;
  const MeshData m = read_obj_text(dir,
                                   "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 2\n"
                                   "f 1 2 3 4\n"
                                   "l 4 5\nl 1/1 2/2 5/3\n"
                                   "t crease 2/1/0 0 1 10\n"
                                   "t crease 4/2/0 1 2 2 3 1.5 2.5\n"
                                   "t corner 2/1/0 0 3 4\n"
                                   "t interpolateboundary 1/0/0 1\n");
  CHECK(m.line_offsets == std::vector<Index>{0, 2, 5});
  CHECK(m.line_vertices == std::vector<Index>{3, 4, 0, 1, 4});
  REQUIRE(m.creases.size() == 3);
  CHECK(m.creases[0].v0 == 0);
  CHECK(m.creases[0].v1 == 1);
  CHECK(m.creases[0].sharpness == 10.0);
  CHECK(m.creases[1].v0 == 1);
  CHECK(m.creases[1].v1 == 2);
  CHECK(m.creases[1].sharpness == 1.5);
  CHECK(m.creases[2].v0 == 2);
  CHECK(m.creases[2].v1 == 3);
  CHECK(m.creases[2].sharpness == 2.5);
  REQUIRE(m.corners.size() == 2);
  CHECK(m.corners[0].v == 0);
  CHECK(m.corners[1].v == 3);
  CHECK(m.corners[1].sharpness == 4.0);
}

TEST_CASE("obj: non-manifold faces and vertex order reach the caller unchanged") {
  TempDir dir;
  // Three triangles on edge 1-2 (a non-manifold edge) plus a bowtie at vertex 1: a reader
  // that builds half-edges would have to drop or split these.
  const MeshData m = read_obj_text(dir,
                                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\n"
                                   "v 2 0 0\nv 2 -1 0\n"
                                   "f 2 3 1\nf 3 2 4\nf 2 3 5\nf 2 6 7\n");
  CHECK(m.vertex_count() == 7);
  CHECK(m.face_vertices == std::vector<Index>{1, 2, 0, 2, 1, 3, 1, 2, 4, 1, 5, 6});
  CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 2, 0, 0,
                                           2, -1, 0});
}

TEST_CASE("obj: errors name the file, the line and the problem") {
  TempDir dir;
  const std::string t = kTriangle;

  SUBCASE("a coordinate that is not a number") {
    const std::string e = obj_error(dir, "v 0 0 0\nv 1 zero 0\n");
    CHECK(contains(e, "bad.obj:2:"));
    CHECK(contains(e, "expected a number"));
    CHECK(contains(e, "'zero'"));
  }
  SUBCASE("a vertex with two coordinates") {
    CHECK(contains(obj_error(dir, "v 1 2\n"), "bad.obj:1: a vertex needs 3 coordinates"));
  }
  SUBCASE("faces that use vt numbers in a file with no vt (found by fuzz_read_obj: a division by zero)") {
    const std::string e = obj_error(dir, t + "f 1/1 2/2 3/3\n");
    CHECK(contains(e, "bad.obj:4: this face uses vt number 3, but the file has 0"));
  }
  SUBCASE("a face index beyond the last vertex") {
    const std::string e = obj_error(dir, t + "f 1 2 9\n");
    CHECK(contains(e, "bad.obj:4:"));
    CHECK(contains(e, "vertex 9"));
    CHECK(contains(e, "only 3 vertices"));
  }
  SUBCASE("a relative index before the first vertex") {
    const std::string e = obj_error(dir, t + "f -1 -2 -4\n");
    CHECK(contains(e, "bad.obj:4:"));
    CHECK(contains(e, "-4"));
  }
  SUBCASE("vertex number 0") {
    CHECK(contains(obj_error(dir, t + "f 0 1 2\n"), "bad.obj:4: vertex number 0 is invalid"));
  }
  SUBCASE("a malformed vertex reference") {
    CHECK(contains(obj_error(dir, t + "f 1 2 a/3\n"), "bad.obj:4: expected a vertex number"));
  }
  SUBCASE("NaN and infinite coordinates") {
    const std::string nan = obj_error(dir, "v 0 0 0\nv 1 nan 0\n");
    CHECK(contains(nan, "bad.obj:2:"));
    CHECK(contains(nan, "vertex 2 has a non-finite coordinate"));
    const std::string inf = obj_error(dir, "v 0 0 0\nv 0 0 0\nv 1e999 0 0\n");
    CHECK(contains(inf, "bad.obj:3: vertex 3 has a non-finite coordinate"));
  }
  SUBCASE("a face with fewer than 3 vertices") {
    const std::string e = obj_error(dir, t + "f 1 2\n");
    CHECK(contains(e, "bad.obj:4:"));
    CHECK(contains(e, "at least 3 vertices"));
  }
  SUBCASE("a polyline with one vertex") {
    CHECK(contains(obj_error(dir, t + "l 1\n"), "bad.obj:4: a polyline 'l' needs at least 2"));
  }
  SUBCASE("negative crease sharpness") {
    const std::string e = obj_error(dir, t + "f 1 2 3\nt crease 2/1/0 0 1 -1\n");
    CHECK(contains(e, "bad.obj:5:"));
    CHECK(contains(e, "sharpness -1"));
  }
  SUBCASE("NaN corner sharpness") {
    CHECK(contains(obj_error(dir, t + "f 1 2 3\nt corner 1/1/0 0 nan\n"), "bad.obj:5:"));
  }
  SUBCASE("a crease naming a vertex that does not exist") {
    const std::string e = obj_error(dir, t + "f 1 2 3\nt crease 2/1/0 2 3 1\n");
    CHECK(contains(e, "bad.obj:5:"));
    CHECK(contains(e, "vertex 3, which does not exist"));
  }
  SUBCASE("a corner naming a vertex that does not exist") {
    CHECK(contains(obj_error(dir, t + "f 1 2 3\nt corner 1/1/0 -1 1\n"), "bad.obj:5: corner tag"));
  }
  SUBCASE("a crease between vertices that share no edge") {
    const std::string e = obj_error(dir, t + "v 5 5 5\nf 1 2 3\nt crease 2/1/0 0 3 1\n");
    CHECK(contains(e, "bad.obj:6:"));
    CHECK(contains(e, "not an edge"));
  }
  SUBCASE("a crease with an odd number of vertices") {
    CHECK(contains(obj_error(dir, t + "f 1 2 3\nt crease 3/1/0 0 1 2 1\n"),
                   "bad.obj:5: a crease tag needs pairs"));
  }
  SUBCASE("a tag whose counts do not match its values") {
    const std::string e = obj_error(dir, t + "f 1 2 3\nt crease 2/1/0 0 1\n");
    CHECK(contains(e, "bad.obj:5:"));
    CHECK(contains(e, "missing"));
  }
  SUBCASE("a hierarchical edit (gone from OpenSubdiv 3)") {
    const std::string e = obj_error(dir, t + "f 1 2 3\nt vertexedit 1/0/0 0\n");
    CHECK(contains(e, "bad.obj:5: tag 'vertexedit' is a hierarchical edit"));
  }
  SUBCASE("a tag OpenSubdiv does not know") {
    const std::string e = obj_error(dir, t + "f 1 2 3\nt sparkle 1/0/0 0\n");
    CHECK(contains(e, "bad.obj:5: tag 'sparkle' is not one of OpenSubdiv's tags"));
  }
  SUBCASE("a forward reference that never gets its vertex") {
    const std::string e = obj_error(dir, "f 1 2 4\n" + t);
    CHECK(contains(e, "bad.obj:1:"));
    CHECK(contains(e, "vertex 4"));
  }
}

TEST_CASE("obj: a continued statement reports its first line") {
  TempDir dir;
  const std::string e = obj_error(dir, std::string(kTriangle) + "f 1 \\\n 2 \\\n 7\n");
  CHECK(contains(e, "bad.obj:4:"));
}
