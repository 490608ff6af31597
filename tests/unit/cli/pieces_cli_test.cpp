// `subdiv refine --pieces N -o OUT.pvtp` end to end: the pieces' faces, points and arrays,
// merged, are the whole refinement's (the serial .vtp is the reference), and bad option
// combinations are refused with no file left behind.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <fstream>
#include <map>
#include <set>
#include <tuple>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "support/cli_runner.h"
#include "support/vtk_read.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

using Point = std::array<std::uint64_t, 3>;

Point point_bits(vtkPolyData& poly, vtkIdType i) {
  double p[3];
  poly.GetPoint(i, p);
  return {std::bit_cast<std::uint64_t>(p[0]), std::bit_cast<std::uint64_t>(p[1]), std::bit_cast<std::uint64_t>(p[2])};
}

// A refined surface as comparable data: its polygons by their points' bits (from the
// smallest point, in order), and every point array's tuple by point.
struct Surface {
  std::vector<std::vector<Point>> faces;
  // (array, point, tuple): a point on a UV seam is written once per side, with its tuple.
  std::set<std::tuple<std::string, Point, std::vector<double>>> point_values;
  std::set<std::tuple<std::string, std::vector<Point>, std::vector<double>>> cell_values;  // by face

  void add(vtkPolyData& poly) {
    vtkCellArray* polys = poly.GetPolys();
    vtkNew<vtkIdList> ids;
    vtkCellData* cd = poly.GetCellData();
    // VTK numbers cells vertices first, then lines (crease edges), then polygons.
    vtkIdType cell = poly.GetNumberOfVerts() + poly.GetNumberOfLines();
    for (polys->InitTraversal(); polys->GetNextCell(ids); ++cell) {
      std::vector<Point> f;
      for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i) f.push_back(point_bits(poly, ids->GetId(i)));
      std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
      for (int a = 0; a < cd->GetNumberOfArrays(); ++a) {
        vtkDataArray* array = cd->GetArray(a);
        if (std::string(array->GetName()) == "parent_face") continue;  // numbers the piece's own faces
        std::vector<double> tuple(array->GetNumberOfComponents());
        array->GetTuple(cell, tuple.data());
        cell_values.insert({array->GetName(), f, tuple});
      }
      faces.push_back(std::move(f));
    }
    vtkPointData* pd = poly.GetPointData();
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a) {
      vtkDataArray* array = pd->GetArray(a);
      // vertex_id (points split at UV seams, io/mesh_seams.h) numbers the file's own
      // vertices: a numbering, not data, and a piece has its own.
      if (std::string(array->GetName()) == "vertex_id") continue;
      for (vtkIdType i = 0; i < poly.GetNumberOfPoints(); ++i) {
        std::vector<double> tuple(array->GetNumberOfComponents());
        array->GetTuple(i, tuple.data());
        point_values.insert({array->GetName(), point_bits(poly, i), tuple});
      }
    }
  }
  void sort() { std::sort(faces.begin(), faces.end()); }
};

Surface serial(const fs::path& vtp) {
  Surface s;
  s.add(*read_vtp(vtp));
  s.sort();
  return s;
}

Surface merged(const fs::path& pvtp, int pieces) {
  Surface s;
  for (int i = 0; i < pieces; ++i) {
    const fs::path piece = pvtp.parent_path() / (pvtp.stem().string() + "_pieces") / ("piece_" + std::to_string(i) + ".vtp");
    REQUIRE(fs::exists(piece));
    s.add(*read_vtp(piece));
  }
  s.sort();
  return s;
}

