#pragma once
// Streaming (non-temporal) stores: writes that go past the caches without reading each
// line in first. For large output that nothing reads soon (a refinement's last level:
// its faces and points), they save the read of every line written, and keep the caches
// for what is read again. Weakly ordered: call streaming_fence() at the end of each loop
// that uses them, before another thread may read the output. Plain stores where the
// instructions are missing (or SUBDIV_NO_STREAMING_STORES is defined); callers ask
// streaming_stores_wanted() first, which SUBDIV_STREAMING_STORES=0 in the environment
// turns off (to measure what they give: docs/benchmarks.md).
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#if defined(__x86_64__) && defined(__SSE2__) && !defined(SUBDIV_NO_STREAMING_STORES)
#include <emmintrin.h>
#define SUBDIV_STREAMING_STORES 1
#endif

namespace subdiv {

inline bool streaming_stores_wanted() {
  static const bool wanted = [] {
    const char* setting = std::getenv("SUBDIV_STREAMING_STORES");
    return !setting || std::string_view(setting) != "0";
  }();
  return wanted;
}

inline void stream_store(std::int32_t* to, std::int32_t value) {
#ifdef SUBDIV_STREAMING_STORES
  _mm_stream_si32(to, value);
#else
  *to = value;
#endif
}

inline void stream_store(double* to, double value) {
#ifdef SUBDIV_STREAMING_STORES
  _mm_stream_si64(reinterpret_cast<long long*>(to), std::bit_cast<long long>(value));
#else
  *to = value;
#endif
}

// Four values at `to`, which must be 16-byte aligned (one store).
inline void stream_store4(std::int32_t* to, std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t d) {
#ifdef SUBDIV_STREAMING_STORES
  _mm_stream_si128(reinterpret_cast<__m128i*>(to), _mm_setr_epi32(a, b, c, d));
#else
  to[0] = a, to[1] = b, to[2] = c, to[3] = d;
#endif
}

inline void streaming_fence() {
#ifdef SUBDIV_STREAMING_STORES
  _mm_sfence();
#endif
}

}  // namespace subdiv
