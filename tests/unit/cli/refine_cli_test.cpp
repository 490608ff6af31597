#include <doctest/doctest.h>

#include <fstream>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "support/cli_checks.h"
#include "support/cli_runner.h"
#include "support/vtk_read.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {


}  // namespace

TEST_CASE("refine the bundled cube to .vtp and read it back: counts per level of the quad split") {
  const auto dir = fresh_dir("cli-vtp");
  const auto out = dir / "cube.vtp";
  const CliResult r = run_subdiv("refine " + source_path("examples/meshes/cube.obj") +
                                 " --scheme catmull-clark --levels 2 --arrays all -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const auto poly = read_vtp(out);
  // Cube: V=8, E=12, F=6. Level 1: 26 vertices, 24 quads, 48 edges; level 2: 98 vertices, 96 quads.
  CHECK(poly->GetNumberOfPoints() == 98);
  CHECK(poly->GetNumberOfPolys() == 96);
  CHECK(poly->GetPointData()->GetArray("origin") != nullptr);
  CHECK(poly->GetPointData()->GetArray("valence") != nullptr);
  CHECK(poly->GetCellData()->GetArray("parent_face") != nullptr);
  // Catmull-Clark shrinks the cube [-0.5, 0.5]^3: every point lies strictly inside it.
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
    double p[3];
    poly->GetPoint(i, p);
    for (double c : p) CHECK((c > -0.5 && c < 0.5));
  }
}

