// The user's arrays through `subdiv refine`: a .vtp with point and cell arrays (a scalar, a
// 7-component vector, UVs as the active texture coordinates, normals, an integer label, a
// cell material) is refined, and the output read back with VTK must have every array, of
// the right length, with the values the mathematics gives: data that is an affine
// function of the position stays that function (rows are affine), UVs made from x and y
// stay x and y, labels and materials are inherited.
#include <doctest/doctest.h>

#include <fstream>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include "support/cli_checks.h"
#include "support/cli_runner.h"
#include "support/test_meshes.h"
#include "support/vtk_read.h"

using namespace subdiv;
using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

double affine(const double* p, int c) { return (c + 1) * p[0] - 2 * p[1] + 0.5 * c * p[2] + c; }

vtkSmartPointer<vtkDoubleArray> doubles(const char* name, int components, vtkIdType tuples) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

// A closed quad torus with user arrays, written as .vtp by VTK itself.
void write_input(const fs::path& file, bool with_string_array = false) {
  const Mesh m = torus(8, 6);
  const Level L = m.level();
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();  // the arrays are computed from exact double positions
  for (Index v = 0; v < m.vertex_count; ++v) points->InsertNextPoint(&m.positions[3 * v]);
  poly->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  for (Index f = 0; f < L.face_count(); ++f) {
    polys->InsertNextCell(vtkIdType(L.face(f).size()));
    for (Index v : L.face(f)) polys->InsertCellPoint(v);
  }
  poly->SetPolys(polys);
  auto temperature = doubles("temperature", 1, m.vertex_count), seven = doubles("seven", 7, m.vertex_count);
  auto uv = doubles("uv", 2, m.vertex_count), normals = doubles("Normals", 3, m.vertex_count);
  vtkNew<vtkIntArray> label;
  label->SetName("label");
  label->SetNumberOfTuples(m.vertex_count);
  for (Index v = 0; v < m.vertex_count; ++v) {
    const double* p = &m.positions[3 * v];
    temperature->SetValue(v, affine(p, 0));
    for (int c = 0; c < 7; ++c) seven->SetComponent(v, c, affine(p, c));
    uv->SetComponent(v, 0, p[0]), uv->SetComponent(v, 1, p[1]);
    normals->SetComponent(v, 0, 0), normals->SetComponent(v, 1, 0), normals->SetComponent(v, 2, 1);
    label->SetValue(v, 42);
  }
  poly->GetPointData()->AddArray(temperature);
  poly->GetPointData()->AddArray(seven);
  poly->GetPointData()->AddArray(label);
  poly->GetPointData()->SetTCoords(uv);
  poly->GetPointData()->SetNormals(normals);
  vtkNew<vtkIntArray> material;
  material->SetName("material");
  material->SetNumberOfTuples(L.face_count());
  for (Index f = 0; f < L.face_count(); ++f) material->SetValue(f, 1000 + f);
  poly->GetCellData()->AddArray(material);
  if (with_string_array) {
    vtkNew<vtkStringArray> names;
    names->SetName("names");
    names->SetNumberOfTuples(m.vertex_count);
    poly->GetPointData()->AddArray(names);
  }
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->SetFileName(file.c_str());
  REQUIRE(writer->Write() == 1);
}

}  // namespace

TEST_CASE("refine a .vtp with point and cell arrays: every array comes out refined, UVs active, normals left out") {
  const auto dir = fresh_dir("cli-primvars");
  write_input(dir / "in.vtp");
  const auto out = dir / "out.vtp";
  const CliResult r = run_subdiv("refine " + (dir / "in.vtp").string() + " --scheme catmull-clark -l 2 -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("point array 'Normals' holds normals") != std::string::npos);
  const auto poly = read_vtp(out);
  const vtkIdType n = poly->GetNumberOfPoints();
  CHECK(n == 48 * 16);  // a closed quad mesh: V = F at every level; 48 faces x 4^2
  auto* temperature = poly->GetPointData()->GetArray("temperature");
  auto* seven = poly->GetPointData()->GetArray("seven");
  auto* label = poly->GetPointData()->GetArray("label");
  auto* uv = poly->GetPointData()->GetTCoords();
  REQUIRE(temperature);
  REQUIRE(seven);
  REQUIRE(label);
  REQUIRE(uv);
  CHECK(std::string(uv->GetName()) == "uv");
  CHECK(poly->GetPointData()->GetArray("Normals") == nullptr);
  CHECK(seven->GetNumberOfComponents() == 7);
  for (vtkIdType v = 0; v < n; ++v) {
    double p[3];
    poly->GetPoint(v, p);
    CHECK(temperature->GetTuple1(v) == doctest::Approx(affine(p, 0)).epsilon(1e-12));
    for (int c = 0; c < 7; ++c) CHECK(seven->GetComponent(v, c) == doctest::Approx(affine(p, c)).epsilon(1e-12));
    CHECK(uv->GetComponent(v, 0) == doctest::Approx(p[0]).epsilon(1e-12));
    CHECK(uv->GetComponent(v, 1) == doctest::Approx(p[1]).epsilon(1e-12));
    CHECK(label->GetTuple1(v) == 42);
  }
  auto* material = poly->GetCellData()->GetArray("material");
  auto* base_face = poly->GetCellData()->GetArray("base_face");
  REQUIRE(material);
  REQUIRE(base_face);
  for (vtkIdType f = 0; f < poly->GetNumberOfCells(); ++f)
    CHECK(material->GetTuple1(f) == 1000 + base_face->GetTuple1(f));
}

TEST_CASE("--limit moves the arrays with the positions; --normals writes the limit normals as the active normals") {
  const auto dir = fresh_dir("cli-primvar-limit");
  write_input(dir / "in.vtp");
  const auto out = dir / "limit.vtp";
  CliResult r = run_subdiv("refine " + (dir / "in.vtp").string() + " --scheme loop-composite -l 0 --limit -o " +
                           out.string());
  // loop-composite needs triangles: the refusal names them; then Catmull-Clark.
  CHECK(r.exit_code != 0);
  r = run_subdiv("refine " + (dir / "in.vtp").string() + " --scheme catmull-clark -l 1 --limit -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  auto poly = read_vtp(out);
  auto* temperature = poly->GetPointData()->GetArray("temperature");
  for (vtkIdType v = 0; v < poly->GetNumberOfPoints(); ++v) {
    double p[3];
    poly->GetPoint(v, p);
    CHECK(temperature->GetTuple1(v) == doctest::Approx(affine(p, 0)).epsilon(1e-12));  // limit masks are affine too
  }
  r = run_subdiv("refine " + (dir / "in.vtp").string() + " --scheme catmull-clark -l 1 --normals -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  poly = read_vtp(out);
  auto* normals = poly->GetPointData()->GetNormals();
  REQUIRE(normals);
  CHECK(std::string(normals->GetName()) == "normal");
  for (vtkIdType v = 0; v < poly->GetNumberOfPoints(); ++v) {
    double* nv = normals->GetTuple3(v);
    CHECK(std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]) == doctest::Approx(1.0).epsilon(1e-9));
  }
}

TEST_CASE("bad arrays are refused with a clear message and no output") {
  const auto dir = fresh_dir("cli-primvar-bad");
  write_input(dir / "strings.vtp", true);
  check_refused("refine " + (dir / "strings.vtp").string() + " --scheme catmull-clark", dir / "o.vtp",
                "point array 'names' is not numeric");
}
