// VTK PolyData: XML (.vtp) and legacy (.vtk). Polygons become faces, lines become
// polylines, triangle strips are split into triangles; vertex cells carry no surface and
// are skipped. Points keep their order. Crease and corner tags come back from the arrays
// write_vtp adds (cell_kind, sharpness, corner_sharpness).
#include <algorithm>
#include <set>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCharArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkType.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSmartPointer.h>
#include <vtkExecutive.h>
#include <vtkXMLPolyDataReader.h>

#include "framework/io/formats.h"
#include "framework/io/vtk/vtk_read.h"
#include "framework/io/text_input.h"
#include "framework/io/vtk/vtk_legacy_check.h"
#include "framework/io/vtk/vtk_messages.h"
#include "framework/io/vtk/vtk_xml_check.h"
#include "framework/io/vtk/vtp_fast_read.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

// VTK reports failures through events, not return values. The observer collects the
// first message from the reader, its pipeline executive and its XML parser, so that the
// caller can report it (and the console stays free of VTK's raw output).
class ErrorObserver {
public:
  explicit ErrorObserver(vtkAlgorithm& reader) {
    callback_->SetClientData(this);
    callback_->SetCallback([](vtkObject*, unsigned long, void* self, void* message) {
      auto& text = static_cast<ErrorObserver*>(self)->text_;
      if (text.empty() && message) text = vtk_readable_message(static_cast<const char*>(message));
    });
    for (vtkObject* object : {static_cast<vtkObject*>(&reader),
                              static_cast<vtkObject*>(reader.GetExecutive())}) {
      object->AddObserver(vtkCommand::ErrorEvent, callback_);
      object->AddObserver(vtkCommand::WarningEvent, callback_);
    }
    if (auto* xml = vtkXMLReader::SafeDownCast(&reader)) xml->SetParserErrorObserver(callback_);
  }
  const std::string& text() const { return text_; }

private:
  vtkNew<vtkCallbackCommand> callback_;
  std::string text_;
};

[[noreturn]] void fail(const fs::path& file, std::string_view problem) {
  throw Error(fmt::format("cannot read {}: {}", subdiv::quoted(file.string()), problem));
}

// What VTK said went wrong: the reader's own message, else whatever it printed.
std::string vtk_reason(const ErrorObserver& observed, const VtkMessageCapture& printed) {
  if (!observed.text().empty()) return observed.text();
  if (!printed.first_error().empty()) return printed.first_error();
  if (!printed.first_message().empty()) return printed.first_message();
  return "no reason given; the file is damaged or not VTK PolyData";
}

vtkSmartPointer<vtkPolyData> load_xml(const fs::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  if (!reader->CanReadFile(file.c_str()))
    fail(file, "it is not a VTK XML PolyData file (expected <VTKFile type=\"PolyData\">)");
  check_vtp_file(file);  // sizes VTK would allocate from, before it does
  VtkMessageCapture printed;
  ErrorObserver errors(*reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  if (!errors.text().empty() || reader->GetErrorCode() != 0 || !printed.first_error().empty())
    fail(file, fmt::format("VTK reports: {}", vtk_reason(errors, printed)));
  return reader->GetOutput();
}

vtkSmartPointer<vtkPolyData> load_legacy(const fs::path& file) {
  // VTK's legacy reader trusts every count: a cut-off file crashes it. A file with METADATA
  // blocks comes back with them blanked; VTK reads that text instead of the file.
  std::optional<std::string> checked = check_legacy_vtk_file(file);
  VtkMessageCapture printed;
  vtkNew<vtkPolyDataReader> reader;
  ErrorObserver errors(*reader);
  vtkNew<vtkCharArray> text;
  if (checked) {
    text->SetArray(checked->data(), vtkIdType(checked->size()), 1);  // 1: the string keeps its bytes
    reader->SetInputArray(text);
    reader->ReadFromInputStringOn();
  } else {
    reader->SetFileName(file.c_str());
  }
  if (!reader->IsFilePolyData())
    fail(file, "it is not a legacy VTK file with POLYDATA (other dataset types are not "
               "surfaces this tool refines)");
  reader->Update();
  if (!errors.text().empty() || reader->GetErrorCode() != 0 || !printed.first_error().empty())
    fail(file, fmt::format("VTK reports: {}", vtk_reason(errors, printed)));
  return reader->GetOutput();
}

// Every id of `kind` cell `cell` names a point: checked here, on VTK's 64-bit ids, because
// the 32-bit indices they become would wrap (2^32 + 6 became vertex 6).
void check_ids(const vtkIdType* ids, vtkIdType size, vtkIdType points, const char* kind, vtkIdType cell,
               const fs::path& file) {
  for (vtkIdType i = 0; i < size; ++i)
    if (ids[i] < 0 || ids[i] >= points)
      fail(file, fmt::format("{} {} refers to point {}, but the file has {} points (0 to {}); the connectivity array "
                             "is damaged",
                             kind, cell, ids[i], points, points - 1));
}

// Appends every cell of `cells` to a CSR pair.
void append_cells(vtkCellArray* cells, vtkIdType points, ScratchVector<Index>& offsets, ScratchVector<Index>& indices,
                  const fs::path& file) {
  // Sized once: growing by each cell's ids copied a 16M-face level's corners several times.
  indices.reserve(indices.size() + std::size_t(cells->GetNumberOfConnectivityIds()));
  offsets.reserve(offsets.size() + std::size_t(cells->GetNumberOfCells()));
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  vtkIdType cell = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell) {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    check_ids(ids, size, points, "polygon", cell, file);
    indices.insert(indices.end(), ids, ids + size);
    offsets.push_back(Index(indices.size()));
  }
}

