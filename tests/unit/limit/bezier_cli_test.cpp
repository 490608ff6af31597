// `subdiv evaluate --approximate bezier` (and gregory's --at rows): the written points and
// arrays are the library's patches and distances, the control nets read back with VTK's own
// Bézier cells give the same surface, and bad inputs are refused with the reason and no file.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vtkBezierQuadrilateral.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkGenericCell.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "framework/limit/bezier_approximation.h"
#include "framework/pipeline/approximation_request.h"
#include "support/cli_checks.h"
#include "support/cli_runner.h"
#include "support/vtk_read.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

PreparedEvaluation cube() {
  EvaluateRequest r;
  r.mesh_file = test::source_path("examples/meshes/cube.obj");
  r.scheme.text = "catmull-clark";
  return prepare_evaluation(std::move(r));
}

}  // namespace

TEST_CASE("subdiv evaluate --approximate bezier --samples writes the patches, their normals and distances") {
  const fs::path dir = test::fresh_dir("bezier-cli");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  const auto r = test::run_subdiv("evaluate " + mesh + " --approximate bezier --samples 4 -o " +
                                  (dir / "out.vtp").string() + " --bezier-net " + (dir / "net.vtu").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const PreparedEvaluation p = cube();
  const BezierApproximation patches_set = approximation_patches(p);
  const std::vector<BezierPatch>& patches = patches_set.patches;
  ApproximationDistances d;
  (void)approximated_limit_mesh(p, patches_set, 4, d);
  CHECK(r.output.find(approximation_summary(d)) != std::string::npos);
  const auto poly = test::read_vtp(dir / "out.vtp");
  REQUIRE(poly->GetNumberOfCells() == 6 * 16);
  vtkDataArray* cell_distance = poly->GetCellData()->GetArray("limit_distance");
  vtkDataArray* base_face = poly->GetCellData()->GetArray("base_face");
  REQUIRE(cell_distance);
  REQUIRE(base_face);
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c)
    CHECK(cell_distance->GetTuple1(c) == d.per_face[size_t(base_face->GetTuple1(c))]);
  vtkDataArray* uv = poly->GetPointData()->GetArray("uv");
  vtkDataArray* point_face = poly->GetPointData()->GetArray("base_face");
  REQUIRE(uv);
  REQUIRE(point_face);
  double worst = 0;
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
    const PatchSample s =
        evaluate_patch(patches[size_t(point_face->GetTuple1(i))], uv->GetComponent(i, 0), uv->GetComponent(i, 1));
    double x[3];
    poly->GetPoint(i, x);
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(x[c] - s.position[c]));
  }
  CHECK(worst < 1e-15);

  // The control nets, read by VTK 9's own reader and evaluated by its Bézier cell.
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "net.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  REQUIRE(grid->GetNumberOfCells() == 6);
  double net_worst = 0;
  for (vtkIdType c = 0; c < 6; ++c) {
    REQUIRE(grid->GetCellType(c) == VTK_BEZIER_QUADRILATERAL);
    vtkNew<vtkGenericCell> cell;
    grid->GetCell(c, cell);
    for (const auto& st : {std::array{0.3, 0.6}, std::array{0.0, 1.0}, std::array{0.9, 0.05}}) {
      double pcoords[3] = {st[0], st[1], 0}, x[3], weights[16];
      int sub = 0;
      cell->EvaluateLocation(sub, pcoords, x, weights);
      const PatchSample s = evaluate_patch(patches[size_t(c)], st[0], st[1]);
      for (size_t k = 0; k < 3; ++k) net_worst = std::max(net_worst, std::abs(x[k] - s.position[k]));
    }
  }
  CHECK(net_worst < 1e-12);
}

TEST_CASE("subdiv evaluate --approximate bezier|gregory --at writes points, normals and distances") {
  const fs::path dir = test::fresh_dir("bezier-cli-at");
  std::ofstream(dir / "points.csv") << "face,u,v\n0,0.3,0.2\n4,0.5,0.125\n";
  const PreparedEvaluation p = cube();
  const std::vector<Index> faces{0, 4};
  const std::vector<double> uv{0.3, 0.2, 0.5, 0.125};
  for (const std::string kind : {"bezier", "gregory"}) {
    CAPTURE(kind);
    const auto r = test::run_subdiv("evaluate " + test::source_path("examples/meshes/cube.obj") + " --approximate " +
                                    kind + " --at " + (dir / "points.csv").string() + " -o " +
                                    (dir / "out.csv").string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::ifstream in(dir / "out.csv");
    std::string header, line;
    std::getline(in, header);
    CHECK(header == "face,u,v,x,y,z,nx,ny,nz,limit_distance");
    const ApproximatedPoints a = kind == "bezier" ? approximate_points(p, approximation_patches(p), faces, uv)
                                                  : approximate_points(p, gregory_approximation_patches(p), faces, uv);
    for (size_t i = 0; i < 2; ++i) {
      REQUIRE(std::getline(in, line));
      std::vector<double> row;
      std::stringstream s(line);
      for (std::string f; std::getline(s, f, ',');) row.push_back(std::stod(f));
      REQUIRE(row.size() == 10);
      for (size_t c = 0; c < 3; ++c) {
        CHECK(row[3 + c] == a.positions[3 * i + c]);
        CHECK(row[6 + c] == a.normals[3 * i + c]);
      }
      CHECK(row[9] == a.distances.per_point[i]);
      CHECK(row[9] > 1e-4);  // next to the cube's valence-3 corners the patches only approximate
    }
  }
}

TEST_CASE("subdiv evaluate --approximate bezier refuses what the patches do not cover, leaving no file") {
  const fs::path dir = test::fresh_dir("bezier-cli-refused");
  const std::string cube = test::source_path("examples/meshes/cube.obj");
  const std::string base = "evaluate " + cube + " --approximate bezier --samples 4";
  test::check_refused("evaluate " + test::source_path("examples/meshes/octahedron.obj") +
                          " --approximate bezier --samples 4 -s loop",
                      dir / "a.vtp", "its split makes triangles");
  test::check_refused(base + " -s loop", dir / "a.vtp", "needs triangles, but face 0 of the mesh has 4 vertices");
  test::check_refused(base + " -s doo-sabin", dir / "b.vtp", "not the bicubic B-spline");
  test::check_refused(base + " -s bilinear", dir / "c.vtp", "not the bicubic B-spline");
  test::check_refused(base + " -s catmull-clark:1,catmull-clark", dir / "s.vtp", "a sequence's limit");
  // cube-creased.obj: a tagged corner inside the surface (vertex 0), and top edges with one face on a side.
  test::check_refused("evaluate " + test::source_path("examples/meshes/cube-creased.obj") +
                          " --approximate bezier --samples 4",
                      dir / "f.vtp", "vertex 0 is a corner inside the surface");
  test::check_refused("evaluate " + cube + " --approximate spline --samples 4", dir / "g.vtp", "the approximations are bezier");
  test::check_refused(base + " --bezier-net " + (dir / "net.vtp").string(), dir / "h.vtp", ".vtu");
  CHECK_FALSE(fs::exists(dir / "net.vtp"));
}
