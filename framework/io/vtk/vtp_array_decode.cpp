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

// Two characters at a time: their 12 bits, or kPairBad (128 KB, built once).
constexpr std::uint16_t kPairBad = 0xF000;
const std::uint16_t* pair_table() {
  static const std::vector<std::uint16_t> table = [] {
    std::vector<std::uint16_t> t(65536);
    for (std::uint32_t a = 0; a < 256; ++a)
      for (std::uint32_t b = 0; b < 256; ++b) {
        const bool bad = (kBase64[a] | kBase64[b]) & kBad;
        // The first character is the low byte of the index.
        t[a | (b << 8)] = bad ? kPairBad : std::uint16_t((kBase64[a] << 6) | kBase64[b]);
      }
    return t;
  }();
  return table.data();
}

// `groups` whole groups of four characters into 3 * groups bytes.
bool decode_groups(const char* text, std::size_t groups, unsigned char* out) {
  const std::uint16_t* pairs = pair_table();
  std::uint32_t bad = 0;
  for (std::size_t g = 0; g < groups; ++g, text += 4, out += 3) {
    const auto byte = [&](int i) { return std::uint32_t(static_cast<unsigned char>(text[i])); };
    const std::uint32_t hi = pairs[byte(0) | (byte(1) << 8)], lo = pairs[byte(2) | (byte(3) << 8)];
    bad |= hi | lo;
    const std::uint32_t bits = (hi << 12) | lo;
    out[0] = static_cast<unsigned char>(bits >> 16);
    out[1] = static_cast<unsigned char>(bits >> 8);
    out[2] = static_cast<unsigned char>(bits);
  }
  return (bad & kPairBad) == 0;
}

// Bytes [from, to) of a base64 run of `total` bytes at `run` (its last group padded).
bool decode_base64_range(const char* run, std::size_t total, std::size_t from, std::size_t to, unsigned char* out) {
  if (from >= to) return true;
  const std::size_t whole = total / 3, g0 = from / 3, g1 = (to + 2) / 3;
  thread_local std::vector<unsigned char> scratch;
  scratch.resize(3 * (g1 - g0));
  const std::size_t full_end = std::min(g1, whole);
  if (full_end > g0 && !decode_groups(run + 4 * g0, full_end - g0, scratch.data())) return false;
  if (g1 > whole && !decode_base64_run(run + 4 * whole, total - 3 * whole, scratch.data() + 3 * (whole - g0)))
    return false;
  std::memcpy(out, scratch.data() + (from - 3 * g0), to - from);
  return true;
}

// Little-endian words of 4 or 8 bytes.
std::uint64_t word_at(const unsigned char* p, std::size_t size) {
  std::uint64_t v = 0;
  for (std::size_t i = size; i-- > 0;) v = (v << 8) | p[i];
  return v;
}

// A run of data in the file: raw bytes, or base64 text (4 characters per 3 bytes).
struct Run {
  const char* at = nullptr;
  std::size_t bytes = 0;
  bool base64 = false;
  // Bytes [from, to) of the run into `out`, or a pointer to them in the file (raw).
  const unsigned char* get(std::size_t from, std::size_t to, unsigned char* out) const {
    if (!base64) return reinterpret_cast<const unsigned char*>(at) + from;
    return decode_base64_range(at, bytes, from, to, out) ? out : nullptr;
  }
};

// Reads the runs of one array from its start.
class Source {
public:
  Source(std::string_view file, const VtpArray& a) : file_(file), pos_(a.at), end_(a.end), base64_(a.base64) {}

  std::size_t available() const { return base64_ ? (end_ - pos_) / 4 * 3 : end_ - pos_; }

  // The next run of `bytes` bytes; nothing if it does not fit before the end.
  std::optional<Run> run(std::size_t bytes) {
    const std::size_t chars = base64_ ? (bytes + 2) / 3 * 4 : bytes;
    if (bytes > available() || chars > end_ - pos_) return std::nullopt;
    Run r{file_.data() + pos_, bytes, base64_};
    pos_ += chars;
    return r;
  }

  // Inline text may be followed by blanks only, up to its element's end.
  bool ends_cleanly(bool inline_text) const {
    if (!inline_text) return true;
    for (std::size_t p = pos_; p < end_; ++p)
      if (file_[p] != ' ' && file_[p] != '\t' && file_[p] != '\n' && file_[p] != '\r') return false;
    return true;
  }

private:
  std::string_view file_;
  std::size_t pos_, end_;
  bool base64_;
};

// The first `count` words of a run.
std::optional<std::vector<std::uint64_t>> words(const Run& run, std::size_t count, std::size_t w) {
  std::vector<unsigned char> bytes(count * w);
  const unsigned char* p = run.get(0, count * w, bytes.data());
  if (!p) return std::nullopt;
  std::vector<std::uint64_t> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = word_at(p + i * w, w);
  return out;
}

}  // namespace

vtkSmartPointer<vtkDataCompressor> make_vtp_decompressor(VtpCompressor type) {
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

namespace {

// Pieces of an uncompressed array: about a megabyte, whole values.
constexpr std::size_t kPiece = 1 << 20;

bool uncompressed(Source& source, std::size_t expected, std::size_t h, std::size_t value, ArraySink& sink) {
  // Raw: the header is its own word before the data; base64: one run holds both.
  const auto run = source.run(h + expected);
  if (!run) return false;
  const auto header = words(*run, 1, h);
  if (!header || (*header)[0] != expected) return false;
  const std::size_t piece = std::max<std::size_t>(1, kPiece / value) * value;
  const std::size_t pieces = (expected + piece - 1) / piece;
  std::atomic<bool> ok{true};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pieces, 1), [&](const tbb::blocked_range<std::size_t>& r) {
    thread_local std::vector<unsigned char> buffer;
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const std::size_t at = k * piece, n = std::min(piece, expected - at);
      unsigned char* direct = sink.direct(at, n);
      if (!direct) buffer.resize(n);
      const unsigned char* bytes = run->get(h + at, h + at + n, direct ? direct : buffer.data());
      if (!bytes) {
        ok = false;
        return;
      }
      if (!direct) {
        sink.put(at, bytes, n);
        continue;
      }
      if (bytes != direct) std::memcpy(direct, bytes, n);
      sink.written(at, n);
    }
  });
  return ok;
}

