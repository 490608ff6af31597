// write_polydata_file (framework/io/vtk/vtk_polydata.h): the inline pipeline, the parallel
// block compressor, the fast base64 stream and the cached ranges write exactly the file VTK's own
// vtkXMLPolyDataWriter writes with the same settings, for any thread count.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tbb/global_control.h>
#include <vtkCellData.h>
#include <vtkDataCompressor.h>
#include <vtkDoubleArray.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkZLibDataCompressor.h>

#include "framework/io/vtk/vtk_block_compressor.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/io/vtk/vtk_polydata.h"
#include "io_test_support.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

// A grid of n x n quads with a bumpy height, a double and an integer point array, an
// integer cell array, a crease, corners and a polyline: arrays of several blocks of 1 MB each.
MeshData grid(int n) {
  MeshData m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.insert(m.positions.end(), {double(i), double(j), std::sin(0.1 * i * j)});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index v = j * (n + 1) + i;
      m.face_vertices.insert(m.face_vertices.end(), {v, v + 1, v + n + 2, v + n + 1});
      m.face_offsets.push_back(Index(m.face_vertices.size()));
    }
  DataArray heat{"heat", 1, {}, false}, id{"id", 1, {}, true}, face{"face", 1, {}, true};
  for (Index v = 0; v < m.vertex_count(); ++v) heat.values.push_back(std::cos(0.01 * v)), id.values.push_back(v % 977);
  for (Index f = 0; f < m.face_count(); ++f) face.values.push_back(f);
  m.point_data = {heat, id};
  m.cell_data = {face};
  m.creases.push_back({0, 1, 2.5f});
  // Corners and a polyline: write_vtp's feature arrays with values besides their zeros,
  // whose ranges come from the tags (cache_sparse_array_range), checked against VTK's.
  m.corners = {{n + 2, 3.0}, {2 * n, 0.5}, {n + 2, 4.0}};
  m.line_vertices = {0, n + 1, 2 * n + 2};
  m.line_offsets = {0, 3};
  return m;
}

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// VTK's own writer with the settings write_polydata_file uses.
void write_with_vtk(vtkPolyData& poly, const fs::path& file, VtkCompressor type, int level,
                    VtkEncoding encoding = VtkEncoding::Base64) {
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(&poly);
  writer->SetFileName(file.c_str());
  if (encoding == VtkEncoding::Raw) {
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
  } else {
    writer->SetDataModeToBinary();
  }
  writer->SetBlockSize(1 << 20);
  writer->SetHeaderTypeToUInt64();
  switch (type) {
    case VtkCompressor::None: writer->SetCompressorTypeToNone(); break;
    case VtkCompressor::ZLib: writer->SetCompressorTypeToZLib(); break;
    case VtkCompressor::LZ4: writer->SetCompressorTypeToLZ4(); break;
    case VtkCompressor::LZMA: writer->SetCompressorTypeToLZMA(); break;
  }
  writer->SetCompressionLevel(level);
  REQUIRE(writer->Write() == 1);
}

}  // namespace

TEST_CASE("write_polydata_file writes VTK's own file, byte for byte, on any number of threads") {
  const subdiv::test::TempDir scratch;  // its own folder: other test runs may be writing at the same time
  const fs::path& dir = scratch.path();
  const MeshData mesh = grid(300);  // 90601 points: 2.2 MB of coordinates
  OutputLevel level{&mesh, 2, mesh.point_data, mesh.cell_data};
  const auto poly = io_detail::make_polydata(level);
  for (VtkCompressor type : {VtkCompressor::ZLib, VtkCompressor::LZ4, VtkCompressor::LZMA, VtkCompressor::None}) {
    for (int compression_level : {1, 6}) {
      CAPTURE(int(type));
      CAPTURE(compression_level);
      write_with_vtk(*poly, dir / "vtk.vtp", type, compression_level);
      const std::string expected = file_text(dir / "vtk.vtp");
      for (int threads : {1, 2, 3}) {
        CAPTURE(threads);
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        io_detail::BlockCounts counts;
        VtkWriteOptions options;
        options.compressor = type;
        options.compression_level = compression_level;
        io_detail::write_polydata_file(*poly, dir / "ours.vtp", dir / "ours.vtp", options, &counts);
        CHECK(file_text(dir / "ours.vtp") == expected);
        if (type == VtkCompressor::None) continue;
        // Every array's blocks go through the inline pipeline (vtk_inline_blocks.h): VTK's own
        // block loop, which calls the block compressor, compresses none.
        CHECK(counts.parallel + counts.serial == 0);
      }
    }
  }
}

TEST_CASE("write_polydata_file with raw appended data writes VTK's own file, byte for byte, on any number of threads") {
  const subdiv::test::TempDir scratch;  // its own folder: other test runs may be writing at the same time
  const fs::path& dir = scratch.path();
  const MeshData mesh = grid(300);
  OutputLevel level{&mesh, 2, mesh.point_data, mesh.cell_data};
  const auto poly = io_detail::make_polydata(level);
  for (VtkCompressor type : {VtkCompressor::ZLib, VtkCompressor::LZ4, VtkCompressor::None}) {
    CAPTURE(int(type));
    write_with_vtk(*poly, dir / "vtk.vtp", type, 1, VtkEncoding::Raw);
    const std::string expected = file_text(dir / "vtk.vtp");
    REQUIRE(expected.find("<AppendedData encoding=\"raw\">") != std::string::npos);
    for (int threads : {1, 2, 3}) {
      CAPTURE(threads);
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      VtkWriteOptions options;
      options.compressor = type;
      options.encoding = VtkEncoding::Raw;
      io_detail::write_polydata_file(*poly, dir / "ours.vtp", dir / "ours.vtp", options);
      CHECK(file_text(dir / "ours.vtp") == expected);
    }
  }
}

