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
#include <vtkXMLPolyDataWriter.h>

namespace subdiv::io_detail {

class FastXMLPolyDataWriter : public vtkXMLPolyDataWriter {
public:
  static FastXMLPolyDataWriter* New();

protected:
  FastXMLPolyDataWriter();
  void WriteInlinePiece(vtkIndent indent) override;
};

}  // namespace subdiv::io_detail
