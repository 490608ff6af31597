// The pipelined inline data of FastXMLPolyDataWriter (framework/io/vtk/vtk_inline_blocks.h)
// against VTK's own vtkXMLPolyDataWriter: with blocks of a few bytes, arrays of every length
// around the block size and the base64 triplet (the bytes a block leaves over for the next,
// the last block's padding, a block shorter than the leftover) give the same file, byte for
// byte, for every compressor and thread count.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <tbb/global_control.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

#include "framework/io/vtk/vtk_fast_xml_writer.h"
#include "io_test_support.h"

namespace fs = std::filesystem;

namespace {

// n points on a curve, a vertex cell on each, a byte and an int array per point: arrays of
// 24n, 8n, n and 4n bytes.
vtkSmartPointer<vtkPolyData> polydata(int n) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkUnsignedCharArray> bytes;
  vtkNew<vtkIntArray> ints;
  bytes->SetName("bytes");
  ints->SetName("ints");
  vtkNew<vtkCellArray> verts;
  for (int i = 0; i < n; ++i) {
    points->InsertNextPoint(i * 0.37, i * i * 1e-3, (i % 7) * 0.5);  // some repeats for the compressors
    bytes->InsertNextValue(static_cast<unsigned char>((i * 37) % 251));
    ints->InsertNextValue(i % 5 == 0 ? -i : i * 1000003);
    const vtkIdType id = i;
    verts->InsertNextCell(1, &id);
  }
  poly->SetPoints(points);
  poly->SetVerts(verts);
  poly->GetPointData()->AddArray(bytes);
  poly->GetPointData()->AddArray(ints);
  return poly;
}

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write(vtkXMLPolyDataWriter& writer, vtkPolyData& poly, const fs::path& file, int compressor, int block_size,
           bool header64) {
  writer.SetInputData(&poly);
  writer.SetFileName(file.c_str());
  writer.SetDataModeToBinary();
  writer.SetCompressorType(compressor);
  writer.SetCompressionLevel(1);
  writer.SetBlockSize(block_size);
  if (header64)
    writer.SetHeaderTypeToUInt64();
  else
    writer.SetHeaderTypeToUInt32();  // not pipelined: VTK's own loop
  REQUIRE(writer.Write() == 1);
}

}  // namespace

TEST_CASE("FastXMLPolyDataWriter's pipelined inline data is VTK's, byte for byte") {
  const subdiv::test::TempDir scratch;
  const fs::path& dir = scratch.path();
  const int compressors[] = {vtkXMLWriter::NONE, vtkXMLWriter::LZ4, vtkXMLWriter::ZLIB};
  for (int n : {1, 2, 3, 4, 5, 7, 8, 9, 15, 16, 17, 100, 1001}) {
    const auto poly = polydata(n);
    for (int compressor : compressors)
      for (int block_size : {8, 16, 24, 4096})
        for (bool header64 : {true, false}) {
          CAPTURE(n);
          CAPTURE(compressor);
          CAPTURE(block_size);
          CAPTURE(header64);
          vtkNew<vtkXMLPolyDataWriter> vtk;
          write(*vtk, *poly, dir / "vtk.vtp", compressor, block_size, header64);
          const std::string expected = file_text(dir / "vtk.vtp");
          for (int threads : {1, 2, 4}) {
            CAPTURE(threads);
            tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
            vtkNew<subdiv::io_detail::FastXMLPolyDataWriter> ours;
            write(*ours, *poly, dir / "ours.vtp", compressor, block_size, header64);
            CHECK(file_text(dir / "ours.vtp") == expected);
          }
        }
  }
}
