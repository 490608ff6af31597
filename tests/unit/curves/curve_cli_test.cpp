// `subdiv refine` with curve schemes, end to end: OBJ and VTK polylines in; .vtp, .pvd and
// OBJ out, read back with VTK's reader and our OBJ reader.
#include <doctest/doctest.h>

#include <fstream>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "curve_test_support.h"
#include "framework/curve/curve_level.h"
#include "framework/io/mesh_read.h"
#include "support/cli_checks.h"
#include "support/cli_runner.h"

using namespace subdiv;
using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

vtkSmartPointer<vtkPolyData> read_vtp(const fs::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

// Point ids of line cell `cell`.
std::vector<vtkIdType> line_ids(vtkPolyData* poly, vtkIdType cell) {
  vtkNew<vtkIdList> ids;
  poly->GetLines()->GetCellAtId(cell, ids);
  std::vector<vtkIdType> out;
  for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i) out.push_back(ids->GetId(i));
  return out;
}


}  // namespace

TEST_CASE("refine an open OBJ polyline with the four-point scheme to .vtp and read it back") {
  const auto dir = fresh_dir("curve-cli-vtp");
  const auto out = dir / "zigzag.vtp";
  const CliResult r = run_subdiv("refine " + source_path("examples/curves/open-zigzag.obj") +
                                 " --scheme four-point --levels 3 -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const auto poly = read_vtp(out);
  // 6 points, open, primal binary: 6 -> 11 -> 21 -> 41.
  CHECK(poly->GetNumberOfPoints() == 41);
  CHECK(poly->GetNumberOfLines() == 1);
  CHECK(poly->GetNumberOfPolys() == 0);
  const auto ids = line_ids(poly, 0);
  REQUIRE(ids.size() == 41);
  for (size_t i = 0; i < ids.size(); ++i) CHECK(ids[i] == vtkIdType(i));
  // Interpolatory: the input points are every 8th point.
  const MeshData input = read_mesh(source_path("examples/curves/open-zigzag.obj"));
  for (int i = 0; i < 6; ++i) {
    double p[3];
    poly->GetPoint(8 * i, p);
    for (int c = 0; c < 3; ++c) CHECK(p[c] == input.positions[3 * i + c]);
  }
  CHECK(poly->GetPointData()->GetArray("rule") != nullptr);
  CHECK(poly->GetCellData()->GetArray("polyline") != nullptr);
  CHECK(poly->GetCellData()->GetArray("closed")->GetTuple1(0) == 0);
}

TEST_CASE("a closed square with Chaikin to .pvd: one .vtp per level, closed line cells") {
  const auto dir = fresh_dir("curve-cli-pvd");
  const auto out = dir / "square.pvd";
  const CliResult r = run_subdiv("refine " + source_path("examples/curves/square.obj") +
                                 " -s chaikin -l 3 -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(fs::exists(out));
  for (int l = 0; l <= 3; ++l) {
    CAPTURE(l);
    const auto level = dir / "square_levels" / ("level_" + std::to_string(l) + ".vtp");
    REQUIRE(fs::exists(level));
    const auto poly = read_vtp(level);
    const vtkIdType points = 4 << l;  // closed: 4 * 2^l
    CHECK(poly->GetNumberOfPoints() == points);
    REQUIRE(poly->GetNumberOfLines() == 1);
    const auto ids = line_ids(poly, 0);
    CHECK(ids.size() == size_t(points + 1));  // the first point again closes the loop
    CHECK(ids.front() == ids.back());
    CHECK(poly->GetCellData()->GetArray("closed")->GetTuple1(0) == 1);
  }
}

TEST_CASE("OBJ output keeps closed polygons closed (l ... first) and shared end points; VTK input refines too") {
  const auto dir = fresh_dir("curve-cli-obj");
  const auto obj = dir / "strokes.obj";
  CliResult r = run_subdiv("refine " + source_path("examples/curves/two-strokes.obj") + " -s cubic-bspline -l 2 -o " +
                           obj.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const MeshData mesh = read_mesh(obj);
  const CurveLevel level = curve_level_from_mesh(mesh, obj.string());
  REQUIRE(level.polyline_count() == 3);
  // Open 4 points -> 13, open 3 points -> 9 (sharing the joint), closed 3 -> 12.
  CHECK(level.size(0) == 13);
  CHECK(level.size(1) == 9);
  CHECK(level.size(2) == 12);
  CHECK(level.closed == std::vector<std::uint8_t>{0, 0, 1});
  CHECK(mesh.vertex_count() == 13 + 9 - 1 + 12);
  CHECK(level.polyline(0).back() == level.polyline(1).front());

  // Refine the .vtp of a previous run again: VTK line cells in, one more level out.
  const auto vtp = dir / "strokes.vtp";
  r = run_subdiv("refine " + source_path("examples/curves/two-strokes.obj") + " -s ternary-four-point -l 1 -o " +
                 vtp.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const auto again = dir / "again.vtp";
  r = run_subdiv("refine " + vtp.string() + " -s ternary-four-point -l 1 -o " + again.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const auto poly = read_vtp(again);
  // Ternary, two levels: open 4 -> 10 -> 28, open 3 -> 7 -> 19 (joint shared), closed 3 -> 9 -> 27.
  CHECK(poly->GetNumberOfLines() == 3);
  CHECK(poly->GetNumberOfPoints() == 28 + 19 - 1 + 27);
}

TEST_CASE("curve schemes take --param; the tension scheme puts the octagon's points on a circle") {
  const auto dir = fresh_dir("curve-cli-param");
  const auto out = dir / "circle.vtp";
  const CliResult r = run_subdiv("refine " + source_path("examples/curves/circle8.obj") +
                                 " -s tension-bspline --param alpha0=0.70710678118654757 -l 5 -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const auto poly = read_vtp(out);
  REQUIRE(poly->GetNumberOfPoints() == 8 * 32);
  double expected = 1.0;
  for (int l = 1; l <= 5; ++l) expected *= std::cos(M_PI / 4 / std::pow(2.0, l));
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
    double p[3];
    poly->GetPoint(i, p);
    CHECK(std::hypot(p[0], p[1]) == doctest::Approx(expected).epsilon(1e-12));
  }
  const CliResult d5 = run_subdiv("refine " + source_path("examples/curves/square.obj") + " -s bspline -p d=5 -l 2 -o " +
                                  (dir / "d5.vtp").string());
  CHECK_MESSAGE(d5.exit_code == 0, d5.output);
  CHECK(read_vtp(dir / "d5.vtp")->GetNumberOfPoints() == 16);
}

TEST_CASE("curve CLI errors: wrong kind of mesh or scheme, formats without polylines; nothing written") {
  const auto dir = fresh_dir("curve-cli-errors");
  check_refused("refine " + source_path("examples/meshes/cube.obj") + " -s chaikin", dir / "a.vtp",
                "a curve scheme refines polylines only");
  check_refused("refine " + source_path("examples/curves/square.obj") + " -s catmull-clark", dir / "b.vtp",
                "its polylines need a curve scheme");
  check_refused("refine " + source_path("examples/curves/square.obj") + " -s chaikin", dir / "c.off",
                "cannot write polylines");
  check_refused("refine " + source_path("examples/curves/square.obj") + " -s four-point -p w=0.5", dir / "d.vtp",
                "outside its range");
  check_refused("refine " + source_path("examples/curves/square.obj") + " -s chaikin -l 30", dir / "e.vtp",
                "ask for fewer levels");
}