TEST_CASE("the block compressor in small blocks: many runs of parallel blocks, VTK's bytes") {
  const subdiv::test::TempDir scratch;  // its own folder: other test runs may be writing at the same time
  const fs::path& dir = scratch.path();
  const MeshData mesh = grid(120);  // 14641 points: 343 blocks of 1 KB of coordinates, runs of 64
  OutputLevel level{&mesh, 0, mesh.point_data, mesh.cell_data};
  const auto poly = io_detail::make_polydata(level);
  const auto write = [&](const fs::path& file, vtkDataCompressor* compressor) {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(poly);
    writer->SetFileName(file.c_str());
    writer->SetDataModeToBinary();
    writer->SetBlockSize(1024);
    writer->SetHeaderTypeToUInt64();
    if (compressor) writer->SetCompressor(compressor);
    else writer->SetCompressorTypeToZLib(), writer->SetCompressionLevel(3);
    REQUIRE(writer->Write() == 1);
  };
  write(dir / "vtk.vtp", nullptr);
  io_detail::BlockCounts counts;
  write(dir / "ours.vtp",
        io_detail::make_block_compressor(VtkCompressor::ZLib, 3, 1024, io_detail::contiguous_arrays(*poly), &counts));
  CHECK(file_text(dir / "ours.vtp") == file_text(dir / "vtk.vtp"));
  CHECK(counts.parallel > 343);
  CHECK(counts.serial < counts.parallel / 2);  // the offsets, which VTK copies
}

TEST_CASE("write_polydata_file: direct I/O and the page cache write the same file") {
  // Files of several 4 MB chunks (the direct writer's), so that VTK's seeks back (each
  // array's compression header, raw appended data's offsets) land in chunks already written.
  const subdiv::test::TempDir scratch;  // its own folder: other test runs may be writing at the same time
  const fs::path& dir = scratch.path();
  const MeshData mesh = grid(700);  // 491401 points: 11.8 MB of coordinates
  OutputLevel level{&mesh, 1, mesh.point_data, mesh.cell_data};
  const auto poly = io_detail::make_polydata(level);
  for (VtkEncoding encoding : {VtkEncoding::Base64, VtkEncoding::Raw}) {
    for (VtkCompressor type : {VtkCompressor::LZ4, VtkCompressor::None}) {
      CAPTURE(int(encoding));
      CAPTURE(int(type));
      VtkWriteOptions options;
      options.compressor = type;
      options.encoding = encoding;
      options.direct_io = false;
      io_detail::write_polydata_file(*poly, dir / "cached.vtp", dir / "cached.vtp", options);
      options.direct_io = true;
      io_detail::write_polydata_file(*poly, dir / "direct.vtp", dir / "direct.vtp", options);
      const std::string cached = file_text(dir / "cached.vtp");
      CHECK(cached.size() > (8u << 20));
      CHECK(file_text(dir / "direct.vtp") == cached);
    }
  }
  write_with_vtk(*poly, dir / "vtk.vtp", VtkCompressor::LZ4, 1);
  VtkWriteOptions options;
  io_detail::write_polydata_file(*poly, dir / "ours.vtp", dir / "ours.vtp", options);
  CHECK(file_text(dir / "ours.vtp") == file_text(dir / "vtk.vtp"));
}

TEST_CASE("make_polydata: the feature arrays' cached ranges are the ranges VTK computes from their values") {
  for (int n : {3, 40}) {
    CAPTURE(n);
    MeshData mesh = grid(n);
    for (int tags : {0, 1}) {  // with the tags of grid(), and with none (all zeros)
      CAPTURE(tags);
      if (tags == 0) mesh.creases.clear(), mesh.corners.clear(), mesh.line_vertices.clear(), mesh.line_offsets = {0};
      OutputLevel level{&mesh, 0, mesh.point_data, mesh.cell_data};
      const auto poly = io_detail::make_polydata(level);
      for (vtkDataSetAttributes* data : {static_cast<vtkDataSetAttributes*>(poly->GetCellData()),
                                         static_cast<vtkDataSetAttributes*>(poly->GetPointData())}) {
        for (const char* name : {"sharpness", "cell_kind", "corner_sharpness"}) {
          vtkDataArray* array = data->GetArray(name);
          if (!array) continue;
          CAPTURE(name);
          vtkNew<vtkDoubleArray> fresh;  // the same values, no cached range
          fresh->SetNumberOfTuples(array->GetNumberOfTuples());
          for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i) fresh->SetValue(i, array->GetComponent(i, 0));
          double cached[2], computed[2];
          array->GetRange(cached, 0);
          fresh->GetRange(computed, 0);
          CHECK(cached[0] == computed[0]);
          CHECK(cached[1] == computed[1]);
        }
      }
    }
  }
}