// Strip p0 p1 p2 p3 ... gives triangles (p0 p1 p2), (p2 p1 p3), ...: every second one is
// flipped so that all keep the strip's orientation.
void append_strips(vtkCellArray* strips, vtkIdType points, MeshData& mesh, const fs::path& file) {
  auto it = vtk::TakeSmartPointer(strips->NewIterator());
  vtkIdType cell = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell) {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    check_ids(ids, size, points, "triangle strip", cell, file);
    for (vtkIdType i = 0; i + 2 < size; ++i) {
      const bool odd = i % 2 != 0;
      mesh.face_vertices.insert(mesh.face_vertices.end(),
                                {Index(ids[odd ? i + 1 : i]), Index(ids[odd ? i : i + 1]),
                                 Index(ids[i + 2])});
      mesh.face_offsets.push_back(Index(mesh.face_vertices.size()));
    }
  }
}

// Line cells are polylines, except in files from write_vtp, which marks crease edges with
// cell_kind 2 and stores their sharpness; reading those back keeps .vtp lossless.
void append_lines(vtkPolyData& poly, MeshData& mesh, const fs::path& file) {
  vtkDataArray* kind = poly.GetCellData()->GetArray("cell_kind");
  vtkDataArray* sharpness = poly.GetCellData()->GetArray("sharpness");
  // Arrays shorter than the cells (a damaged file) would be read past their end.
  const vtkIdType cells = poly.GetNumberOfCells();
  const bool tagged = kind && sharpness && kind->GetNumberOfTuples() >= cells && sharpness->GetNumberOfTuples() >= cells;
  vtkIdType cell = poly.GetNumberOfVerts();  // VTK numbers cells: verts, lines, polys, strips
  auto it = vtk::TakeSmartPointer(poly.GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell) {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    check_ids(ids, size, poly.GetNumberOfPoints(), "line", cell - poly.GetNumberOfVerts(), file);
    if (tagged && size == 2 && kind->GetTuple1(cell) == 2) {
      mesh.creases.push_back({Index(ids[0]), Index(ids[1]), sharpness->GetTuple1(cell)});
      continue;
    }
    mesh.line_vertices.insert(mesh.line_vertices.end(), ids, ids + size);
    mesh.line_offsets.push_back(Index(mesh.line_vertices.size()));
  }
}

void restore_corners(vtkPolyData& poly, MeshData& mesh) {
  vtkDataArray* corners = poly.GetPointData()->GetArray("corner_sharpness");
  if (!corners || corners->GetNumberOfTuples() < poly.GetNumberOfPoints()) return;
  for (vtkIdType v = 0; v < poly.GetNumberOfPoints(); ++v)
    if (const double s = corners->GetTuple1(v); s != 0) mesh.corners.push_back({Index(v), s});
}

ArrayRole role_of(vtkDataSetAttributes& attributes, vtkDataArray* array) {
  if (array == attributes.GetNormals()) return ArrayRole::Normals;
  if (array == attributes.GetTCoords()) return ArrayRole::TextureCoordinates;
  if (array == attributes.GetScalars() && array->GetDataType() == VTK_UNSIGNED_CHAR) return ArrayRole::Color;
  return ArrayRole::Data;
}

// Every numeric array of `attributes`, with the tuples `pick(i)` for i < count (point data:
// every point; cell data: the cells that became faces).
template <typename Pick>
std::vector<DataArray> read_arrays(vtkDataSetAttributes& attributes, bool point, vtkIdType count, Pick pick,
                                   const fs::path& file) {
  std::vector<DataArray> out;
  for (int i = 0; i < attributes.GetNumberOfArrays(); ++i) {
    vtkAbstractArray* abstract = attributes.GetAbstractArray(i);
    const char* name = abstract ? abstract->GetName() : nullptr;
    if (subdivkit_array(name, point)) continue;
    const std::string shown = name && *name ? name : fmt::format("#{}", i);
    auto* array = vtkDataArray::SafeDownCast(abstract);
    if (!array)
      fail(file, fmt::format("{} array {} is not numeric ({}); SubdivKit refines numbers only: remove it or "
                             "convert it", point ? "point" : "cell", subdiv::quoted(shown), abstract->GetClassName()));
    DataArray a;
    a.name = name && *name ? name : fmt::format("array_{}", i);
    a.components = array->GetNumberOfComponents();
    a.integer = array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE;
    a.role = role_of(attributes, array);
    a.values.reserve(size_t(count) * size_t(a.components));
    for (vtkIdType t = 0; t < count; ++t)
      for (int c = 0; c < a.components; ++c) a.values.push_back(array->GetComponent(pick(t), c));
    // 64-bit ids beyond an int are carried as doubles rather than refused.
    for (double x : a.values) a.integer = a.integer && std::abs(x) <= 2147483647.0;
    out.push_back(std::move(a));
  }
  return out;
}

