#include "framework/io/vtk/vtk_inline_blocks.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>
#include <vtkDataCompressor.h>
#include <vtkSmartPointer.h>

#include "framework/io/vtk/base64_encode.h"
#include "framework/util/checked_file_stream.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the header and the values are written as they lie in memory");

namespace subdiv::io_detail {
namespace {

// Blocks between two progress reports: the pipeline drains at each, so that the calling
// thread can report (a few blocks of overlap lost per 64 MB).
constexpr std::size_t kSegmentBlocks = 64;

// A buffer kept across the blocks a slot carries (new memory per block would be new pages,
// each first touched and zeroed by the kernel).
template <typename T>
struct Buffer {
  std::unique_ptr<T[]> data;
  std::size_t capacity = 0;
  T* reserve(std::size_t size) {
    if (size > capacity) data.reset(new T[size]), capacity = size;  // uninitialised: written before read
    return data.get();
  }
};

// One piece of the run on its way through the pipeline: its bytes (compressed or in place),
// the bytes the pieces before it left over (fewer than a triplet), and its text.
struct Slot {
  vtkSmartPointer<vtkDataCompressor> compressor;
  Buffer<unsigned char> compressed;
  Buffer<char> text;
  std::size_t index = 0;
  const unsigned char* bytes = nullptr;
  std::size_t size = 0;
  unsigned char carry[3] = {};  // at most 2 used; 3 for the compiler's bounds check of at()
  std::size_t carry_size = 0;
  std::size_t text_size = 0;
  bool last = false, failed = false;

  // Byte i of carry + bytes.
  unsigned char at(std::size_t i) const { return i < carry_size ? carry[i] : bytes[i - carry_size]; }
};

// The run's pieces: the blocks, compressed; without compression the 8-byte length first, then
// the data (a block per piece, in place).
class Pieces {
public:
  Pieces(const InlineBytes& bytes, vtkDataCompressor* compressor)
      : in_(bytes), compressor_(compressor),
        blocks_((bytes.size + bytes.block_size - 1) / bytes.block_size),
        length_(std::uint64_t(bytes.size)) {}

  std::size_t count() const { return compressor_ ? blocks_ : blocks_ + 1; }
  std::size_t blocks() const { return blocks_; }

