#include "analysis_output.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include "framework/io/vtk/polydata_conversion.h"

namespace subdiv::paraview {
namespace {

double map_radius(const MeshData& map) {
  double r = 0;
  for (Index v = 0; v < map.vertex_count(); ++v)
    r = std::max(r, std::hypot(map.positions[size_t(3 * v)], map.positions[size_t(3 * v + 1)]));
  return r;
}

// Appends `map` moved by dx along x to `all`, with its per-point arrays.
void append_map(const SurfaceAnalysis& a, double dx, MeshData& all, std::vector<double>& valence,
                std::vector<double>& ring, std::vector<double>& radius) {
  const MeshData& map = a.characteristic_map.mesh;
  const Index first = all.vertex_count();
  for (Index v = 0; v < map.vertex_count(); ++v) {
    const double x = map.positions[size_t(3 * v)], y = map.positions[size_t(3 * v + 1)];
    all.positions.insert(all.positions.end(), {x + dx, y, 0.0});
    radius.push_back(std::hypot(x, y));
    valence.push_back(a.config.valence);
  }
  ring.insert(ring.end(), a.characteristic_map.ring.begin(), a.characteristic_map.ring.end());
  ring.resize(size_t(all.vertex_count()), -1.0);  // a map without distances
  for (Index f = 0; f < map.face_count(); ++f) {
    for (Index c = map.face_offsets[f]; c < map.face_offsets[f + 1]; ++c)
      all.face_vertices.push_back(first + map.face_vertices[c]);
    all.face_offsets.push_back(Index(all.face_vertices.size()));
  }
}

template <typename Array>
vtkSmartPointer<Array> named_column(const std::string& name, vtkIdType rows) {
  auto a = vtkSmartPointer<Array>::New();
  a->SetName(name.c_str());
  a->SetNumberOfTuples(rows);
  return a;
}

}  // namespace

vtkSmartPointer<vtkPolyData> characteristic_maps_polydata(const std::vector<SurfaceAnalysis>& analyses) {
  MeshData all;
  std::vector<double> valence, ring, radius;
  double right = 0;  // the right edge of the maps placed so far
  for (const SurfaceAnalysis& a : analyses) {
    if (!a.characteristic_map.computed || a.characteristic_map.mesh.face_count() == 0) continue;
    const double r = map_radius(a.characteristic_map.mesh);
    const double dx = all.vertex_count() == 0 ? 0.0 : right + 1.25 * r;
    append_map(a, dx, all, valence, ring, radius);
    right = dx + r;
  }
  OutputLevel out;
  out.mesh = &all;
  out.point_data = {DataArray{"valence", 1, valence, true}, DataArray{"ring", 1, ring, true},
                    DataArray{"radius", 1, radius, false}};
  return polydata_from_level(out, "SubdivKit Analyze");
}

vtkSmartPointer<vtkTable> spectrum_table(const std::vector<SurfaceAnalysis>& analyses, int shown) {
  const auto rows = vtkIdType(analyses.size());
  auto table = vtkSmartPointer<vtkTable>::New();
  auto valence = named_column<vtkIntArray>("valence", rows);
  table->AddColumn(valence);
  for (vtkIdType r = 0; r < rows; ++r) valence->SetValue(r, analyses[size_t(r)].config.valence);
  for (int k = 0; k < shown; ++k) {
    auto column = named_column<vtkDoubleArray>(fmt::format("lambda_{}", k), rows);
    for (vtkIdType r = 0; r < rows; ++r) {
      const auto& ev = analyses[size_t(r)].eigenvalues;
      column->SetValue(r, size_t(k) < ev.size() ? std::abs(ev[size_t(k)]) : std::numeric_limits<double>::quiet_NaN());
    }
    table->AddColumn(column);
  }
  auto square = named_column<vtkDoubleArray>("lambda_1^2", rows);
  auto c1 = named_column<vtkIntArray>("c1", rows);
  auto verdict = named_column<vtkStringArray>("verdict", rows);
  for (vtkIdType r = 0; r < rows; ++r) {
    const SurfaceAnalysis& a = analyses[size_t(r)];
    square->SetValue(r, a.lambda1 * a.lambda1);
    c1->SetValue(r, a.c1 ? 1 : 0);
    verdict->SetValue(r, a.verdict);
  }
  table->AddColumn(square);
  table->AddColumn(c1);
  table->AddColumn(verdict);
  return table;
}

}  // namespace subdiv::paraview
