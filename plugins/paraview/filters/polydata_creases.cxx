#include "polydata_creases.h"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <utility>

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPolyData.h>

#include "framework/features/sharpness.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::paraview {
namespace {

using Edge = std::pair<Index, Index>;
Edge edge_key(Index a, Index b) { return {std::min(a, b), std::max(a, b)}; }

// Line cells come after the vertex cells in VTK's cell numbering.
void add_line_creases(vtkPolyData& poly, vtkDataArray& values, std::map<Edge, double>& creases) {
  vtkIdType cell = poly.GetNumberOfVerts();
  auto it = vtk::TakeSmartPointer(poly.GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell) {
    const double sharpness = values.GetTuple1(cell);
    if (!(sharpness > 0)) continue;
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    for (vtkIdType i = 0; i + 1 < size; ++i) creases[edge_key(Index(ids[i]), Index(ids[i + 1]))] = sharpness;
  }
}

// Polygons follow vertex and line cells; their values are read in that order (strips,
// which the mesh holds as triangles, carry no region border).
void add_region_borders(vtkPolyData& poly, vtkDataArray& values, const MeshData& mesh,
                        std::map<Edge, double>& creases) {
  const vtkIdType first = poly.GetNumberOfVerts() + poly.GetNumberOfLines();
  const Index polygons = std::min(Index(poly.GetNumberOfPolys()), mesh.face_count());
  std::map<Edge, double> first_value;  // the value of the first face seen at each edge
  for (Index f = 0; f < polygons; ++f) {
    const double value = values.GetTuple1(first + f);
    const Index begin = mesh.face_offsets[f], end = mesh.face_offsets[f + 1];
    for (Index c = begin; c < end; ++c) {
      const Edge e = edge_key(mesh.face_vertices[c], mesh.face_vertices[c + 1 < end ? c + 1 : begin]);
      const auto [seen, added] = first_value.emplace(e, value);
      if (!added && seen->second != value) creases[e] = kInfinitelySharp;
    }
  }
}

}  // namespace

void add_creases_from_cell_array(vtkPolyData& poly, const std::string& name, MeshData& mesh,
                                 const std::string& source) {
  vtkDataArray* values = poly.GetCellData()->GetArray(name.c_str());
  if (!values || values->GetNumberOfTuples() < poly.GetNumberOfCells())
    throw Error(fmt::format("{}: Crease array {}: the input has no numeric cell array of that name; choose one "
                            "of its cell arrays (sharpness on line cells, or part ids on faces) or none",
                            source, subdiv::quoted(name)));
  std::map<Edge, double> creases;
  add_region_borders(poly, *values, mesh, creases);
  add_line_creases(poly, *values, creases);  // lines drawn by the user win over region borders
  for (const auto& [edge, sharpness] : creases) mesh.creases.push_back({edge.first, edge.second, sharpness});
}

}  // namespace subdiv::paraview