  void fill(Slot& slot) const {
    const std::size_t block = compressor_ ? slot.index : slot.index - 1;
    if (!compressor_ && slot.index == 0) {
      slot.bytes = reinterpret_cast<const unsigned char*>(&length_), slot.size = sizeof length_;
      return;
    }
    const unsigned char* in = in_.data + block * in_.block_size;
    const std::size_t size = std::min(in_.block_size, in_.size - block * in_.block_size);
    if (!compressor_) {
      slot.bytes = in, slot.size = size;
      return;
    }
    if (!slot.compressor) {
      slot.compressor.TakeReference(compressor_->NewInstance());  // VTK's class (vtk_block_compressor.h)
      slot.compressor->SetCompressionLevel(compressor_->GetCompressionLevel());
    }
    const std::size_t space = slot.compressor->GetMaximumCompressionSpace(size);
    unsigned char* out = slot.compressed.reserve(space);
    slot.size = slot.compressor->Compress(in, size, out, space);
    slot.bytes = out;
    slot.failed = slot.size == 0;
  }

private:
  InlineBytes in_;
  vtkDataCompressor* compressor_;
  std::size_t blocks_;
  std::uint64_t length_;
};

// Where a slot's text goes: the slot's own buffer (then written with the stream's write), or
// the file stream's room in place (CheckedFileBuffer::room: direct mode's chunks), which
// saves a copy of every character.
struct SlotText {  // one span, large enough for the whole text
  char* out;
  char* end;
  std::span<char> room() const { return {out, end}; }
  void commit(std::size_t n) { out += n; }
  void put(const char* text, std::size_t n) { out = std::copy(text, text + n, out); }
};

struct FileRoom {
  CheckedFileBuffer& file;
  std::span<char> room() const { return file.room(); }
  void commit(std::size_t n) const { file.commit(n); }
  void put(const char* text, std::size_t n) const { file.sputn(text, std::streamsize(n)); }
};

// Whole triplets of carry + bytes as text into `out`, in as many pieces as its room comes in
// (a quad that would straddle two pieces through put); the last piece also its padded tail.
template <class Out>
void encode(const Slot& slot, Out& out) {
  const std::size_t total = slot.carry_size + slot.size, triplets = total / 3;
  const unsigned char* in = slot.bytes;
  std::size_t rest = triplets;
  char quad[4];
  if (slot.carry_size > 0 && triplets > 0) {
    const unsigned char first[3] = {slot.at(0), slot.at(1), slot.at(2)};
    encode_base64_triplets(first, 1, quad);
    out.put(quad, 4);
    in += 3 - slot.carry_size, rest = triplets - 1;
  }
  while (rest > 0) {
    const std::span<char> room = out.room();
    const std::size_t n = std::min(rest, room.size() / 4);
    if (n == 0) {  // less than a quad of room: through put, on into the next
      encode_base64_triplets(in, 1, quad);
      out.put(quad, 4);
      in += 3, rest -= 1;
      continue;
    }
    encode_base64_triplets(in, n, room.data());
    out.commit(4 * n);
    in += 3 * n, rest -= n;
  }
  if (slot.last) {
    unsigned char tail[2] = {};
    for (std::size_t i = 3 * triplets; i < total; ++i) tail[i - 3 * triplets] = slot.at(i);
    out.put(quad, encode_base64_tail(tail, total - 3 * triplets, quad));
  }
}

// Into the slot's own buffer.
void encode(Slot& slot) {
  const std::size_t size = 4 * ((slot.carry_size + slot.size) / 3) + 4;
  char* const text = slot.text.reserve(size);
  SlotText out{text, text + size};
  encode(slot, out);
  slot.text_size = std::size_t(out.out - text);
}

// The base64 text of `size` bytes as a run of its own (padded).
void write_run(std::ostream& os, const unsigned char* data, std::size_t size) {
  std::vector<char> text(4 * (size / 3) + 4);
  encode_base64_triplets(data, size / 3, text.data());
  const std::size_t tail = encode_base64_tail(data + 3 * (size / 3), size % 3, text.data() + 4 * (size / 3));
  os.write(text.data(), std::streamsize(4 * (size / 3) + tail));
}

// The pieces' run: compressed and encoded in parallel, the leftover bytes passed on and the
// text written in order. Returns false if a piece failed to compress. `sizes`, if not null,
// receives each piece's size.
bool write_pieces(std::ostream& os, const Pieces& pieces, std::uint64_t* sizes,
                  const std::function<void(double)>& progress) {
  // The file's own buffer: each slot's text encoded straight into it, in order (the last
  // stage), which saves copying every character once more (6 % of the write's CPU time
  // went to that copy); the encoding is then serial, but it is a fraction of the
  // compression's work, which keeps the other cores busy meanwhile. Other streams get text
  // encoded in parallel into the slots, then written.
  auto* const file = dynamic_cast<CheckedFileBuffer*>(os.rdbuf());
  const std::size_t tokens = std::size_t(2 * tbb::this_task_arena::max_concurrency() + 2);
  std::vector<Slot> slots(tokens);
  unsigned char carry[2] = {};
  std::size_t carry_size = 0;
  bool failed = false;
  const std::size_t count = pieces.count();
  for (std::size_t first = 0; first < count && !failed; first += kSegmentBlocks) {
    const std::size_t end = std::min(count, first + kSegmentBlocks);
    std::size_t next = first;
    tbb::parallel_pipeline(
        tokens,
        tbb::make_filter<void, Slot*>(tbb::filter_mode::serial_in_order,
                                      [&](tbb::flow_control& control) -> Slot* {
                                        if (next == end) {
                                          control.stop();
                                          return nullptr;
                                        }
                                        Slot* slot = &slots[next % tokens];  // at most `tokens` in flight
                                        slot->index = next++;
                                        slot->last = slot->index + 1 == count;
                                        return slot;
                                      }) &
            tbb::make_filter<Slot*, Slot*>(tbb::filter_mode::parallel,
                                           [&](Slot* slot) {
                                             pieces.fill(*slot);
                                             return slot;
                                           }) &
            tbb::make_filter<Slot*, Slot*>(tbb::filter_mode::serial_in_order,
                                           [&](Slot* slot) {
                                             std::copy(carry, carry + carry_size, slot->carry);
                                             slot->carry_size = carry_size;
                                             const std::size_t total = carry_size + slot->size;
                                             carry_size = slot->last ? 0 : total % 3;
                                             for (std::size_t i = 0; i < carry_size; ++i)
                                               carry[i] = slot->at(total - carry_size + i);
                                             if (sizes) sizes[slot->index] = slot->size;
                                             return slot;
                                           }) &
            tbb::make_filter<Slot*, Slot*>(tbb::filter_mode::parallel,
                                           [&](Slot* slot) {
                                             if (!file && !slot->failed) encode(*slot);
                                             return slot;
                                           }) &
            tbb::make_filter<Slot*, void>(tbb::filter_mode::serial_in_order, [&](Slot* slot) {
              failed = failed || slot->failed;
              if (failed) return;
              if (!file) {
                os.write(slot->text.data.get(), std::streamsize(slot->text_size));
                return;
              }
              FileRoom out{*file};
              encode(*slot, out);
            }));
    if (progress) progress(double(end) / double(count));
  }
  return !failed;
}

}  // namespace

bool write_inline_base64(std::ostream& os, const InlineBytes& bytes, vtkDataCompressor* compressor,
                         const std::function<void(double)>& progress) {
  const Pieces pieces(bytes, compressor);
  if (!compressor) return write_pieces(os, pieces, nullptr, progress);
  // vtkXMLWriter's compression header: blocks, block size, last block's size, then each
  // block's compressed size, known once they are compressed: a placeholder of its length first.
  std::vector<std::uint64_t> header(3 + pieces.blocks(), 0);
  const auto* header_bytes = reinterpret_cast<const unsigned char*>(header.data());
  const std::size_t header_size = header.size() * sizeof(std::uint64_t);
  const std::streampos at = os.tellp();
  write_run(os, header_bytes, header_size);
  header[0] = pieces.blocks(), header[1] = bytes.block_size, header[2] = bytes.size % bytes.block_size;
  const bool compressed = write_pieces(os, pieces, header.data() + 3, progress);
  const std::streampos end = os.tellp();
  os.seekp(at);
  write_run(os, header_bytes, header_size);
  os.seekp(end);
  return compressed;
}

}  // namespace subdiv::io_detail
