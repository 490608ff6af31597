#include "framework/io/vtk/vtk_block_compressor.h"

#include <algorithm>
#include <cstring>
#include <map>

#include <tbb/parallel_for.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkZLibDataCompressor.h>

namespace subdiv::io_detail {
namespace {

// `Base` is VTK's compressor (vtkZLibDataCompressor, ...). No vtkTypeMacro: GetClassName()
// stays Base's, which the writer puts into the file for the reader to pick its decompressor.
template <class Base>
class ParallelBlocks final : public Base {
public:
  static ParallelBlocks* create(std::size_t block_size, std::vector<ArrayBytes> arrays, BlockCounts* counts) {
    auto* compressor = new ParallelBlocks;
    compressor->InitializeObjectBase();
    compressor->block_size_ = block_size;
    compressor->arrays_ = std::move(arrays);
    for (std::size_t i = 0; i < compressor->arrays_.size(); ++i)  // arrays sharing memory: the first keeps it
      compressor->by_start_.emplace(compressor->arrays_[i].data, i);
    compressor->counts_ = counts;
    return compressor;
  }

protected:
  std::size_t CompressBuffer(unsigned char const* in, std::size_t size, unsigned char* out,
                             std::size_t space) override {
    if (const std::vector<unsigned char>* block = precompressed(in, size); block && block->size() <= space) {
      std::memcpy(out, block->data(), block->size());
      if (counts_) ++counts_->parallel;
      return block->size();
    }
    if (counts_) ++counts_->serial;
    return Base::CompressBuffer(in, size, out, space);
  }

private:
  // The writer's block length for values of `word` bytes (vtkXMLWriter: BlockSize / word
  // values per block).
  std::size_t block_bytes(std::size_t word) const { return std::max<std::size_t>(1, block_size_ / word) * word; }

  // The compressed block that starts at `in`, if it belongs to a known array; compresses the
  // next run of the array's blocks first when `in` is the array's start or past the run done.
  const std::vector<unsigned char>* precompressed(unsigned char const* in, std::size_t size) {
    if (const auto it = by_start_.find(in); it != by_start_.end() && it->second != current_) {
      const ArrayBytes& a = arrays_[it->second];
      if (size != std::min(a.size, block_bytes(a.word))) return nullptr;
      current_ = it->second;
      compress_run(a, 0);
    }
    if (current_ == kNone) return nullptr;
    const ArrayBytes& a = arrays_[current_];
    if (in < a.data || in >= a.data + a.size) return nullptr;
    const std::size_t offset = std::size_t(in - a.data), length = block_bytes(a.word);
    if (offset % length != 0 || size != std::min(length, a.size - offset)) return nullptr;
    const std::size_t k = offset / length;
    if (k < first_ || k >= first_ + blocks_.size()) compress_run(a, k);
    const std::vector<unsigned char>& block = blocks_[k - first_];
    return block.empty() ? nullptr : &block;  // empty: that block failed; VTK's own call reports it
  }

  // Blocks `first` on of `a`, kRunBlocks of them, each by a compressor of this one's kind and
  // level: the same bytes as one compressor block after block. A run at a time bounds the
  // memory the compressed blocks take to kRunBlocks blocks.
  void compress_run(const ArrayBytes& a, std::size_t first) {
    const std::size_t length = block_bytes(a.word), count = (a.size + length - 1) / length;
    first_ = first;
    // The buffers are kept from run to run: fresh ones would be fresh pages, each first
    // touched (and zeroed by the kernel) again.
    blocks_.resize(std::min(kRunBlocks, count - first));
    const int level = this->GetCompressionLevel();
    const tbb::blocked_range<std::size_t> all(0, blocks_.size());
    tbb::parallel_for(all, [&](const tbb::blocked_range<std::size_t>& r) {
      vtkSmartPointer<Base> compressor = vtkSmartPointer<Base>::New();
      compressor->SetCompressionLevel(level);
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        const std::size_t k = first + i, size = std::min(length, a.size - k * length);
        std::vector<unsigned char>& block = blocks_[i];
        block.resize(compressor->GetMaximumCompressionSpace(size));
        block.resize(compressor->Compress(a.data + k * length, size, block.data(), block.size()));
      }
    });
  }

  static constexpr std::size_t kNone = std::size_t(-1);
  static constexpr std::size_t kRunBlocks = 64;
  std::size_t block_size_ = 0;
  std::vector<ArrayBytes> arrays_;
  std::map<const unsigned char*, std::size_t> by_start_;
  std::size_t current_ = kNone;  // the array blocks_ belongs to
  std::size_t first_ = 0;        // the block of that array blocks_ starts with
  std::vector<std::vector<unsigned char>> blocks_;
  BlockCounts* counts_ = nullptr;
};

template <class Base>
vtkSmartPointer<vtkDataCompressor> make(int level, std::size_t block_size, std::vector<ArrayBytes> arrays,
                                        BlockCounts* counts) {
  vtkSmartPointer<ParallelBlocks<Base>> compressor;
  compressor.TakeReference(ParallelBlocks<Base>::create(block_size, std::move(arrays), counts));
  compressor->SetCompressionLevel(level);
  return compressor;
}

void add(std::vector<ArrayBytes>& out, vtkDataArray* array) {
  if (!array || !array->HasStandardMemoryLayout() || array->GetNumberOfValues() == 0) return;
  const std::size_t word = std::size_t(array->GetDataTypeSize());
  const auto* data = static_cast<const unsigned char*>(array->GetVoidPointer(0));
  out.push_back({data, std::size_t(array->GetNumberOfValues()) * word, word});
}

void add(std::vector<ArrayBytes>& out, vtkFieldData* data) {
  if (!data) return;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) add(out, data->GetArray(i));
}

void add(std::vector<ArrayBytes>& out, vtkCellArray* cells) {
  if (!cells || cells->GetNumberOfCells() == 0) return;
  add(out, cells->GetConnectivityArray());
  // The file's offsets leave out the cell array's leading 0: should the writer pass the
  // offsets in place, its blocks start one value in.
  vtkDataArray* offsets = cells->GetOffsetsArray();
  add(out, offsets);
  if (!out.empty() && offsets && out.back().size > out.back().word) {
    ArrayBytes tail = out.back();
    tail.data += tail.word, tail.size -= tail.word;
    out.push_back(tail);
  }
}

}  // namespace

std::vector<ArrayBytes> contiguous_arrays(vtkPolyData& data) {
  std::vector<ArrayBytes> out;
  if (data.GetPoints()) add(out, data.GetPoints()->GetData());
  add(out, data.GetPointData());
  add(out, data.GetCellData());
  add(out, data.GetFieldData());
  for (vtkCellArray* cells : {data.GetVerts(), data.GetLines(), data.GetStrips(), data.GetPolys()}) add(out, cells);
  return out;
}

vtkSmartPointer<vtkDataCompressor> make_block_compressor(VtkCompressor type, int level, std::size_t block_size,
                                                         std::vector<ArrayBytes> arrays, BlockCounts* counts) {
  switch (type) {
    case VtkCompressor::None: return nullptr;
    case VtkCompressor::ZLib: return make<vtkZLibDataCompressor>(level, block_size, std::move(arrays), counts);
    case VtkCompressor::LZ4: return make<vtkLZ4DataCompressor>(level, block_size, std::move(arrays), counts);
    case VtkCompressor::LZMA: return make<vtkLZMADataCompressor>(level, block_size, std::move(arrays), counts);
  }
  return nullptr;
}

}  // namespace subdiv::io_detail
