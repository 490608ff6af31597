// Real-world meshes a first-day user brings: a face repeating a vertex, an edge with three
// faces, a bow-tie vertex, a face written twice, files saved by Windows editors with a UTF-8
// byte-order mark. Commands that need a manifold mesh name the file, the place (face, edge or
// vertex, counted from 0) and the repair, exit 1 and leave no file; a byte-order mark is
// not part of the first line.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_checks.h"
#include "support/cli_runner.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

fs::path write(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

const std::string kBom = "\xEF\xBB\xBF";
const std::string kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("refine --adaptive, parameterize: a face repeating a vertex (f 1 2 2 3) names the file, the face and the fix") {
  const auto dir = fresh_dir("hostile-meshes-repeat");
  const fs::path mesh = write(dir / "repeat.obj", kQuad + "v 2 0 0\nf 1 2 2 3\nf 2 5 3\n");
  for (const std::string command : {"refine " + mesh.string() + " --adaptive 2", "parameterize " + mesh.string()}) {
    CAPTURE(command);
    check_refused(command, dir / "out.obj",
                  "repeat.obj: ");  // the file, in front
    check_refused(command, dir / "out.obj",
                  "face 0 repeats vertex 1 (its edge 1-1 joins the vertex to itself) (faces and vertices counted "
                  "from 0); remove the repeat from the face");
  }
  // Not next to each other: no edge from the vertex to itself.
  const fs::path apart = write(dir / "apart.obj", kQuad + "v 2 0 0\nf 1 2 3 2\nf 2 5 3\n");
  check_refused("refine " + apart.string() + " --adaptive 2", dir / "out.obj",
                "apart.obj: adaptive refinement needs faces with distinct corners, but face 0 repeats vertex 1 (faces "
                "and vertices counted from 0)");
}

TEST_CASE("refine --adaptive: an edge of three faces, a bow-tie vertex and a face written twice are refined") {
  const auto dir = fresh_dir("hostile-meshes-places");
  const fs::path edge = write(dir / "fin.obj", "v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 -1 0\nv 0.5 0 1\n"
                                               "f 1 2 3\nf 2 1 4\nf 1 2 5\n");
  const fs::path bow = write(dir / "bow.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n");
  const fs::path twice = write(dir / "twice.obj", kQuad + "f 1 2 3 4\nf 1 2 3 4\n");
  // The limit surface of a sequence (its head refines a manifold mesh only) names the place.
  const fs::path at = write(dir / "at.csv", "face,u,v\n0,0.5,0.5\n");
  check_refused("evaluate " + bow.string() + " -s catmull-clark:1,catmull-clark --at " + at.string(), dir / "d.csv",
                "bow.obj: limit evaluation at (face, u, v) of a scheme sequence needs a manifold mesh, but the faces "
                "around vertex 0 (0, 1) meet only at the vertex");
  // Uniform and adaptive refinement take them all, as OpenSubdiv does (adaptively with Loop,
  // as the triangles need; tests/unit/limit/adaptive_non_manifold_test.cpp checks the result).
  for (const fs::path& mesh : {edge, bow, twice}) {
    CAPTURE(mesh.string());
    CHECK(run_subdiv("refine " + mesh.string() + " -q -o " + (dir / "ok.vtp").string()).exit_code == 0);
    const std::string scheme = mesh == twice ? "" : " -s loop";
    const CliResult r = run_subdiv("refine " + mesh.string() + " --adaptive 2 --limit" + scheme + " -q -o " +
                                   (dir / "adaptive.vtp").string());
    CHECK_MESSAGE(r.exit_code == 0, r.output);
  }
}

TEST_CASE("interpolate: a non-manifold mesh names the file and the place, not the eigenvalues") {
  const auto dir = fresh_dir("hostile-meshes-interpolate");
  const fs::path bow = write(dir / "bow.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n");
  const CliResult r = run_subdiv("interpolate " + bow.string() + " -o " + (dir / "out.obj").string());
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(contains(r.output, "bow.obj: scheme 'catmull-clark' has no limit mask at the non-manifold places of "
                                   "this mesh"),
                r.output);
  CHECK_MESSAGE(contains(r.output, "give each fan its own copy of the vertex"), r.output);
  CHECK_FALSE(fs::exists(dir / "out.obj"));
}

TEST_CASE("a UTF-8 byte-order mark is not part of the first line of an OBJ, OFF or PLY mesh") {
  const auto dir = fresh_dir("hostile-meshes-bom");
  const std::string ply_header = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n";
  // The mark before the first vertex used to hide it: face 1 2 3 4 then named a vertex 4 of 3.
  const fs::path obj = write(dir / "bom.obj", kBom + kQuad + "f 1 2 3 4\n");
  const fs::path crlf = write(dir / "bom-crlf.obj", kBom + "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf 1 2 3 4\r\n");
  const fs::path off = write(dir / "bom.off", kBom + "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  const fs::path ply = write(dir / "bom.ply", kBom + ply_header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  for (const fs::path& mesh : {obj, crlf, off, ply}) {
    CAPTURE(mesh);
    const CliResult r = run_subdiv("refine " + mesh.string() + " -o " + (dir / "out.obj").string());
    CHECK_MESSAGE(r.exit_code == 0, r.output);
    // Level 1 of one quad: 9 vertices, 4 faces (all four base vertices read).
    CHECK_MESSAGE(contains(r.output, "-> 9 vertices, 4 faces"), r.output);
  }
}

TEST_CASE("an ASCII STL with a byte-order mark is refused naming the mark, not as 'not an STL file'") {
  const auto dir = fresh_dir("hostile-meshes-bom-stl");
  const fs::path stl = write(dir / "bom.stl", kBom + "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                                     "vertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\nendsolid t\n");
  check_refused("refine " + stl.string(), dir / "out.vtp", "bom.stl: the file starts with a UTF-8 byte-order mark");
}

TEST_CASE("--select and --vertex-param files saved with a byte-order mark are read from their first value") {
  const auto dir = fresh_dir("hostile-meshes-bom-values");
  const std::string cube = source_path("examples/meshes/cube.obj");
  const fs::path select = write(dir / "select.txt", kBom + "0,1\n");
  CliResult r = run_subdiv("interpolate " + cube + " -q --select " + select.string() + " -o " +
                           (dir / "a.obj").string());
  CHECK_MESSAGE(r.exit_code == 0, r.output);
  std::string lambdas = kBom;
  for (int v = 0; v < 8; ++v) lambdas += "0.5\n";
  const fs::path lambda = write(dir / "lambda.txt", lambdas);
  r = run_subdiv("refine " + cube + " -q -s catmull-clark-shape --vertex-param lambda=" + lambda.string() + " -o " +
                 (dir / "b.obj").string());
  CHECK_MESSAGE(r.exit_code == 0, r.output);
}

TEST_CASE("-l 30: refused at once with the memory in units a person reads; with --pieces, not 'ask for more pieces'") {
  const auto dir = fresh_dir("hostile-meshes-levels");
  const std::string octahedron = source_path("examples/meshes/octahedron.obj");
  // 8 * 4^30 faces at ~300 bytes each: about 2.3e21 bytes, some 2e6 PiB.
  check_refused("refine " + octahedron + " -l 30", dir / "a.vtp", "PiB, but only");
  const CliResult r = run_subdiv("refine " + octahedron + " -l 30 -o " + (dir / "b.vtp").string());
  CHECK_FALSE(contains(r.output, "0.0 GiB"));  // not "1932735283200.0 GiB"
  // One face refined 30 levels fits no machine: more pieces cannot help, fewer levels can.
  check_refused("refine " + octahedron + " -l 30 --pieces 4", dir / "c.pvtp",
                "even one face refined 30 levels would not fit: no number of pieces helps; ask for fewer levels");
  CHECK_FALSE(fs::exists(dir / "c_pieces"));
}
