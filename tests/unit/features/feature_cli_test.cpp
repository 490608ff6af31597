// `subdiv refine` with --features, --feature-angle and OBJ tags, end to end: the .vtp/.pvd
// output carries crease edges as line cells with their sharpness and each point's class.
#include <doctest/doctest.h>

#include <array>
#include <fstream>
#include <map>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "support/cli_runner.h"
#include "support/vtk_read.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

fs::path level_file(const fs::path& pvd, int level) {
  return pvd.parent_path() / (pvd.stem().string() + "_levels") / ("level_" + std::to_string(level) + ".vtp");
}

// Crease line cells (cell_kind 2) of a level: sharpness -> count.
std::map<double, int> crease_cells(vtkPolyData& poly) {
  std::map<double, int> out;
  vtkDataArray* kind = poly.GetCellData()->GetArray("cell_kind");
  vtkDataArray* sharpness = poly.GetCellData()->GetArray("sharpness");
  REQUIRE(kind);
  REQUIRE(sharpness);
  for (vtkIdType c = 0; c < poly.GetNumberOfCells(); ++c)
    if (kind->GetTuple1(c) == 2) {
      CHECK(poly.GetCell(c)->GetNumberOfPoints() == 2);
      ++out[sharpness->GetTuple1(c)];
    }
  return out;
}

std::vector<int> vertex_classes(vtkPolyData& poly) {
  vtkDataArray* a = poly.GetPointData()->GetArray("vertex_class");
  REQUIRE(a);
  std::vector<int> out(size_t(poly.GetNumberOfPoints()));
  for (vtkIdType v = 0; v < poly.GetNumberOfPoints(); ++v) out[size_t(v)] = int(a->GetTuple1(v));
  return out;
}

// A 4 x 4 quad grid in the plane z = 0 with bumps; vertex (i, j) is 5j + i (0-based).
fs::path write_grid(const fs::path& dir) {
  const auto file = dir / "grid.obj";
  std::ofstream out(file);
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) out << "v " << i << ' ' << j << ' ' << 0.1 * ((3 * i + 5 * j) % 4) << '\n';
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int v = 5 * j + i + 1;
      out << "f " << v << ' ' << v + 1 << ' ' << v + 6 << ' ' << v + 5 << '\n';
    }
  return file;
}

void check_refused(const std::string& args, const fs::path& out, const std::string& message) {
  const CliResult r = run_subdiv(args + " -o " + out.string());
  CHECK(r.exit_code != 0);
  CHECK_MESSAGE(r.output.find(message) != std::string::npos, r.output);
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(fs::exists(level_file(out, 0)));
}

}  // namespace

TEST_CASE("--features: a semi-sharp crease of sharpness 2 shows for two levels; classes and a fixed corner") {
  const auto dir = fresh_dir("features-sidecar");
  const auto grid = write_grid(dir);
  // The middle row (i, 2) from the left boundary to (3, 2): 3 edges of sharpness 2; a
  // corner tag on (1, 3).
  std::ofstream(dir / "f.json") << R"({"creases": [{"path": [10, 11, 12, 13], "sharpness": 2}],
                                       "corners": [{"vertex": 16}]})";
  const auto out = dir / "grid.pvd";
  const CliResult r = run_subdiv("refine " + grid.string() + " --features " + (dir / "f.json").string() +
                                 " --levels 3 --arrays default,vertex_class -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("3 crease edge(s), 1 corner(s)") != std::string::npos);

  // Each level halves the crease edges and lowers their sharpness by one.
  const std::map<double, int> expected[] = {{{2.0, 3}}, {{1.0, 6}}, {}, {}};
  for (int l = 0; l <= 3; ++l) {
    CAPTURE(l);
    const auto poly = read_vtp(level_file(out, l));
    CHECK(crease_cells(*poly) == expected[l]);
  }

  const auto base = read_vtp(level_file(out, 0));
  const auto cls = vertex_classes(*base);
  // Boundary vertices are crease vertices, the four grid corners are corners (boundary
  // edges and corners mode); (0, 2) on the boundary meets the crease: three sharp edges.
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) {
      const int v = 5 * j + i;
      const bool boundary = i == 0 || j == 0 || i == 4 || j == 4;
      const bool grid_corner = (i == 0 || i == 4) && (j == 0 || j == 4);
      int expected_class = 0;
      if (grid_corner || v == 10 || v == 16) expected_class = 3;
      else if (boundary || v == 11 || v == 12) expected_class = 2;
      else if (v == 13) expected_class = 1;  // the crease ends inside: a dart
      CHECK_MESSAGE(cls[size_t(v)] == expected_class, "vertex " << v);
    }
  // Level 2: the crease has decayed; the old interior crease vertices are smooth.
  const auto l2 = vertex_classes(*read_vtp(level_file(out, 2)));
  CHECK(l2[11] == 0);
  CHECK(l2[12] == 0);
  CHECK(l2[16] == 3);
  // The corner tag keeps vertex 16 where it was at every level.
  for (int l = 1; l <= 3; ++l) {
    double p[3];
    read_vtp(level_file(out, l))->GetPoint(16, p);
    CHECK(p[0] == 1.0);
    CHECK(p[1] == 3.0);
    CHECK(p[2] == doctest::Approx(0.1 * ((3 * 1 + 5 * 3) % 4)).epsilon(1e-15));
  }
}

