#include "framework/io/vtk/vtk_polydata.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <new>
#include <numeric>
#include <span>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataCompressor.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

#include "framework/io/mesh_validate.h"
#include "framework/io/vtk/vtk_array_ranges.h"
#include "framework/io/vtk/vtk_block_compressor.h"
#include "framework/io/vtk/vtk_fast_xml_writer.h"
#include "framework/io/vtk/vtk_xml_text.h"
#include "framework/util/checked_file_stream.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

// Bytes per compressed block. VTK's default, 32 KB, costs a compressor set-up and a flush of
// the stream per block (vtkXMLWriter::WriteCompressionBlock); larger blocks wrote the
// 16M-face torus faster and no larger (docs/benchmarks.md). Readers take the size from the file.
constexpr int kBlockSize = 1 << 20;

// Arrays write_vtp adds itself; user arrays may not take these names.
const std::set<std::string> kReservedCellArrays = {"sharpness", "cell_kind"};
const std::set<std::string> kReservedPointArrays = {"corner_sharpness"};

// VTK numbers the cells of a vtkPolyData lines first, then polygons; callers give cell
// values faces first. Cell data is reordered here so that every value lands on its cell.
struct CellCounts {
  std::size_t faces, polylines, creases;
  std::size_t lines() const { return polylines + creases; }
  std::size_t total() const { return faces + lines(); }
};

CellCounts cell_counts(const MeshData& mesh) {
  return {std::size_t(mesh.face_count()), std::size_t(mesh.line_count()), mesh.creases.size()};
}

// Whether `v` is a whole number that fits an int, as an integer array's values must be.
bool whole_int(double v) {
  return v == std::floor(v) && v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max();
}

// The first value of `a` that whole_int refuses, named; `a` holds one.
[[noreturn]] void refuse_integer_values(const DataArray& a, std::string_view context) {
  std::size_t i = 0;
  while (i + 1 < a.values.size() && whole_int(a.values[i])) ++i;
  throw Error(fmt::format("{}: integer array {} holds {} at position {}, which is not a "
                          "whole number that fits an int; mark the array as not integer",
                          context, subdiv::quoted(a.name), a.values[i], i));
}

// `check_integers`: whether an integer array's values are checked here, or when to_vtk
// converts them (IntegerValues).
void check_array(const DataArray& a, std::size_t tuples, const char* per, bool check_integers,
                 std::string_view context) {
  if (a.name.empty()) throw Error(fmt::format("{}: a {} data array has no name", context, per));
  require_xml_text(a.name, fmt::format("{} data array", per), context);
  if (a.components < 1)
    throw Error(fmt::format("{}: array {} has {} components; it needs at least 1", context,
                            subdiv::quoted(a.name), a.components));
  if (a.values.size() != tuples * std::size_t(a.components))
    throw Error(fmt::format("{}: array {} has {} values, expected {} ({} {}s x {} "
                            "components)",
                            context, subdiv::quoted(a.name), a.values.size(), tuples * a.components, tuples,
                            per, a.components));
  if (!a.integer || !check_integers) return;
  // On every core first; in order, for the message, only if some value is not whole.
  const bool all_whole = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, a.values.size(), 1 << 14), true,
      [&](const tbb::blocked_range<std::size_t>& r, bool ok) {
        for (std::size_t i = r.begin(); ok && i != r.end(); ++i) ok = whole_int(a.values[i]);
        return ok;
      },
      [](bool x, bool y) { return x && y; });
  if (!all_whole) refuse_integer_values(a, context);
}

void check_arrays(const std::vector<DataArray>& arrays, const std::set<std::string>& reserved,
                  const char* per, std::size_t tuples, std::size_t alternative_tuples, bool check_integers,
                  std::string_view context) {
  std::set<std::string> names;
  for (const DataArray& a : arrays) {
    if (reserved.count(a.name))
      throw Error(fmt::format("{}: array name {} is reserved for the array write_vtp adds; "
                              "rename it",
                              context, subdiv::quoted(a.name)));
    if (!names.insert(a.name).second)
      throw Error(fmt::format("{}: two {} data arrays are named {}", context, per, subdiv::quoted(a.name)));
    const bool alternative = a.components > 0 &&
                             a.values.size() == alternative_tuples * std::size_t(a.components);
    check_array(a, alternative ? alternative_tuples : tuples, per, check_integers, context);
  }
}

