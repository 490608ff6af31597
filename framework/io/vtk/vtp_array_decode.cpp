#include "framework/io/vtk/vtp_array_decode.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataCompressor.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkZLibDataCompressor.h>

namespace subdiv::io_detail {
namespace {

constexpr std::uint32_t kBad = 0x1000000;  // above any 24-bit group: marks a character outside base64

constexpr std::array<std::uint32_t, 256> base64_table() {
  std::array<std::uint32_t, 256> t{};
  for (auto& v : t) v = kBad;
  const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (std::uint32_t i = 0; i < 64; ++i) t[static_cast<unsigned char>(alphabet[i])] = i;
  return t;
}
constexpr std::array<std::uint32_t, 256> kBase64 = base64_table();

std::uint32_t group(const char* c) {
  const auto v = [&](int i) { return kBase64[static_cast<unsigned char>(c[i])]; };
  return (v(0) << 18) | (v(1) << 12) | (v(2) << 6) | v(3) | ((v(0) | v(1) | v(2) | v(3)) & kBad);
}

// `groups` whole groups of four characters into 3 * groups bytes.
bool decode_groups(const char* text, std::size_t groups, unsigned char* out) {
  std::uint32_t bad = 0;
  for (std::size_t g = 0; g < groups; ++g, text += 4, out += 3) {
    const std::uint32_t bits = group(text);
    bad |= bits;
    out[0] = static_cast<unsigned char>(bits >> 16);
    out[1] = static_cast<unsigned char>(bits >> 8);
    out[2] = static_cast<unsigned char>(bits);
  }
  return (bad & kBad) == 0;
}

// Little-endian words of 4 or 8 bytes.
std::uint64_t word_at(const unsigned char* p, std::size_t size) {
  std::uint64_t v = 0;
  for (std::size_t i = size; i-- > 0;) v = (v << 8) | p[i];
  return v;
}

// Reads a run of data: raw bytes at the file's position, or a base64 run.
class Source {
public:
  Source(std::string_view file, const VtpArray& a) : file_(file), pos_(a.at), end_(a.end), base64_(a.base64) {}

  std::size_t available() const { return base64_ ? (end_ - pos_) / 4 * 3 : end_ - pos_; }

  // A run of `bytes` bytes (a base64 run: its own padding); points into the file when raw.
  std::optional<DecodedBytes> run(std::size_t bytes) {
    DecodedBytes out;
    out.size = bytes;
    if (!base64_) {
      if (bytes > end_ - pos_) return std::nullopt;
      out.bytes = reinterpret_cast<const unsigned char*>(file_.data() + pos_);
      pos_ += bytes;
      return out;
    }
    const std::size_t chars = (bytes + 2) / 3 * 4;
    if (chars > end_ - pos_) return std::nullopt;
    out.owner.reset(new unsigned char[bytes + 2]);
    if (!decode_base64_run(file_.data() + pos_, bytes, out.owner.get())) return std::nullopt;
    out.bytes = out.owner.get();
    pos_ += chars;
    return out;
  }

  // Inline text may be followed by blanks only, up to its element's end.
  bool ends_cleanly(bool inline_text) const {
    if (!inline_text) return true;
    for (std::size_t p = pos_; p < end_; ++p)
      if (file_[p] != ' ' && file_[p] != '\t' && file_[p] != '\n' && file_[p] != '\r') return false;
    return true;
  }

