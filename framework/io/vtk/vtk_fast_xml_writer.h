#pragma once
// VTK's XML polydata writer with a faster base64 encoder. Internal to io/.
//
// Inline binary data (the mode write_vtp uses, which every ParaView reads: see
// vtk_polydata.cpp) goes through vtkBase64OutputStream, which encodes three bytes at a time
// and hands each four characters to the ostream on their own: about 100 MB/s, which made
// writing a 16M-face level take 16 s even without compression. vtkXMLWriter lets a subclass
// choose its data stream (the protected SetDataStream); this writer gives it one that
// encodes whole writes into a buffer and passes that on at once. The text is standard
// base64 with VTK's padding, the same characters VTK's encoder writes.
//
// It also writes the cells as vtkXMLPolyDataWriter does, but with the value ranges of the
// connectivity and offsets arrays it makes (ConvertCells) computed in parallel
// (vtk_array_ranges.h): VTK's own sequential range took seconds on a 16M-face level.
//
// And it writes each array's inline data itself (vtk_inline_blocks.h): VTK's block loop
// compressed, encoded and wrote one block at a time, so the cores and the write() calls
// took turns; the bytes are the same.
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

namespace subdiv::io_detail {

// Polydata whose GetCellTypes reads the cell sizes instead of building the cell map.
// vtkXMLUnstructuredDataWriter::ProcessRequest asks its input for GetCellTypes, which for
// vtkPolyData goes through vtkDataSet's cell by cell GetCellType and so builds vtkPolyData's
// cell map: seconds and hundreds of megabytes on a 16M-face level, for a list of a few types.
// The types are those vtkPolyData gives, in the same order.
class FastCellTypesPolyData : public vtkPolyData {
public:
  static FastCellTypesPolyData* New();
  void GetCellTypes(vtkCellTypes* types) override;
};

class FastXMLPolyDataWriter : public vtkXMLPolyDataWriter {
public:
  static FastXMLPolyDataWriter* New();
  // Writes into `stream` instead of a file VTK opens itself (vtkXMLWriter's protected
  // Stream): write_polydata_file hands it a stream that never fails (checked_file_stream.h),
  // because VTK's writer crashes when its own stream fails on a full disk.
  void WriteToStream(std::ostream* stream) { this->Stream = stream; }

protected:
  FastXMLPolyDataWriter();
  void WriteInlinePiece(vtkIndent indent) override;
  // An array's inline binary data through vtk_inline_blocks.h (compressed, encoded and
  // written in a pipeline on every core), VTK's own for what that does not cover.
  void WriteInlineData(vtkAbstractArray* a, vtkIndent indent) override;

private:
  bool pipelined(vtkAbstractArray* a);
};

}  // namespace subdiv::io_detail