template <typename Array>
vtkSmartPointer<Array> new_array(const std::string& name, int components, std::size_t tuples) {
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(vtkIdType(tuples));
  return array;
}

// `values` as a VTK array of the same type: their own memory, handed over without a copy
// (`share`, see make_polydata), or a copy.
template <typename Array, typename T, typename Allocator>
vtkSmartPointer<Array> wrap(const std::vector<T, Allocator>& values, bool share) {
  auto array = vtkSmartPointer<Array>::New();
  if (share) {
    array->SetArray(const_cast<T*>(values.data()), vtkIdType(values.size()), 1);  // 1: VTK does not free it
  } else {
    array->SetNumberOfValues(vtkIdType(values.size()));
    std::copy(values.begin(), values.end(), array->GetPointer(0));
  }
  return array;
}

// `values` is already in VTK's cell or point order.
// An integer array's values as ints, with their range (cached for the writer's header) and
// the check that each is whole and fits an int, all in one pass (16M faces' base_face: a
// check, a conversion and a range were three). Throws as check_array does if one is not.
vtkSmartPointer<vtkIntArray> to_vtk_ints(const DataArray& a, const std::vector<double>& values,
                                         std::string_view context) {
  auto array = new_array<vtkIntArray>(a.name, a.components, values.size() / std::size_t(a.components));
  int* out = array->GetPointer(0);
  struct Seen {
    int min = std::numeric_limits<int>::max(), max = std::numeric_limits<int>::min();
    bool whole = true;
  };
  const Seen seen = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, values.size(), 1 << 16), Seen{},
      [&](const tbb::blocked_range<std::size_t>& r, Seen so_far) {
        int lo = so_far.min, hi = so_far.max, refused = 0;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          const double v = values[i];
          // Outside int (or NaN) converted as 0, which then differs from v: refused.
          const bool fits = v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max();
          const int n = int(fits ? v : 0.0);
          out[i] = n;
          refused |= int(double(n) != v);
          lo = n < lo ? n : lo;
          hi = n > hi ? n : hi;
        }
        return Seen{lo, hi, so_far.whole && refused == 0};
      },
      [](const Seen& x, const Seen& y) { return Seen{std::min(x.min, y.min), std::max(x.max, y.max), x.whole && y.whole}; });
  if (!seen.whole) refuse_integer_values(a, context);
  if (!values.empty()) store_array_range(array, seen.min, seen.max);
  return array;
}

// `context` names the file in the message for an integer array's value that is not whole.
vtkSmartPointer<vtkDataArray> to_vtk(const DataArray& a, const std::vector<double>& values, bool share,
                                     std::string_view context) {
  const std::size_t tuples = values.size() / a.components;
  // Integer colours within 0..255 as bytes, as PLY stores them: ParaView shows byte scalars
  // as colours directly, and the reader (vtk_read.cpp role_of) knows them for colours again.
  const auto byte = [](double x) { return x >= 0 && x <= 255 && x == std::floor(x); };
  if (a.integer && a.role == ArrayRole::Color && std::all_of(values.begin(), values.end(), byte)) {
    auto array = new_array<vtkUnsignedCharArray>(a.name, a.components, tuples);
    for (std::size_t i = 0; i < values.size(); ++i)
      array->SetValue(vtkIdType(i), static_cast<unsigned char>(values[i]));
    return array;
  }
  if (a.integer) return to_vtk_ints(a, values, context);
  auto array = wrap<vtkDoubleArray>(values, share);
  array->SetName(a.name.c_str());
  array->SetNumberOfComponents(a.components);
  return array;
}

