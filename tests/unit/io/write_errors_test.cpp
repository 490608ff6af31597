// Writers refuse bad input before creating anything, and never leave half files.
#include <sys/stat.h>

#include "framework/io/formats.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/util/atomic_file.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

TEST_CASE("write_mesh: a missing directory is reported and nothing is created") {
  TempDir dir;
  const fs::path target = dir / "no" / "such" / "dir" / "out.obj";
  const std::string e = error_of([&] { write_mesh(target, cube_mesh()); });
  CHECK(contains(e, "out.obj"));
  CHECK(contains(e, "does not exist"));
  CHECK(dir.entries().empty());
}

TEST_CASE("write_mesh: a file name longer than the file system allows is refused by name, nothing created") {
  TempDir dir;
  for (const char* ext : {".obj", ".vtp"}) {
    const fs::path target = dir / (std::string(300, 'x') + ext);
    const std::string e = error_of([&] { write_mesh(target, cube_mesh()); });
    CHECK(contains(e, "file name is 304 bytes long"));
    CHECK(dir.entries().empty());
  }
  // A name that fits must not fail because its temporary name (longer) would not.
  const fs::path fits = dir / (std::string(250, 'y') + ".obj");
  write_mesh(fits, cube_mesh());
  CHECK(fs::exists(fits));
}

TEST_CASE("write_mesh: a target that is a FIFO, a link to a device or a directory is refused and stays as it was") {
  // Renaming the finished temporary would replace it: as root, -o /dev/null turned the
  // device into a plain file. The link to /dev/null shows it without touching /dev.
  TempDir dir;
  REQUIRE(::mkfifo((dir / "pipe.obj").c_str(), 0600) == 0);
  fs::create_symlink("/dev/null", dir / "null.vtp");
  fs::create_directory(dir / "folder.obj");
  struct Bad {
    const char* name;
    const char* message;
  };
  for (const Bad& b : {Bad{"pipe.obj", "is a FIFO (named pipe), which writing would replace by a plain file"},
                       Bad{"null.vtp", "is a character device, which writing would replace by a plain file"},
                       Bad{"folder.obj", "is a directory; name a file, in it or beside it"}}) {
    CAPTURE(b.name);
    CHECK(contains(error_of([&] { write_mesh(dir / b.name, cube_mesh()); }), b.message));
  }
  CHECK(fs::is_fifo(dir / "pipe.obj"));
  CHECK(fs::is_symlink(dir / "null.vtp"));
  CHECK(fs::is_character_file(dir / "null.vtp"));
  CHECK(fs::is_directory(dir / "folder.obj"));
  // No temporary left (entries() would resolve the link to /dev/null).
  CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 3);
  CHECK(fs::is_empty(dir / "folder.obj"));
  // A link to a regular file is written as before (the link replaced by the new file).
  write_text(dir / "real.obj", "old");
  fs::create_symlink(dir / "real.obj", dir / "link.obj");
  write_mesh(dir / "link.obj", cube_mesh());
  CHECK(fs::is_regular_file(dir / "link.obj"));
}

TEST_CASE("write_mesh: invalid meshes are refused before any file exists") {
  TempDir dir;
  MeshData bad = cube_mesh();
  std::string expected;
  SUBCASE("index out of range") {
    bad.face_vertices[5] = 8;
    expected = "face 1 refers to vertex 8";
  }
  SUBCASE("negative index") {
    bad.face_vertices[0] = -1;
    expected = "face 0 refers to vertex -1";
  }
  SUBCASE("face with two vertices") {
    bad.face_offsets = {0, 2, 24};
    expected = "face 0 has 2 vertices";
  }
  SUBCASE("offsets that do not match the index array") {
    bad.face_offsets.back() = 30;
    expected = "face offsets end at 30";
  }
  SUBCASE("non-finite coordinate") {
    bad.positions[13] = std::numeric_limits<double>::quiet_NaN();
    expected = "vertex 4 has a non-finite coordinate";
  }
  SUBCASE("crease on a missing vertex") {
    bad.creases.push_back({0, 9, 1.0});
    expected = "crease 0-9 names a vertex that does not exist";
  }
  SUBCASE("negative corner sharpness") {
    bad.corners.push_back({0, -2.0});
    expected = "corner 0 has sharpness -2";
  }
  SUBCASE("polyline out of range") {
    bad.line_offsets = {0, 2};
    bad.line_vertices = {0, 100};
    expected = "polyline 0 refers to vertex 100";
  }
  for (const char* name : {"out.obj", "out.off", "out.ply", "out.stl", "out.vtp", "out.pvd"}) {
    CAPTURE(name);
    const std::string e = error_of([&] { write_mesh(dir / name, bad); });
    CHECK(contains(e, name));
    CHECK(contains(e, expected));
  }
  CHECK(dir.entries().empty());
}