  bool raw() const { return !base64_; }

private:
  std::string_view file_;
  std::size_t pos_, end_;
  bool base64_;
};

vtkSmartPointer<vtkDataCompressor> make_decompressor(VtpCompressor type) {
  vtkSmartPointer<vtkDataCompressor> c;
  if (type == VtpCompressor::ZLib) c = vtkSmartPointer<vtkZLibDataCompressor>::New();
  if (type == VtpCompressor::LZ4) c = vtkSmartPointer<vtkLZ4DataCompressor>::New();
  if (type == VtpCompressor::LZMA) c = vtkSmartPointer<vtkLZMADataCompressor>::New();
  // A damaged block is a declined file, not a message on the terminal: an observer takes
  // the compressor's error event instead of VTK's output window.
  vtkNew<vtkCallbackCommand> quiet;
  quiet->SetCallback([](vtkObject*, unsigned long, void*, void*) {});
  c->AddObserver(vtkCommand::ErrorEvent, quiet);
  c->AddObserver(vtkCommand::WarningEvent, quiet);
  return c;
}

std::optional<DecodedBytes> uncompressed(Source& source, std::size_t expected, std::size_t header_bytes) {
  if (source.raw()) {
    const auto header = source.run(header_bytes);
    if (!header || word_at(header->bytes, header_bytes) != expected) return std::nullopt;
    return source.run(expected);
  }
  if (expected > source.available()) return std::nullopt;
  auto run = source.run(header_bytes + expected);
  if (!run || word_at(run->bytes, header_bytes) != expected) return std::nullopt;
  run->bytes += header_bytes;
  run->size = expected;
  return run;
}

std::optional<DecodedBytes> compressed(Source& source, std::size_t expected, std::size_t w, VtpCompressor type) {
  // The first three words (no padding: 3w bytes are whole base64 groups), then the block sizes.
  Source peek = source;
  const auto first = peek.run(3 * w);
  if (!first) return std::nullopt;
  const std::uint64_t blocks = word_at(first->bytes, w), block = word_at(first->bytes + w, w),
                      last = word_at(first->bytes + 2 * w, w);
  if (blocks == 0) {
    if (expected != 0 || last != 0 || double(block) > 64.0 * (1 << 20)) return std::nullopt;
    const auto header = source.run(3 * w);
    return header ? std::optional<DecodedBytes>(DecodedBytes{}) : std::nullopt;
  }
  if (block == 0 || last > block || blocks != (expected + block - 1) / block) return std::nullopt;
  const std::uint64_t tail = expected - (blocks - 1) * block;  // the last block's true size
  if (last != (tail == block ? 0 : tail)) return std::nullopt;
  if (blocks > source.available() / w) return std::nullopt;
  const auto header = source.run((3 + blocks) * w);
  if (!header) return std::nullopt;
  std::vector<std::size_t> starts(blocks + 1, 0);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t size = word_at(header->bytes + (3 + b) * w, w);
    if (size > source.available()) return std::nullopt;
    starts[b + 1] = starts[b] + size;
    if (starts[b + 1] > source.available()) return std::nullopt;
  }
  // As much as the compressor can expand its input (vtk_xml_blocks.cpp's bounds): a header
  // claiming more is damaged, and nothing is allocated for it.
  const double limit = type == VtpCompressor::ZLib ? 1100 : type == VtpCompressor::LZ4 ? 300 : 1e5;
  const double possible = double(starts[blocks]) * limit + 65536;
  if (double(expected) > possible || double(block) > std::max(possible, 64.0 * (1 << 20))) return std::nullopt;
  const auto data = source.run(starts[blocks]);
  if (!data) return std::nullopt;
  DecodedBytes out;
  out.owner.reset(new unsigned char[expected]);
  out.bytes = out.owner.get();
  out.size = expected;
  std::atomic<bool> ok{true};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks), [&](const tbb::blocked_range<std::size_t>& r) {
    const auto decompressor = make_decompressor(type);
    for (std::size_t b = r.begin(); b != r.end() && ok.load(std::memory_order_relaxed); ++b) {
      const std::size_t size = b + 1 == blocks ? std::size_t(tail) : std::size_t(block);
      if (decompressor->Uncompress(data->bytes + starts[b], starts[b + 1] - starts[b], out.owner.get() + b * block,
                                   size) != size)
        ok = false;
    }
  });
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace

bool decode_base64_run(const char* text, std::size_t bytes, unsigned char* out) {
  const std::size_t whole = bytes / 3;
  constexpr std::size_t kPiece = 1 << 16;  // groups per task
  std::atomic<bool> ok{true};
  if (whole < kPiece) {
    ok = decode_groups(text, whole, out);
  } else {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, whole, kPiece), [&](const tbb::blocked_range<std::size_t>& r) {
      if (!decode_groups(text + 4 * r.begin(), r.size(), out + 3 * r.begin())) ok = false;
    });
  }
  if (!ok) return false;
  const std::size_t rest = bytes - 3 * whole;
  if (rest == 0) return true;
  const char* g = text + 4 * whole;
  // "xx==" holds one byte, "xxx=" two.
  const char padded[4] = {g[0], g[1], rest == 2 ? g[2] : 'A', 'A'};
  if (g[3] != '=' || (rest == 1 && g[2] != '=')) return false;
  unsigned char tail[3];
  if (!decode_groups(padded, 1, tail)) return false;
  std::memcpy(out + 3 * whole, tail, rest);
  return true;
}

std::optional<DecodedBytes> decode_vtp_array(std::string_view file, const VtpArray& array, std::size_t expected,
                                             std::size_t header_bytes, VtpCompressor compressor) {
  if (array.at > array.end || array.end > file.size()) return std::nullopt;
  Source source(file, array);
  auto out = compressor == VtpCompressor::None ? uncompressed(source, expected, header_bytes)
                                               : compressed(source, expected, header_bytes, compressor);
  if (!out || !source.ends_cleanly(array.inline_text)) return std::nullopt;
  return out;
}

}  // namespace subdiv::io_detail