// Cell values in VTK order: line cells first (padded with -1 for per-face arrays).
std::vector<double> cell_order(const DataArray& a, const CellCounts& cells) {
  const std::size_t c = std::size_t(a.components);
  const auto faces_end = a.values.begin() + std::ptrdiff_t(cells.faces * c);
  std::vector<double> out;
  out.reserve(cells.total() * c);
  if (a.values.size() == cells.total() * c && cells.lines() > 0)
    out.insert(out.end(), faces_end, a.values.end());
  else
    out.insert(out.end(), cells.lines() * c, -1.0);
  out.insert(out.end(), a.values.begin(), faces_end);
  return out;
}

// The mesh's indices as they are (32 bits), which vtkCellArray stores and the writer
// writes as they are (connectivity and offsets as Int32 in the file): no 64-bit copy.
vtkSmartPointer<vtkCellArray> cell_array(const ScratchVector<Index>& offsets, const ScratchVector<Index>& connectivity,
                                         bool share) {
  static_assert(sizeof(Index) == sizeof(vtkTypeInt32));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  if (offsets.empty()) return cells;  // no cells (VTK wants the leading 0 otherwise)
  cells->SetData(wrap<vtkTypeInt32Array>(offsets, share), wrap<vtkTypeInt32Array>(connectivity, share));
  return cells;
}

vtkSmartPointer<vtkPoints> points(const MeshData& mesh, bool share) {
  auto coords = wrap<vtkDoubleArray>(mesh.positions, share);
  coords->SetName("Points");
  coords->SetNumberOfComponents(3);
  auto pts = vtkSmartPointer<vtkPoints>::New();
  pts->SetData(coords);
  return pts;
}

// Polylines, then one two-point line per crease edge: a few cells, made and owned by VTK.
vtkSmartPointer<vtkCellArray> lines(const MeshData& mesh) {
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (Index l = 0; l < mesh.line_count(); ++l) {
    cells->InsertNextCell(mesh.line_offsets[l + 1] - mesh.line_offsets[l]);
    for (Index i = mesh.line_offsets[l]; i < mesh.line_offsets[l + 1]; ++i)
      cells->InsertCellPoint(mesh.line_vertices[i]);
  }
  for (const CreaseTag& c : mesh.creases) {
    const vtkIdType ends[2] = {c.v0, c.v1};
    cells->InsertNextCell(2, ends);
  }
  return cells;
}

// A one-component array of zeros in memory from calloc: blocks this large come from the
// kernel as zero pages that nothing here writes, so the writer reads them without the first
// touch (the kernel clearing each page) that filling a fresh array with zeros costs: 320 MB
// for the three arrays below on a 16M-face level, almost all zeros.
template <typename Array>
vtkSmartPointer<Array> zero_array(const char* name, std::size_t tuples) {
  using Value = typename Array::ValueType;
  auto* values = static_cast<Value*>(std::calloc(std::max<std::size_t>(tuples, 1), sizeof(Value)));
  if (!values) throw std::bad_alloc();
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfComponents(1);
  array->SetArray(values, vtkIdType(tuples), 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);  // VTK frees it
  return array;
}

// Their ranges from the values set (cache_sparse_array_range), not from a pass over the zeros.
void add_feature_arrays(vtkPolyData& poly, const MeshData& mesh, const CellCounts& cells,
                        const VtkWriteOptions& options) {
  std::vector<vtkIdType> line_cells(cells.lines());  // polylines, then creases
  std::iota(line_cells.begin(), line_cells.end(), vtkIdType(0));
  const std::span<const vtkIdType> crease_cells = std::span<const vtkIdType>(line_cells).subspan(cells.polylines);
  if (options.sharpness) {
    auto sharpness = zero_array<vtkDoubleArray>("sharpness", cells.total());
    for (std::size_t i = 0; i < cells.creases; ++i)
      sharpness->SetValue(vtkIdType(cells.polylines + i), mesh.creases[i].sharpness);
    cache_sparse_array_range(sharpness, crease_cells);
    poly.GetCellData()->AddArray(sharpness);
  }
  if (options.cell_kind) {
    auto kind = zero_array<vtkIntArray>("cell_kind", cells.total());  // 0: faces, which come after the line cells
    for (std::size_t i = 0; i < cells.polylines; ++i) kind->SetValue(vtkIdType(i), 1);
    for (std::size_t i = 0; i < cells.creases; ++i) kind->SetValue(vtkIdType(cells.polylines + i), 2);
    cache_sparse_array_range(kind, line_cells);
    poly.GetCellData()->AddArray(kind);
  }
  if (options.corner_sharpness) {
    auto corners = zero_array<vtkDoubleArray>("corner_sharpness", std::size_t(mesh.vertex_count()));
    std::vector<vtkIdType> tagged;
    for (const CornerTag& c : mesh.corners) corners->SetValue(c.v, c.sharpness), tagged.push_back(c.v);
    cache_sparse_array_range(corners, tagged);
    poly.GetPointData()->AddArray(corners);
  }
}

