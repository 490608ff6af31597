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
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkOutputStream.h>
#include <vtkPolyData.h>

#include "framework/io/vtk/base64_encode.h"
#include "framework/io/vtk/vtk_array_ranges.h"

namespace subdiv::io_detail {
namespace {

// For the padded tail of a run (the whole triplets go through base64_encode.h).
constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

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
    char* out = reserve(4);
    size_t size = 0;
    if (pending_size_ == 1) {
      out[0] = kAlphabet[pending_[0] >> 2];
      out[1] = kAlphabet[(pending_[0] & 0x03) << 4];
      out[2] = out[3] = '=';
      size = 4;
    } else if (pending_size_ == 2) {
      out[0] = kAlphabet[pending_[0] >> 2];
      out[1] = kAlphabet[((pending_[0] & 0x03) << 4) | (pending_[1] >> 4)];
      out[2] = kAlphabet[(pending_[1] & 0x0F) << 2];
      out[3] = '=';
      size = 4;
    }
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
    cache_array_range(this->CellPoints);
    cache_array_range(this->CellOffsets);
    this->WriteCellsInlineWorker(name, nullptr, indent);
  }
}

}  // namespace subdiv::io_detail
