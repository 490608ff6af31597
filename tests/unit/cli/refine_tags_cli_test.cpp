// `subdiv refine` with OpenSubdiv's OBJ tags: the options they set, the command line
// winning over them, tags written back, holes left out, unused vertices dropped with
// a warning, and a Chaikin crease from a tag agreeing with OpenSubdiv's Far.
#include <doctest/doctest.h>

#include <fstream>

#include "framework/io/mesh_read.h"
#include "support/cli_checks.h"
#include "support/cli_runner.h"
#include "support/osd_reference.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

// A 3x2 grid of quads (vertices 0..11, row-major), face 4 a hole, a semi-sharp crease along
// the middle row and every option tag.
const char* kGrid =
    "v 0 0 0\nv 1 0 0.1\nv 2 0 0\nv 3 0 0.2\n"
    "v 0 1 0.1\nv 1 1 0.3\nv 2 1 -0.1\nv 3 1 0\n"
    "v 0 2 0\nv 1 2 0.2\nv 2 2 0\nv 3 2 0.1\n"
    "f 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 5 6 10 9\nf 6 7 11 10\nf 7 8 12 11\n"
    "t crease 2/1/0 4 5 1.3\nt crease 2/1/0 5 6 2.6\nt crease 2/1/0 6 7 0.6\n"
    "t hole 1/0/0 4\n"
    "t interpolateboundary 1/0/0 2\n"
    "t creasemethod 0/0/1 chaikin\n";

bool has_line(const fs::path& file, const std::string& line) {
  std::ifstream in(file);
  for (std::string l; std::getline(in, l);)
    if (l == line) return true;
  return false;
}

}  // namespace

TEST_CASE("refine: option tags set the options, the command line wins, the output writes them back") {
  const auto dir = fresh_dir("cli-tags");
  std::ofstream(dir / "grid.obj") << kGrid;
  const CliResult r = run_subdiv("refine " + (dir / "grid.obj").string() + " -l 1 -o " + (dir / "a.obj").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(has_line(dir / "a.obj", "t interpolateboundary 1/0/0 2"));
  CHECK(has_line(dir / "a.obj", "t creasemethod 0/0/1 chaikin"));
  const CliResult w = run_subdiv("refine " + (dir / "grid.obj").string() +
                                 " -l 1 --boundary edges-and-corners --crease-method uniform -o " + (dir / "b.obj").string());
  REQUIRE_MESSAGE(w.exit_code == 0, w.output);
  CHECK(has_line(dir / "b.obj", "t interpolateboundary 1/0/0 1"));
  CHECK(has_line(dir / "b.obj", "t creasemethod 0/0/1 normal"));
}

TEST_CASE("refine: hole faces and their children are left out of the output") {
  const auto dir = fresh_dir("cli-holes");
  std::ofstream(dir / "grid.obj") << kGrid;
  const CliResult r = run_subdiv("refine " + (dir / "grid.obj").string() + " -l 2 -o " + (dir / "a.obj").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const subdiv::MeshData out = subdiv::read_mesh(dir / "a.obj");
  CHECK(out.face_count() == 5 * 16);  // 6 quads, one a hole, 16 children each
  CHECK(out.holes.empty());           // left out rather than tagged
}

TEST_CASE("refine: faces with fewer than 3 distinct vertices are refined, unused vertices dropped with a warning") {
  const auto dir = fresh_dir("cli-drop");
  std::ofstream(dir / "m.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 9 9 9\nv 8 8 8\n"
                                  "f 1 2 3 4\nf 1 2 2\nf 3 3 4 4\n";
  const CliResult r = run_subdiv("refine " + (dir / "m.obj").string() + " -l 1 -o " + (dir / "a.obj").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK_MESSAGE(r.output.find("face(s)") == std::string::npos, r.output);  // as OpenSubdiv: no face dropped
  CHECK_MESSAGE(r.output.find("2 vertex/vertices used by no face or polyline dropped") != std::string::npos, r.output);
  CHECK(subdiv::read_mesh(dir / "a.obj").face_count() == 4 + 3 + 4);
}

TEST_CASE("refine: --smooth-triangles needs a scheme with the option") {
  const auto dir = fresh_dir("cli-smooth");
  check_refused("refine " + source_path("examples/meshes/cube.obj") + " --scheme bilinear --smooth-triangles",
                dir / "x.obj", "has no 'triangles' parameter");
}

#ifdef SUBDIV_HAVE_OPENSUBDIV
TEST_CASE("refine: a Chaikin crease and boundary mode from tags agree with OpenSubdiv") {
  const auto dir = fresh_dir("cli-chaikin");
  std::ofstream(dir / "grid.obj") << kGrid;
  const CliResult r = run_subdiv("refine " + (dir / "grid.obj").string() + " -l 3 -o " + (dir / "a.obj").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const subdiv::MeshData in = subdiv::read_mesh(dir / "grid.obj");
  subdiv_test::OsdMesh mesh;
  mesh.vertex_count = in.vertex_count();
  mesh.face_offsets.assign(in.face_offsets.begin(), in.face_offsets.end());
  mesh.face_vertices.assign(in.face_vertices.begin(), in.face_vertices.end());
  mesh.xyz = in.positions;
  for (const auto& c : in.creases) mesh.creases.push_back({c.v0, c.v1, float(c.sharpness)});
  mesh.holes = {4};
  subdiv_test::OsdOptions options;
  options.boundary = subdiv_test::OsdBoundary::EdgesOnly;
  options.creasing = subdiv_test::OsdCreasing::Chaikin;
  const auto osd = subdiv_test::osd_refine(mesh, options, 3);
  const subdiv::MeshData out = subdiv::read_mesh(dir / "a.obj");
  // Every vertex is written (those of hole faces too), in full precision.
  const auto match = subdiv_test::match_points(out.positions, osd.levels[3].xyz, 1e-12);
  CHECK(match.ok);
  CHECK(match.max_difference < 1e-12);
}
#endif