// ParaView reads "TimeValue" as the time of a single file; "level" says it plainly.
void add_level_fields(vtkPolyData& poly, int level) {
  auto level_array = new_array<vtkIntArray>("level", 1, 1);
  level_array->SetValue(0, level);
  auto time = new_array<vtkDoubleArray>("TimeValue", 1, 1);
  time->SetValue(0, level);
  poly.GetFieldData()->AddArray(level_array);
  poly.GetFieldData()->AddArray(time);
}

}  // namespace

LevelCheck check_output_level(const OutputLevel& level, std::string_view context, IntegerValues integers) {
  if (!level.mesh) throw Error(fmt::format("{}: level {} has no mesh", context, level.level));
  LevelCheck check{{}, std::string(context)};
  validate_mesh_data(*level.mesh, context, &check.mesh);
  const bool now = integers == IntegerValues::Checked;
  const CellCounts cells = cell_counts(*level.mesh);
  const std::size_t vertices = std::size_t(level.mesh->vertex_count());
  check_arrays(level.point_data, kReservedPointArrays, "point", vertices, vertices, now, context);
  check_arrays(level.cell_data, kReservedCellArrays, "face", cells.faces, cells.total(), now, context);
  return check;
}

vtkSmartPointer<vtkPolyData> make_polydata(const OutputLevel& level, const VtkWriteOptions& options,
                                           LevelMemory memory, const LevelCheck* check) {
  const bool share = memory == LevelMemory::Share;
  const MeshData& mesh = *level.mesh;
  const CellCounts cells = cell_counts(mesh);
  vtkSmartPointer<vtkPolyData> poly = vtkSmartPointer<FastCellTypesPolyData>::New();
  poly->SetPoints(points(mesh, share));
  poly->SetPolys(cell_array(mesh.face_offsets, mesh.face_vertices, share));
  poly->SetLines(lines(mesh));
  const std::string_view context = check ? std::string_view(check->context) : "cannot convert the level";
  vtkPointData& point_data = *poly->GetPointData();
  for (const DataArray& a : level.point_data) {
    const auto array = to_vtk(a, a.values, share, context);
    point_data.AddArray(array);
    // Active attributes, so that ParaView shades with the normals and textures with the UVs.
    // Only the first array of each role: setting another would drop the first from the
    // file (vtkDataSetAttributes::SetAttribute removes the array it replaces).
    if (a.role == ArrayRole::Normals && a.components == 3 && !point_data.GetNormals()) point_data.SetNormals(array);
    if (a.role == ArrayRole::TextureCoordinates && a.components <= 3 && !point_data.GetTCoords())
      point_data.SetTCoords(array);
    if (a.role == ArrayRole::Color && !point_data.GetScalars()) point_data.SetScalars(array);
  }
  for (const DataArray& a : level.cell_data)  // already in VTK's order without line cells
    poly->GetCellData()->AddArray(cells.lines() == 0 ? to_vtk(a, a.values, share, context)
                                                     : to_vtk(a, cell_order(a, cells), false, context));  // a temporary
  add_level_fields(*poly, level.level);
  if (check && check->mesh.point_norms_known && mesh.vertex_count() > 0)
    store_array_range(poly->GetPoints()->GetData(), check->mesh.point_norm_min, check->mesh.point_norm_max);
  if (check && check->mesh.face_vertices_known && !mesh.face_vertices.empty())
    store_array_range(poly->GetPolys()->GetConnectivityArray(), check->mesh.face_vertex_min, check->mesh.face_vertex_max);
  cache_array_ranges(*poly);
  add_feature_arrays(*poly, mesh, cells, options);  // after: with ranges of their own
  return poly;
}