TEST_CASE("--feature-angle: a cube's twelve edges become sharp; its corners stay and its edges stay straight") {
  const auto dir = fresh_dir("features-angle");
  const auto out = dir / "cube.pvd";
  const CliResult r = run_subdiv("refine " + source_path("examples/meshes/cube.obj") +
                                 " --feature-angle 30 --levels 2 --arrays all -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("12 edge(s) made infinitely sharp") != std::string::npos);
  const auto base = read_vtp(level_file(out, 0));
  CHECK(crease_cells(*base) == std::map<double, int>{{10.0, 12}});
  for (int c : vertex_classes(*base)) CHECK(c == 3);  // three sharp edges at every corner
  const auto fine = read_vtp(level_file(out, 2));
  CHECK(crease_cells(*fine) == std::map<double, int>{{10.0, 48}});
  // The cube [-0.5, 0.5]^3: corners fixed; a point on a sharp edge is on the cube's edge
  // (two coordinates at +-0.5), and the cubic B-spline keeps a straight edge straight.
  const auto cls = vertex_classes(*fine);
  int corners = 0, creases = 0;
  for (vtkIdType v = 0; v < fine->GetNumberOfPoints(); ++v) {
    double p[3];
    fine->GetPoint(v, p);
    int on_face = 0;
    for (double c : p) on_face += std::abs(std::abs(c) - 0.5) < 1e-15;
    if (cls[size_t(v)] == 3) {
      ++corners;
      CHECK(on_face == 3);
    }
    if (cls[size_t(v)] == 2) {
      ++creases;
      CHECK(on_face == 2);
    }
  }
  CHECK(corners == 8);
  CHECK(creases == 12 * 3);
  // Not sharp enough: nothing found.
  const CliResult none = run_subdiv("refine " + source_path("examples/meshes/cube.obj") +
                                    " --feature-angle 120 -o " + (dir / "none.vtp").string());
  REQUIRE_MESSAGE(none.exit_code == 0, none.output);
  CHECK(crease_cells(*read_vtp(dir / "none.vtp")).empty());
}

TEST_CASE("OBJ crease and corner tags show in the output") {
  const auto dir = fresh_dir("features-obj");
  const auto out = dir / "cube.vtp";
  const CliResult r = run_subdiv("refine " + source_path("examples/meshes/cube-creased.obj") +
                                 " --levels 0 --arrays all -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const auto poly = read_vtp(out);
  // Four sharp top edges; the top vertices 4..7 each have two: crease vertices; vertex 0
  // is tagged a corner; the rest are smooth.
  CHECK(crease_cells(*poly) == std::map<double, int>{{10.0, 4}});
  CHECK(vertex_classes(*poly) == std::vector<int>{3, 0, 0, 0, 2, 2, 2, 2});
}

TEST_CASE("bad feature input: clear message, non-zero exit, nothing written") {
  const auto dir = fresh_dir("features-bad");
  const auto grid = write_grid(dir);
  const auto out = dir / "out.pvd";
  const std::string refine = "refine " + grid.string() + " --levels 2";

  std::ofstream(dir / "not-an-edge.json") << R"({"creases": [{"path": [0, 1, 7], "sharpness": 3}]})";
  check_refused(refine + " --features " + (dir / "not-an-edge.json").string(), out,
                "not-an-edge.json: creases[0].path[1..2]: vertices 1 and 7 are not joined by an edge");

  std::ofstream(dir / "negative.json") << R"({"creases": [{"edge": [0, 1], "sharpness": -1}]})";
  check_refused(refine + " --features " + (dir / "negative.json").string(), out,
                "negative.json: creases[0].sharpness: sharpness -1 is negative");

  std::ofstream(dir / "broken.json") << "{\n  \"creases\": [\n    {\"edge\": [0, 1],}\n  ]\n}\n";
  check_refused(refine + " --features " + (dir / "broken.json").string(), out, "broken.json:3:");

  std::ofstream(dir / "range.json") << R"({"corners": [{"vertex": 25}]})";
  check_refused(refine + " --features " + (dir / "range.json").string(), out, "vertex 25 does not exist");

  check_refused(refine + " --features " + (dir / "missing.json").string(), out, "missing.json");
  check_refused(refine + " --feature-angle 200", out, "--feature-angle");

  // An OBJ crease tag on a vertex pair that is not an edge, and a negative OBJ sharpness.
  std::ofstream(dir / "bad-tag.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nt crease 2/1/0 0 2 10\n";
  check_refused("refine " + (dir / "bad-tag.obj").string(), out, "not an edge");
  std::ofstream(dir / "neg-tag.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nt crease 2/1/0 0 1 -2\n";
  check_refused("refine " + (dir / "neg-tag.obj").string(), out, "sharpness -2 is invalid");
}