TEST_CASE("write_mesh: a failed write leaves an existing target untouched") {
  TempDir dir;
  write_mesh(dir / "keep.obj", cube_mesh());
  const std::string before = read_text(dir / "keep.obj");
  MeshData bad = cube_mesh();
  bad.face_vertices[0] = 42;
  CHECK_THROWS_AS(write_mesh(dir / "keep.obj", bad), Error);
  CHECK(read_text(dir / "keep.obj") == before);
  CHECK(dir.entries() == std::vector<std::string>{"keep.obj"});
}

TEST_CASE("write_mesh: unknown extension lists the supported ones") {
  TempDir dir;
  const std::string e = error_of([&] { write_mesh(dir / "out.xyz", cube_mesh()); });
  CHECK(contains(e, "out.xyz"));
  CHECK(contains(e, supported_output_formats()));
  CHECK(dir.entries().empty());
}

TEST_CASE("write_mesh: STL refuses coordinates beyond float range") {
  TempDir dir;
  MeshData big = cube_mesh();
  big.positions[0] = 1e300;
  CHECK(contains(error_of([&] { write_mesh(dir / "big.stl", big); }), "too large for STL"));
  CHECK(dir.entries().empty());
}

TEST_CASE("write_file_atomically: an exception mid-write removes the temporary") {
  TempDir dir;
  write_text(dir / "target.txt", "old");
  CHECK_THROWS_AS(write_file_atomically(dir / "target.txt",
                                        [](const fs::path& tmp) {
                                          write_text(tmp, "half of the new con");
                                          throw Error("disk full");
                                        }),
                  Error);
  CHECK(read_text(dir / "target.txt") == "old");
  CHECK(dir.entries() == std::vector<std::string>{"target.txt"});

  write_file_atomically(dir / "target.txt", [&](const fs::path& tmp) {
    CHECK(tmp.parent_path() == dir.path());  // same file system, so rename is atomic
    CHECK(tmp != dir / "target.txt");
    write_text(tmp, "new");
    CHECK(read_text(dir / "target.txt") == "old");  // readers still see the old file
  });
  CHECK(read_text(dir / "target.txt") == "new");
  CHECK(dir.entries() == std::vector<std::string>{"target.txt"});
}

TEST_CASE("StagedFiles: temporaries live next to their targets and vanish without commit") {
  TempDir dir;
  fs::create_directory(dir / "sub");
  {
    StagedFiles files;
    const fs::path a = files.stage(dir / "a.txt");
    const fs::path b = files.stage(dir / "sub" / "b.txt");
    CHECK(a.parent_path() == dir.path());
    CHECK(b.parent_path() == dir / "sub");
    CHECK(a != b);
    write_text(a, "a");
    write_text(b, "b");
  }
  CHECK(dir.entries() == std::vector<std::string>{"sub"});
  StagedFiles files;
  write_text(files.stage(dir / "a.txt"), "a");
  write_text(files.stage(dir / "sub" / "b.txt"), "b");
  files.commit();
  CHECK(dir.entries() == std::vector<std::string>{"a.txt", "sub", "sub/b.txt"});
  CHECK(read_text(dir / "sub" / "b.txt") == "b");
}