// Cell tuples for the faces: each polygon's own, and each strip's for every triangle cut from it.
std::vector<vtkIdType> face_cells(vtkPolyData& poly) {
  std::vector<vtkIdType> cells;
  const vtkIdType first_poly = poly.GetNumberOfVerts() + poly.GetNumberOfLines();
  for (vtkIdType i = 0; i < poly.GetNumberOfPolys(); ++i) cells.push_back(first_poly + i);
  const vtkIdType first_strip = first_poly + poly.GetNumberOfPolys();
  auto it = vtk::TakeSmartPointer(poly.GetStrips()->NewIterator());
  vtkIdType strip = first_strip;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++strip) {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    for (vtkIdType i = 0; i + 2 < size; ++i) cells.push_back(strip);
  }
  return cells;
}

void read_user_arrays(vtkPolyData& poly, MeshData& mesh, const fs::path& file) {
  const vtkIdType points = poly.GetNumberOfPoints();
  for (int i = 0; i < poly.GetPointData()->GetNumberOfArrays(); ++i)
    if (auto* a = poly.GetPointData()->GetAbstractArray(i); a && a->GetNumberOfTuples() < points)
      fail(file, fmt::format("point array {} has {} tuples for {} points", subdiv::quoted(a->GetName() ? a->GetName() : ""),
                             a->GetNumberOfTuples(), points));
  mesh.point_data = read_arrays(*poly.GetPointData(), true, points, [](vtkIdType t) { return t; }, file);
  const std::vector<vtkIdType> cells = face_cells(poly);
  for (int i = 0; i < poly.GetCellData()->GetNumberOfArrays(); ++i)
    if (auto* a = poly.GetCellData()->GetAbstractArray(i); a && a->GetNumberOfTuples() < poly.GetNumberOfCells())
      fail(file, fmt::format("cell array {} has {} tuples for {} cells", subdiv::quoted(a->GetName() ? a->GetName() : ""),
                             a->GetNumberOfTuples(), poly.GetNumberOfCells()));
  mesh.cell_data = read_arrays(*poly.GetCellData(), false, vtkIdType(cells.size()),
                               [&](vtkIdType t) { return cells[size_t(t)]; }, file);
}

}  // namespace

bool subdivkit_array(const char* name, bool point) {
  static const std::set<std::string> points = {"corner_sharpness", "origin", "valence", "level", "vertex_class",
                                               "limit_exact", "normal_exact", "rule"};
  static const std::set<std::string> cells = {"cell_kind", "sharpness", "parent_face", "base_face"};
  return name && (point ? points : cells).count(name) > 0;
}

MeshData polydata_to_mesh_data(vtkPolyData& poly, const fs::path& file) {
  MeshData mesh;
  const vtkIdType n = poly.GetNumberOfPoints();
  mesh.positions.resize(std::size_t(n) * 3);
  // Double coordinates (what SubdivKit writes) are copied whole; others point by point.
  vtkDoubleArray* xyz = n > 0 ? vtkDoubleArray::FastDownCast(poly.GetPoints()->GetData()) : nullptr;
  if (xyz && xyz->GetNumberOfComponents() == 3 && xyz->GetNumberOfTuples() == n)
    std::copy_n(xyz->GetPointer(0), std::size_t(n) * 3, mesh.positions.data());
  else
    for (vtkIdType v = 0; v < n; ++v) poly.GetPoint(v, &mesh.positions[3 * v]);
  if (n > std::numeric_limits<Index>::max())
    fail(file, fmt::format("it has {} points, more than SubdivKit's 32-bit indices hold", n));
  append_cells(poly.GetPolys(), n, mesh.face_offsets, mesh.face_vertices, file);
  append_strips(poly.GetStrips(), n, mesh, file);
  append_lines(poly, mesh, file);
  restore_corners(poly, mesh);
  read_user_arrays(poly, mesh, file);
  return mesh;
}

MeshData read_vtk_polydata_with_vtk(const fs::path& file) {
  require_readable(file);
  const auto poly = lowercase_extension(file) == ".vtp" ? load_xml(file) : load_legacy(file);
  if (!poly) fail(file, "VTK produced no data");
  if (poly->GetNumberOfPoints() > std::numeric_limits<Index>::max())
    fail(file, "it has more points than SubdivKit's 32-bit indices hold");
  return polydata_to_mesh_data(*poly, file);
}

MeshData read_vtk_polydata(const fs::path& file) {
  require_readable(file);
  if (lowercase_extension(file) == ".vtp")
    if (std::optional<MeshData> fast = read_vtp_fast_file(file)) return std::move(*fast);
  return read_vtk_polydata_with_vtk(file);
}

}  // namespace subdiv::io_detail
