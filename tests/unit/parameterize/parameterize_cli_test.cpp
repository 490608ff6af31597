// `subdiv parameterize` and `subdiv refine --weights` end to end: the files they write, what
// they refuse (exit 1, the reason, no file left behind).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "framework/io/mesh_data.h"
#include "framework/io/mesh_read.h"
#include "support/cli_runner.h"

namespace subdiv {
namespace {

void write_text(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

// A 3 x 3 quad grid with a raised middle: 16 vertices, 12 on the boundary.
std::string grid_obj() {
  std::string text;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      text += "v " + std::to_string(i) + " " + std::to_string(j) + " " + ((i == 1 || i == 2) && (j == 1 || j == 2) ? "1" : "0") + "\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = 4 * j + i + 1;
      text += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 5) + " " + std::to_string(a + 4) + "\n";
    }
  return text;
}

}  // namespace

TEST_CASE("subdiv parameterize writes OBJ vt that subdiv refine carries as face-varying data") {
  const auto dir = test::fresh_dir("parameterize-cli");
  write_text(dir / "grid.obj", grid_obj());
  const auto made = test::run_subdiv("parameterize " + (dir / "grid.obj").string() + " --boundary-shape square -o " +
                                     (dir / "uv.obj").string());
  REQUIRE(made.exit_code == 0);
  CHECK(made.output.find("12 on the boundary, corners 0 3 15 12") != std::string::npos);
  const MeshData uv = read_mesh(dir / "uv.obj");
  REQUIRE(uv.face_varying.size() == 1);
  const auto& values = uv.face_varying[0].values;
  CHECK(values[2 * 15] == 1.0);  // the corner (3, 3) at the square's corner (1, 1)
  CHECK(values[2 * 15 + 1] == 1.0);
  const auto refined = test::run_subdiv("refine " + (dir / "uv.obj").string() + " -l 2 -o " + (dir / "r.obj").string());
  REQUIRE(refined.exit_code == 0);
  const MeshData r = read_mesh(dir / "r.obj");
  REQUIRE(r.face_varying.size() == 1);
  CHECK(r.face_varying[0].indices.size() == r.face_vertices.size());
}

TEST_CASE("subdiv parameterize refuses a mesh that is no disc and leaves no file") {
  const auto dir = test::fresh_dir("parameterize-cli-refused");
  const auto out = dir / "cube-uv.obj";
  const auto r = test::run_subdiv("parameterize " + test::source_path("examples/meshes/cube.obj") + " -o " + out.string());
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("the mesh has 0 boundary loops; a topological disc has exactly one") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("subdiv refine --weights: a named PLY array, OBJ's fourth coordinate back out, refusals") {
  const auto dir = test::fresh_dir("rational-cli");
  write_text(dir / "w.ply",
             "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
             "property float rw\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
             "0 0 0 1\n1 0 0 3\n1 1 0 1\n0 1 0 1\n4 0 1 2 3\n");
  const auto ok = test::run_subdiv("refine " + (dir / "w.ply").string() + " -s bilinear --weights rw -o " +
                                   (dir / "w.obj").string());
  REQUIRE(ok.exit_code == 0);
  // Bilinear: the edge point of (0,0,0) w=1 and (1,0,0) w=3 is (0·1 + 1·3)/(1 + 3) = 3/4, weight 2.
  std::ifstream in(dir / "w.obj");
  std::string line;
  bool found = false;
  while (std::getline(in, line)) found = found || line == "v 0.75 0 0 2";
  CHECK(found);
  const auto missing = test::run_subdiv("refine " + (dir / "w.ply").string() + " -s bilinear --weights nope -o " +
                                        (dir / "x.obj").string());
  CHECK(missing.exit_code == 1);
  CHECK(missing.output.find("no point array 'nope' holds the rational weights; its point arrays are 'rw'") !=
        std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "x.obj"));
  write_text(dir / "bad.obj", "v 0 0 0\nv 1 0 0 0\nv 1 1 0\nf 1 2 3\n");
  const auto bad = test::run_subdiv("refine " + (dir / "bad.obj").string() + " -o " + (dir / "y.obj").string());
  CHECK(bad.exit_code == 1);
  CHECK(bad.output.find("bad.obj:2: vertex 2 has the weight w = 0") != std::string::npos);
}

}  // namespace subdiv
