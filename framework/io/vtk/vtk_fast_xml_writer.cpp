#include "framework/io/vtk/vtk_fast_xml_writer.h"

#include <cstring>
#include <memory>
#include <string>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkOutputStream.h>
#include <vtkPolyData.h>

#include "framework/io/vtk/base64_encode.h"
#include "framework/io/vtk/vtk_array_ranges.h"
#include "framework/io/vtk/vtk_inline_blocks.h"

namespace subdiv::io_detail {
namespace {

// Base64 as vtkBase64OutputStream writes it (each StartWriting..EndWriting run padded with
// '=' on its own), a whole Write at a time.
class Base64Stream : public vtkOutputStream {
public:
  static Base64Stream* create() {
    auto* stream = new Base64Stream;
    stream->InitializeObjectBase();
    return stream;
  }

  int StartWriting() override {
    pending_size_ = 0;
    return vtkOutputStream::StartWriting();
  }

  int Write(void const* data, size_t length) override {
    const auto* in = static_cast<const unsigned char*>(data);
    size_t start = 0;
    // Complete the triplet a previous Write left open.
    while (pending_size_ > 0 && pending_size_ < 3 && length > 0) pending_[pending_size_++] = *in++, --length;
    const size_t triplets = length / 3;
    char* out = reserve(4 + 4 * triplets);
    if (pending_size_ == 3) {
      encode_base64_triplets(pending_, 1, out);
      pending_size_ = 0;
      start = 4;
    }
    out += start;
    // Large writes (compressed blocks of up to a megabyte) in parallel pieces, each its own
    // whole triplets: the same text for any thread count.
    constexpr size_t kPiece = 1 << 16;  // triplets
    tbb::parallel_for(tbb::blocked_range<size_t>(0, triplets, kPiece), [&](const tbb::blocked_range<size_t>& r) {
      encode_base64_triplets(in + 3 * r.begin(), r.size(), out + 4 * r.begin());
    });
    in += 3 * triplets, length -= 3 * triplets;
    while (length > 0) pending_[pending_size_++] = *in++, --length;
    return put(start + 4 * triplets);
  }

  int EndWriting() override {
    const size_t size = encode_base64_tail(pending_, pending_size_, reserve(4));
    pending_size_ = 0;
    return put(size) && vtkOutputStream::EndWriting();
  }

private:
  // The text buffer, at least `size` characters, kept from write to write (a std::string
  // resized each time would write zeros over it first).
  char* reserve(size_t size) {
    if (size > capacity_) text_.reset(new char[size]), capacity_ = size;
    return text_.get();
  }

  int put(size_t size) {
    if (size == 0) return 1;
    return this->Stream->write(text_.get(), std::streamsize(size)) ? 1 : 0;
  }

  unsigned char pending_[3] = {};
  unsigned pending_size_ = 0;
  std::unique_ptr<char[]> text_;
  size_t capacity_ = 0;
};

}  // namespace

FastCellTypesPolyData* FastCellTypesPolyData::New() {
  auto* poly = new FastCellTypesPolyData;
  poly->InitializeObjectBase();
  return poly;
}

void FastCellTypesPolyData::GetCellTypes(vtkCellTypes* types) {
  types->Reset();
  // vtkPolyData's cell order (verts, lines, polys, strips) and its type for each cell size.
  const auto vertex = [](vtkIdType n) { return n == 1 ? VTK_VERTEX : VTK_POLY_VERTEX; };
  const auto line = [](vtkIdType n) { return n == 2 ? VTK_LINE : VTK_POLY_LINE; };
  const auto polygon = [](vtkIdType n) { return n == 3 ? VTK_TRIANGLE : n == 4 ? VTK_QUAD : VTK_POLYGON; };
  const auto strip = [](vtkIdType) { return VTK_TRIANGLE_STRIP; };
  const auto add = [&](vtkCellArray* cells, auto type_of) {
    if (!cells) return;
    vtkIdType last_size = -1;
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c) {
      const vtkIdType size = cells->GetCellSize(c);
      if (size == last_size) continue;  // most cells: the size of the one before
      last_size = size;
      const auto type = static_cast<unsigned char>(size == 0 ? VTK_EMPTY_CELL : type_of(size));
      if (!types->IsType(type)) types->InsertNextType(type);
    }
  };
  add(this->GetVerts(), vertex);
  add(this->GetLines(), line);
  add(this->GetPolys(), polygon);
  add(this->GetStrips(), strip);
}