bool compressed(Source& source, std::size_t expected, std::size_t w, std::size_t value, VtpCompressor type,
                ArraySink& sink) {
  // The first three words (3w bytes: whole base64 groups), then the block sizes.
  Source peek = source;
  const auto first_run = peek.run(3 * w);
  if (!first_run) return false;
  const auto first = words(*first_run, 3, w);
  if (!first) return false;
  const std::uint64_t blocks = (*first)[0], block = (*first)[1], last = (*first)[2];
  if (blocks == 0) return expected == 0 && last == 0 && double(block) <= 64.0 * (1 << 20) && source.run(3 * w);
  if (block == 0 || block % value != 0 || last > block || blocks != (expected + block - 1) / block) return false;
  const std::uint64_t tail = expected - (blocks - 1) * block;  // the last block's true size
  if (last != (tail == block ? 0 : tail)) return false;
  if (blocks > source.available() / w) return false;
  const auto header_run = source.run((3 + blocks) * w);
  if (!header_run) return false;
  const auto header = words(*header_run, 3 + blocks, w);
  if (!header) return false;
  std::vector<std::size_t> starts(blocks + 1, 0);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t size = (*header)[3 + b];
    if (size > source.available() || starts[b] + size > source.available()) return false;
    starts[b + 1] = starts[b] + size;
  }
  // As much as the compressor can expand its input (vtk_xml_blocks.cpp's bounds): a header
  // claiming more is damaged, and nothing is allocated for it.
  const double limit = type == VtpCompressor::ZLib ? 1100 : type == VtpCompressor::LZ4 ? 300 : 1e5;
  const double possible = double(starts[blocks]) * limit + 65536;
  if (double(expected) > possible || double(block) > std::max(possible, 64.0 * (1 << 20))) return false;
  const auto data = source.run(starts[blocks]);
  if (!data) return false;
  std::atomic<bool> ok{true};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
    const auto decompressor = make_vtp_decompressor(type);
    thread_local std::vector<unsigned char> text, plain;
    for (std::size_t b = r.begin(); b != r.end() && ok.load(std::memory_order_relaxed); ++b) {
      const std::size_t size = b + 1 == blocks ? std::size_t(tail) : std::size_t(block);
      const std::size_t packed = starts[b + 1] - starts[b];
      text.resize(data->base64 ? packed : 0);
      const unsigned char* in = data->get(starts[b], starts[b + 1], text.data());
      unsigned char* target = sink.direct(b * block, size);
      if (!target) plain.resize(size), target = plain.data();
      if (!in || decompressor->Uncompress(in, packed, target, size) != size) {
        ok = false;
        return;
      }
      if (target == plain.data()) sink.put(b * block, target, size);
      else sink.written(b * block, size);
    }
  });
  return ok;
}

// Everything into one buffer of its own.
class BufferSink final : public ArraySink {
public:
  explicit BufferSink(std::size_t size) : data_(new unsigned char[size]) {}
  unsigned char* direct(std::size_t at, std::size_t) override { return data_.get() + at; }
  void put(std::size_t at, const unsigned char* bytes, std::size_t n) override { std::memcpy(data_.get() + at, bytes, n); }
  std::unique_ptr<unsigned char[]> take() { return std::move(data_); }

private:
  std::unique_ptr<unsigned char[]> data_;
};

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

bool decode_vtp_array_into(std::string_view file, const VtpArray& array, std::size_t expected,
                           std::size_t header_bytes, VtpCompressor compressor, ArraySink& sink) {
  if (array.at > array.end || array.end > file.size()) return false;
  const std::size_t value = vtp_type_size(array.type);
  if (expected % value != 0) return false;
  Source source(file, array);
  const bool ok = compressor == VtpCompressor::None
                      ? uncompressed(source, expected, header_bytes, value, sink)
                      : compressed(source, expected, header_bytes, value, compressor, sink);
  return ok && source.ends_cleanly(array.inline_text);
}

std::optional<DecodedBytes> decode_vtp_array(std::string_view file, const VtpArray& array, std::size_t expected,
                                             std::size_t header_bytes, VtpCompressor compressor) {
  DecodedBytes out;
  out.size = expected;
  // Raw uncompressed data is used where it lies.
  if (!array.base64 && compressor == VtpCompressor::None && array.at <= array.end && array.end <= file.size()) {
    Source source(file, array);
    const auto run = source.run(header_bytes + expected);
    if (!run) return std::nullopt;
    const auto header = words(*run, 1, header_bytes);
    if (!header || (*header)[0] != expected) return std::nullopt;
    out.bytes = reinterpret_cast<const unsigned char*>(run->at) + header_bytes;
    return out;
  }
  BufferSink sink(expected);
  if (!decode_vtp_array_into(file, array, expected, header_bytes, compressor, sink)) return std::nullopt;
  out.owner = sink.take();
  out.bytes = out.owner.get();
  return out;
}

}  // namespace subdiv::io_detail