namespace {

// VTK's writer puts names between quotes as they are; escaped here, its XML reader (and
// ParaView's) gives back the names themselves. The arrays are the polydata's own, made
// for this write (make_polydata), so renaming them changes no caller's data.
void escape_names(vtkFieldData* data) {
  if (!data) return;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
    if (vtkAbstractArray* a = data->GetAbstractArray(i); a && a->GetName()) {
      const std::string escaped = xml_attribute_text(a->GetName());
      if (escaped == a->GetName()) continue;
      a->SetName(escaped.c_str());
      // Renaming marks the array modified, which drops its cached range; VTK's own
      // computation would write an overflowing norm as Infinity (found by fuzz_write_read).
      cache_array_range(vtkDataArray::SafeDownCast(a));
    }
}

}  // namespace

void write_polydata_file(vtkPolyData& poly, const fs::path& file, const fs::path& shown,
                         const VtkWriteOptions& options, BlockCounts* counts) {
  escape_names(poly.GetPointData());
  escape_names(poly.GetCellData());
  escape_names(poly.GetFieldData());
  std::string errors;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&errors);
  observer->SetCallback([](vtkObject*, unsigned long, void* text, void* message) {
    auto& errors = *static_cast<std::string*>(text);
    if (errors.empty() && message) errors = static_cast<const char*>(message);
  });
  vtkNew<FastXMLPolyDataWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, observer);
  // VTK's progress goes back and forth between the parts it writes (and says 1 before the
  // end): reported here as the most so far, below 1 until the file is written.
  vtkNew<vtkCallbackCommand> progress;
  double most = 0;
  std::function<void(double)> report = [&](double done) {
    most = std::max(most, std::min(done, 0.99));
    options.progress(most);
  };
  if (options.progress) {
    report(0);
    progress->SetClientData(&report);
    progress->SetCallback([](vtkObject*, unsigned long, void* to, void* done) {
      if (done) (*static_cast<std::function<void(double)>*>(to))(*static_cast<double*>(done));
    });
    writer->AddObserver(vtkCommand::ProgressEvent, progress);
  }
  writer->SetInputData(&poly);
  // No file name: VTK neither opens nor deletes anything; the stream reports write failures
  // (full disk) after VTK is done with it.
  CheckedFileStream stream(file, shown, options.direct_io ? FileWrite::Direct : FileWrite::Buffered);
  writer->WriteToStream(&stream);
  // By default inline binary (base64 inside each DataArray), not raw appended data: the file
  // is then well-formed XML, which every ParaView reads, including Debian 12's ParaView 5.11
  // whose VTK fails on appended data with the system's Expat (see expat_reparse_fix.cpp).
  if (options.encoding == VtkEncoding::Raw) {
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
  } else {
    writer->SetDataModeToBinary();
  }
  writer->SetBlockSize(kBlockSize);
  writer->SetCompressor(make_block_compressor(options.compressor, options.compression_level, kBlockSize,
                                              contiguous_arrays(poly), counts));
  writer->SetHeaderTypeToUInt64();  // blocks over 4 GB on large levels
  const int written = writer->Write();
  writer->WriteToStream(nullptr);
  stream.close();  // a failed write is the cause of anything VTK reports after it
  if (written != 1 || writer->GetErrorCode() != 0 || !errors.empty())
    throw Error(fmt::format("cannot write {}: VTK reports: {}", subdiv::quoted(shown.string()),
                            errors.empty() ? "an unknown error" : errors));
  if (options.progress) options.progress(1.0);
}

}  // namespace subdiv::io_detail