int piece_entries(const fs::path& pvtp) {
  std::ifstream in(pvtp);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  int n = 0;
  for (size_t at = text.find("<Piece "); at != std::string::npos; at = text.find("<Piece ", at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("pieces merged are the whole refinement: faces, points bit for bit, point arrays, UVs") {
  const auto dir = fresh_dir("cli-pieces");
  // An input with user arrays of both kinds: a refined creased cube as .vtp (integer arrays
  // origin, valence...; double arrays corner_sharpness, sharpness), and a mesh with a hole.
  const fs::path input = dir / "input.vtp";
  REQUIRE(run_subdiv("refine " + source_path("examples/meshes/cube-creased.obj") + " -l 1 -q -o " + input.string()).exit_code == 0);
  struct Case {
    std::string mesh, scheme;
    int levels;
  };
  const std::vector<Case> cases{{input.string(), "catmull-clark", 2},
                                {source_path("examples/meshes/plane-with-hole.obj"), "doo-sabin", 2},
                                {source_path("examples/meshes/octahedron.obj"), "loop", 3},
                                {source_path("examples/meshes/octahedron.obj"), "sqrt3", 3},
                                {source_path("examples/meshes/plane-with-hole.obj"), "mid-edge", 3},
                                {source_path("examples/meshes/textured-tube.obj"), "catmull-clark", 2}};  // UVs with seams
  for (const Case& c : cases) {
    const std::string common = c.mesh + " --scheme " + c.scheme + " -l " + std::to_string(c.levels) + " -q -o ";
    const fs::path whole = dir / (c.scheme + ".vtp");
    REQUIRE(run_subdiv("refine " + common + whole.string()).exit_code == 0);
    const Surface reference = serial(whole);
    for (int pieces : {1, 3, 5}) {
      CAPTURE(c.scheme);
      CAPTURE(pieces);
      const fs::path pvtp = dir / (c.scheme + std::to_string(pieces) + ".pvtp");
      const CliResult r = run_subdiv("refine " + common + pvtp.string() + " --pieces " + std::to_string(pieces));
      REQUIRE_MESSAGE(r.exit_code == 0, r.output);
      CHECK(piece_entries(pvtp) == pieces);
      const Surface parts = merged(pvtp, pieces);
      CHECK(parts.faces.size() == reference.faces.size());
      CHECK(parts.faces == reference.faces);
      // Every array's tuples at every point, pieces merged, are the whole refinement's
      // (points shared by two pieces carry the same tuples in both).
      CHECK(parts.point_values.size() == reference.point_values.size());
      CHECK(parts.point_values == reference.point_values);
      CHECK(!parts.cell_values.empty());
      CHECK(parts.cell_values == reference.cell_values);
    }
  }
}

// The budget leaves room for the process itself: under AddressSanitizer (scripts/sanitize.sh)
// the `subdiv` process holds some 64 MiB before it reads the mesh.
TEST_CASE("--max-memory picks enough pieces for each to fit") {
  const auto dir = fresh_dir("cli-pieces-memory");
  const fs::path out = dir / "torus.pvtp";
  const CliResult r = run_subdiv("refine " + source_path("examples/meshes/torus-quads.obj") + " -l 7 --max-memory 160M -o " +
                                 out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(piece_entries(out) > 1);
}

TEST_CASE("bad piece options are refused by name, with no output left behind") {
  const auto dir = fresh_dir("cli-pieces-errors");
  const std::string cube = source_path("examples/meshes/cube.obj");
  struct Bad {
    std::string args, says;
  };
  const std::vector<Bad> bad{
      {cube + " --pieces 2 -o " + (dir / "a.vtp").string(), "is not a .pvtp; write -o"},
      {cube + " --pieces 0 -o " + (dir / "a.pvtp").string(), "--pieces 0"},
      {cube + " --pieces 7 -o " + (dir / "a.pvtp").string(), "ask for 1 to 6 pieces"},
      {cube + " -o " + (dir / "a.pvtp").string(), "add --pieces N"},
      {cube + " --pieces 2 --limit -o " + (dir / "a.pvtp").string(), "--limit cannot be combined"},
      {cube + " --max-memory lots -o " + (dir / "a.pvtp").string(), "--max-memory 'lots' is not a memory size"},
      {cube + " -l 5 --pieces 2 --max-memory 1M -o " + (dir / "a.pvtp").string(), "ask for more --pieces"},
      // Six pieces of the cube are one face each: a seventh piece does not exist. One face
      // refined 5 levels fits 1 MiB (about 0.3 MiB), the face with its ghost ring (five faces,
      // about 1.5 MiB) does not.
      {cube + " -l 5 --pieces 6 --max-memory 1M -o " + (dir / "a.pvtp").string(),
       "is one face of the mesh with its 1 ghost ring(s), 5 faces in all: no number of pieces makes it smaller"},
      // One face refined 8 levels needs about 19 MiB: more pieces cannot help.
      {cube + " -l 8 --pieces 2 --max-memory 1M -o " + (dir / "a.pvtp").string(),
       "no number of pieces helps; ask for fewer levels or a larger --max-memory"},
  };
  for (const Bad& b : bad) {
    CAPTURE(b.args);
    const CliResult r = run_subdiv("refine " + b.args);
    CHECK(r.exit_code == 1);
    CHECK(r.output.find(b.says) != std::string::npos);
    CHECK(fs::is_empty(dir));
  }
}