TEST_CASE("refine to .pvd writes one .vtp per level") {
  const auto dir = fresh_dir("cli-pvd");
  const auto out = dir / "oct.pvd";
  const CliResult r = run_subdiv("refine " + source_path("examples/meshes/octahedron.obj") +
                                 " --scheme loop --levels 2 -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(fs::exists(out));
  // Triangle split: F = 8, 32, 128.
  const int faces[] = {8, 32, 128};
  for (int l = 0; l <= 2; ++l) {
    const auto level = dir / "oct_levels" / ("level_" + std::to_string(l) + ".vtp");
    REQUIRE(fs::exists(level));
    CHECK(read_vtp(level)->GetNumberOfPolys() == faces[l]);
  }
}

TEST_CASE("--param and OBJ output") {
  const auto dir = fresh_dir("cli-obj");
  const auto out = dir / "oct.obj";
  const CliResult r = run_subdiv("refine " + source_path("examples/meshes/octahedron.obj") +
                                 " -s loop -l 1 --param beta=warren -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  std::ifstream in(out);
  int v = 0, f = 0;
  for (std::string line; std::getline(in, line);) v += line.rfind("v ", 0) == 0, f += line.rfind("f ", 0) == 0;
  CHECK(v == 18);
  CHECK(f == 32);
}

TEST_CASE("bad input: clear message, non-zero exit, no output file") {
  const auto dir = fresh_dir("cli-bad");
  const auto out = dir / "out.vtp";
  check_refused("refine " + (dir / "missing.obj").string(), out, "missing.obj");
  check_refused("refine " + source_path("examples/meshes/cube.obj") + " --scheme loop", out, "needs triangles");
  check_refused("refine " + source_path("examples/meshes/cube.obj") + " --scheme nosuch", out, "unknown scheme 'nosuch'");
  check_refused("refine " + source_path("examples/meshes/cube.obj") + " --param nope=1", out, "has a parameter 'nope'");

  std::ofstream(dir / "nan.obj") << "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n";
  check_refused("refine " + (dir / "nan.obj").string(), out, "non-finite");

  std::ofstream(dir / "nonmanifold.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                                            "f 1 2 3\nf 2 1 4\nf 1 2 5\n";
  // Primal schemes refine it as OpenSubdiv does, dual ones with a gap, sqrt3 with the hinge
  // kept as a crease: each says so once per level.
  const CliResult nm = run_subdiv("refine " + (dir / "nonmanifold.obj").string() + " --scheme sqrt3 -l 2 -o " +
                                  (dir / "nm.obj").string());
  CHECK(nm.exit_code == 0);
  CHECK(nm.output.find("subdiv: warning: level 1: the sqrt3 split") != std::string::npos);
  CHECK(nm.output.find("subdiv: warning: level 2: the sqrt3 split") != std::string::npos);
  std::ofstream(dir / "onevertex.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1\n";
  check_refused("refine " + (dir / "onevertex.obj").string(), out, "a face needs at least 3 vertices");
  std::ofstream(dir / "range.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
  check_refused("refine " + (dir / "range.obj").string(), out, "vertex 9");

  std::ofstream(dir / "broken.json") << "{ \"name\": \"b\", \"split\": \"quad\" \"rules\": {} }";
  check_refused("refine " + source_path("examples/meshes/cube.obj") + " --scheme " + (dir / "broken.json").string(),
                out, "broken.json:1:");

  check_refused("refine " + source_path("examples/meshes/cube.obj") + " --levels 29", out, "fewer levels");
  const CliResult r = run_subdiv("refine " + source_path("examples/meshes/cube.obj") + " -o " + (dir / "x.xyz").string());
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("unknown output format") != std::string::npos);
}

TEST_CASE("--vertex-param: one value at every vertex writes what --param writes; a vertex's own value moves only its point") {
  const auto dir = fresh_dir("cli-vertex-param");
  const std::string cube = source_path("examples/meshes/cube.obj");
  auto values = [&](const std::string& name, double first) {
    std::ofstream f(dir / name);
    f << "# lambda per vertex\n" << first << "\n";
    for (int v = 1; v < 8; ++v) f << "0.6\n";
    return (dir / name).string();
  };
  auto refine = [&](const std::string& options, const std::string& out) {
    const CliResult r = run_subdiv("refine " + cube + " --scheme catmull-clark-shape -l 1 " + options + " -o " +
                                   (dir / out).string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::ifstream in(dir / out);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  CHECK(refine("--vertex-param lambda=" + values("same.txt", 0.6), "a.obj") == refine("--param lambda=0.6", "b.obj"));
  // Vertex 0 at lambda = 1 stays where it is (v' = v; its vertex point is the first vertex
  // written); with lambda = 0.6 everywhere it moves inside the cube.
  auto first_vertex = [](const std::string& obj) { return obj.substr(obj.find("\nv ") + 1, obj.find('\n', obj.find("\nv ") + 1) - obj.find("\nv ") - 1); };
  std::ifstream in(cube);
  const std::string original(std::istreambuf_iterator<char>(in), {});
  CHECK(first_vertex(refine("--vertex-param lambda=" + values("one.txt", 1.0), "c.obj")) == first_vertex(original));
  CHECK(first_vertex(refine("--param lambda=0.6", "d.obj")) != first_vertex(original));
  check_refused("refine " + cube + " --scheme catmull-clark --vertex-param lambda=" + values("e.txt", 0.6), dir / "e.obj",
                "no scheme of the run reads it per vertex");
  check_refused("refine " + cube + " --scheme catmull-clark-shape --vertex-param lambda", dir / "f.obj", "must be written name=FILE");
}

TEST_CASE("--adaptive -l L is --adaptive L; two different levels are refused") {
  // The spelling `subdiv refine --adaptive -l L` and `--adaptive L` ask for the same
  // mesh: the two files are byte for byte the same.
  const auto dir = fresh_dir("cli-adaptive-level");
  const std::string cube = source_path("examples/meshes/cube.obj");
  const fs::path by_value = dir / "value.obj", by_l = dir / "l.obj", l_first = dir / "l-first.obj";
  REQUIRE(run_subdiv("refine " + cube + " --adaptive 3 --limit -q -o " + by_value.string()).exit_code == 0);
  REQUIRE(run_subdiv("refine " + cube + " --adaptive -l 3 --limit -q -o " + by_l.string()).exit_code == 0);
  REQUIRE(run_subdiv("refine " + cube + " -l 3 --adaptive --limit -q -o " + l_first.string()).exit_code == 0);
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  CHECK(!bytes(by_value).empty());
  CHECK(bytes(by_l) == bytes(by_value));
  CHECK(bytes(l_first) == bytes(by_value));
  check_refused("refine " + cube + " --adaptive 3 -l 2", dir / "two.obj", "--adaptive 3 and -l 2 ask for two finest levels");
  check_refused("refine " + cube + " --adaptive -l 13", dir / "deep.obj", "adaptive refinement goes to level 12 at most");
}

TEST_CASE("a triangle scheme on quads is refused naming the mesh file, or the level a sequence's earlier scheme made") {
  const auto dir = fresh_dir("cli-face-sizes");
  const std::string cube = source_path("examples/meshes/cube.obj");
  check_refused("refine " + cube + " -s loop", dir / "a.obj",
                cube + ": scheme 'loop' needs triangles, but face 0 of the mesh has 4 vertices");
  check_refused("evaluate " + cube + " -s loop --samples 2", dir / "b.vtp",
                cube + ": scheme 'loop' needs triangles, but face 0 of the mesh has 4 vertices");
  check_refused("refine " + cube + " -s catmull-clark:1,loop:1", dir / "c.obj",
                "scheme 'loop' needs triangles, but face 0 of level 1 (made by the schemes before it) has 4 vertices");
}