FastXMLPolyDataWriter* FastXMLPolyDataWriter::New() {
  auto* writer = new FastXMLPolyDataWriter;
  writer->InitializeObjectBase();
  return writer;
}

FastXMLPolyDataWriter::FastXMLPolyDataWriter() {
  Base64Stream* stream = Base64Stream::create();
  this->SetDataStream(stream);  // registers it
  stream->Delete();
}

// As vtkXMLPolyDataWriter::WriteInlinePiece (points and data, then the four cell kinds),
// without its progress reports, and with the cell arrays' ranges cached before they are written.
void FastXMLPolyDataWriter::WriteInlinePiece(vtkIndent indent) {
  vtkXMLUnstructuredDataWriter::WriteInlinePiece(indent);
  vtkPolyData* input = this->GetInput();
  const std::pair<const char*, vtkCellArray*> kinds[] = {{"Verts", input->GetVerts()},
                                                         {"Lines", input->GetLines()},
                                                         {"Strips", input->GetStrips()},
                                                         {"Polys", input->GetPolys()}};
  for (const auto& [name, cells] : kinds) {
    if (this->GetErrorCode() == vtkErrorCode::OutOfDiskSpaceError) return;
    if (cells) this->ConvertCells(cells);
    this->ConvertFaces(nullptr, nullptr);
    cache_array_range(this->CellPoints, cells ? cells->GetConnectivityArray() : nullptr);
    cache_array_range(this->CellOffsets);
    this->WriteCellsInlineWorker(name, nullptr, indent);
  }
}

// What vtk_inline_blocks.h writes as VTK would: inline binary data of a data array in one
// piece of memory, written as it lies (no 64-bit ids written as 32, no byte swap), with
// 64-bit headers and blocks that start where VTK's do.
bool FastXMLPolyDataWriter::pipelined(vtkAbstractArray* a) {
  auto* array = vtkDataArray::SafeDownCast(a);
  if (!array || this->GetDataMode() != vtkXMLWriter::Binary || !array->HasStandardMemoryLayout() ||
      array->GetNumberOfValues() == 0 || this->GetHeaderType() != vtkXMLWriter::UInt64)
    return false;
  const int type = array->GetDataType();
  const size_t word = this->GetWordTypeSize(type);
  return type != VTK_STRING && this->GetOutputWordTypeSize(type) == word &&
         (word == 1 || this->GetByteOrder() == vtkXMLWriter::LittleEndian) && this->GetBlockSize() > 0 &&
         this->GetBlockSize() % word == 0;
}

// As vtkXMLWriter::WriteInlineData: the indent, the data, a line break.
void FastXMLPolyDataWriter::WriteInlineData(vtkAbstractArray* a, vtkIndent indent) {
  if (!pipelined(a)) return vtkXMLPolyDataWriter::WriteInlineData(a, indent);
  auto* array = vtkDataArray::SafeDownCast(a);
  std::ostream& os = *this->Stream;
  os << indent;
  const InlineBytes bytes{static_cast<const unsigned char*>(array->GetVoidPointer(0)),
                          size_t(array->GetNumberOfValues()) * this->GetWordTypeSize(array->GetDataType()),
                          size_t(this->GetBlockSize())};
  const bool compressed = write_inline_base64(os, bytes, this->Compressor,
                                              [this](double done) { this->SetProgressPartial(float(done)); });
  os << "\n";
  if (!compressed) {
    vtkErrorMacro("cannot compress array " << (a->GetName() ? a->GetName() : "(unnamed)"));
    this->SetErrorCode(vtkErrorCode::UnknownError);
  }
  if (os.fail()) this->SetErrorCode(vtkErrorCode::GetLastSystemError());
}

}  // namespace subdiv::io_detail
