// Bounds on what an input may ask for before any work is done (issue 33): scheme files of
// megabytes, thread counts beyond the cores.
#include <fstream>

#include "framework/scheme/curve_scheme.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/util/input_file.h"
#include "framework/util/thread_count.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

TEST_CASE("a file over its kind's size limit is refused with its size before it is read") {
  TempDir dir;
  const fs::path sparse = dir / "huge.json";
  {
    std::ofstream out(sparse, std::ios::binary);
    out.seekp(std::streamoff(1) << 30);  // 1 GiB, sparse: no disk space, no memory
    out.put('}');
  }
  const std::string e = error_of([&] { read_input_file(sparse, "scheme", 4'000'000); });
  CHECK(contains(e, "huge.json': it is 1073741825 bytes (1073.7 MB), more than the 4 MB a scheme file may have"));
  write_text(dir / "small.json", "{}");
  CHECK(read_input_file(dir / "small.json", "scheme", 4'000'000) == "{}");
}

TEST_CASE("thread counts: 0 means all cores, more than the cores is capped with a note, negative is refused") {
  const int cores = available_cores();
  CHECK(cores >= 1);
  CHECK(capped_thread_count(0).threads == 0);
  CHECK(capped_thread_count(1).threads == 1);
  CHECK(capped_thread_count(1).note.empty());
  const ThreadCount huge = capped_thread_count(2147483647);
  CHECK(huge.threads == cores);
  CHECK(contains(huge.note, "--threads 2147483647 is more than the"));
  CHECK(contains(error_of([] { capped_thread_count(-3, "threads="); }), "threads= -3"));
}

TEST_CASE("schemes: a curve rule's start is bounded, and so are the steps of a level") {
  const auto curve = [](const std::string& start) {
    return "{\"name\": \"c\", \"kind\": \"curve\", \"arity\": 2, \"rules\": [{\"start\": " + start +
           ", \"w\": [\"3/4\", \"1/4\"]}, {\"start\": 0, \"w\": [\"1/4\", \"3/4\"]}]}";
  };
  CHECK(load_curve_text(curve("-1"), "c.json")->starts[0] == -1);
  CHECK(contains(error_of([&] { load_curve_text(curve("-2147483648"), "c.json"); }),
                 "-2147483648 is out of range: a rule starts at most 64 old points away"));
  // 64 smoothing passes are allowed, 128 are not.
  const auto scheme = [](const std::string& passes) {
    return "{\"name\": \"s\", \"faces\": \"any\", \"steps\": [{\"split\": \"quad\", \"rules\": {"
           "\"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}], \"edge\": [{\"sum\": \"ends\", \"w\": \"1/2\"}], "
           "\"vertex\": [{\"at\": \"self\", \"w\": \"1\"}]}}" +
           passes + "]}";
  };
  const std::string pass = ", {\"repeat\": \"64\", \"smooth\": {\"vertex\": {\"smooth\": [{\"sum\": "
                           "\"face-centroids\", \"w\": \"1/n\"}]}}}";
  CHECK(load_scheme_text(scheme(pass), "s.json")->steps.size() == 65);
  CHECK(contains(error_of([&] { load_scheme_text(scheme(pass + pass), "s.json"); }),
                 "the smoothing passes (repeats included) come to more than 64 per level"));
}

TEST_CASE("binary PLY: a file far larger than its header can describe is refused before it is read") {
  TempDir dir;
  const fs::path ply = dir / "sparse.ply";
  write_mesh(ply, cube_mesh());
  const auto size = fs::file_size(ply);
  REQUIRE(read_mesh(ply).face_count() == 6);
  fs::resize_file(ply, std::uintmax_t(1) << 30);  // sparse: the cube, then a gigabyte of holes
  const std::string e = error_of([&] { read_mesh(ply); });
  CHECK(contains(e, "sparse.ply: the file has 1073741824 bytes, but its header describes at most"));
  fs::resize_file(ply, size + 100);  // a little trailing data is tolerated, as before
  CHECK(read_mesh(ply).face_count() == 6);
}

TEST_CASE("reading a .pvd says what it is and which file to read instead") {
  TempDir dir;
  write_mesh(dir / "run.pvd", cube_mesh());
  const std::string e = error_of([&] { read_mesh(dir / "run.pvd"); });
  CHECK(contains(e, "a .pvd is ParaView's index of level files, not a mesh: read one of them instead"));
  CHECK(contains(e, (dir / "run_levels" / "level_0.vtp").string()));
  CHECK(!contains(e, "built without"));
}
