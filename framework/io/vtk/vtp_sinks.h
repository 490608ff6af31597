#pragma once
// Where the fast .vtp reader (vtp_fast_read.h) puts decoded arrays (vtp_array_decode.h's
// ArraySink): converted into the mesh's arrays, checked, scanned or only decoded. Each is
// called from several threads at once, for disjoint pieces. Internal to io/.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <limits>
#include <mutex>
#include <type_traits>
#include <utility>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/io/vtk/vtp_array_decode.h"
#include "framework/io/vtk/vtp_layout.h"

namespace subdiv::io_detail {

// Calls f(T{}) with the C++ type of `type`.
template <class F>
void with_type(VtpType type, F&& f) {
  switch (type) {
    case VtpType::Int8: return f(std::int8_t{});
    case VtpType::UInt8: return f(std::uint8_t{});
    case VtpType::Int16: return f(std::int16_t{});
    case VtpType::UInt16: return f(std::uint16_t{});
    case VtpType::Int32: return f(std::int32_t{});
    case VtpType::UInt32: return f(std::uint32_t{});
    case VtpType::Int64: return f(std::int64_t{});
    case VtpType::UInt64: return f(std::uint64_t{});
    case VtpType::Float32: return f(float{});
    case VtpType::Float64: return f(double{});
  }
}

// Values may lie anywhere in the file (raw appended data): loaded with memcpy.
template <class T>
T load(const unsigned char* bytes, std::size_t i) {
  T v;
  std::memcpy(&v, bytes + i * sizeof(T), sizeof(T));
  return v;
}

// Whether an integer value lies in [lo, hi].
template <class T>
bool within(T v, long long lo, long long hi) {
  if constexpr (std::is_signed_v<T>) return static_cast<long long>(v) >= lo && static_cast<long long>(v) <= hi;
  else return (lo <= 0 || static_cast<unsigned long long>(v) >= static_cast<unsigned long long>(lo)) &&
              static_cast<unsigned long long>(v) <= static_cast<unsigned long long>(hi);
}

// Values into an array of Out as they are decoded: straight from the decoder where the file
// has Out's type, else converted (integers checked against [lo, hi] first, when asked).
template <class Out>
class ConvertSink final : public ArraySink {
public:
  ConvertSink(VtpType type, bool same, Out* out) : type_(type), same_(same), out_(out) {}
  void check(long long lo, long long hi) { checked_ = true, lo_ = lo, hi_ = hi; }
  bool good() const { return good_; }

  unsigned char* direct(std::size_t at, std::size_t) override {
    return same_ ? reinterpret_cast<unsigned char*>(out_) + at : nullptr;
  }
  // Values of the file's type, checked while still in cache.
  void written(std::size_t at, std::size_t n) override {
    if constexpr (std::is_integral_v<Out>) {
      if (!checked_) return;
      if (hi_ < lo_) {  // nothing fits (ids with no points)
        if (n > 0) good_ = false;
        return;
      }
      // Bounds inside Out's range (they are for ids and offsets), compared without branches so
      // that the loop vectorises.
      const auto lo = Out(std::max<long long>(lo_, std::numeric_limits<Out>::min()));
      const auto hi = Out(std::min<long long>(hi_, std::numeric_limits<Out>::max()));
      const Out* v = out_ + at / sizeof(Out);
      unsigned outside = 0;
      for (std::size_t i = 0; i < n / sizeof(Out); ++i) outside |= unsigned(v[i] < lo) | unsigned(v[i] > hi);
      if (outside) good_ = false;
    }
  }
  void put(std::size_t at, const unsigned char* bytes, std::size_t n) override {
    with_type(type_, [&](auto tag) {
      using T = decltype(tag);
      Out* out = out_ + at / sizeof(T);
      bool fits = true;
      for (std::size_t i = 0; i < n / sizeof(T); ++i) {
        const T v = load<T>(bytes, i);
        if constexpr (!std::is_floating_point_v<T>)
          if (checked_) fits = fits && within(v, lo_, hi_);
        out[i] = static_cast<Out>(v);
      }
      if (!fits) good_ = false;
    });
  }

private:
  VtpType type_;
  bool same_;
  Out* out_;
  bool checked_ = false;
  long long lo_ = 0, hi_ = 0;
  std::atomic<bool> good_{true};
};

// Decodes and checks an array SubdivKit does not keep (field data, its own arrays).
class DiscardSink final : public ArraySink {
public:
  unsigned char* direct(std::size_t, std::size_t) override { return nullptr; }
  void put(std::size_t, const unsigned char*, std::size_t) override {}
};

// The nonzero values of a one-component point array (corner_sharpness), in point order.
class NonzeroSink final : public ArraySink {
public:
  explicit NonzeroSink(VtpType type) : type_(type) {}
  unsigned char* direct(std::size_t, std::size_t) override { return nullptr; }
  void put(std::size_t at, const unsigned char* bytes, std::size_t n) override {
    std::vector<CornerTag> found;
    with_type(type_, [&](auto tag) {
      using T = decltype(tag);
      for (std::size_t i = 0; i < n / sizeof(T); ++i)
        if (const double s = static_cast<double>(load<T>(bytes, i)); s != 0)
          found.push_back({Index(at / sizeof(T) + i), s});
    });
    if (found.empty()) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    pieces_.emplace_back(at, std::move(found));
  }
  std::vector<CornerTag> take() {
    std::sort(pieces_.begin(), pieces_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<CornerTag> out;
    for (auto& piece : pieces_) out.insert(out.end(), piece.second.begin(), piece.second.end());
    return out;
  }

private:
  VtpType type_;
  std::mutex mutex_;
  std::vector<std::pair<std::size_t, std::vector<CornerTag>>> pieces_;
};

}  // namespace subdiv::io_detail
