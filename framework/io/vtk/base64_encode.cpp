#include "framework/io/vtk/base64_encode.h"

#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define SUBDIV_BASE64_AVX2 1
#endif

namespace subdiv::io_detail {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// The two characters of every 12 bits: a triplet is two look-ups instead of four.
struct CharPairs {
  char pairs[4096][2];
  constexpr CharPairs() : pairs() {
    for (int i = 0; i < 4096; ++i) pairs[i][0] = kAlphabet[i >> 6], pairs[i][1] = kAlphabet[i & 63];
  }
};
constexpr CharPairs kPairs;

#ifdef SUBDIV_BASE64_AVX2
// The 32 sextets of 24 input bytes, one per byte: lane 0 holds bytes 0..11 of the input, lane 1
// bytes 12..23 (loaded from in + 12), each lane split as the SSSE3 version of the paper does
// (shuffle every triplet into a 32-bit word, then shift its four sextets into place with
// 16-bit multiplies).
__attribute__((target("avx2"))) __m256i sextets(const unsigned char* in) {
  const __m256i bytes = _mm256_inserti128_si256(
      _mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(in))),
      _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + 12)), 1);
  const __m256i shuffled = _mm256_shuffle_epi8(
      bytes, _mm256_setr_epi8(1, 0, 2, 1, 4, 3, 5, 4, 7, 6, 8, 7, 10, 9, 11, 10,  //
                              1, 0, 2, 1, 4, 3, 5, 4, 7, 6, 8, 7, 10, 9, 11, 10));
  const __m256i t0 = _mm256_and_si256(shuffled, _mm256_set1_epi32(0x0FC0FC00));
  const __m256i t1 = _mm256_mulhi_epu16(t0, _mm256_set1_epi32(0x04000040));
  const __m256i t2 = _mm256_and_si256(shuffled, _mm256_set1_epi32(0x003F03F0));
  const __m256i t3 = _mm256_mullo_epi16(t2, _mm256_set1_epi32(0x01000010));
  return _mm256_or_si256(t1, t3);
}

// Sextets 0..63 to the alphabet: the offset to add for each of the five ranges (A-Z, a-z,
// 0-9, '+', '/') from a 16-entry table.
__attribute__((target("avx2"))) __m256i characters(__m256i sextet) {
  const __m256i offsets = _mm256_setr_epi8(65, 71, -4, -4, -4, -4, -4, -4, -4, -4, -4, -4, -19, -16, 0, 0,  //
                                           65, 71, -4, -4, -4, -4, -4, -4, -4, -4, -4, -4, -19, -16, 0, 0);
  __m256i index = _mm256_subs_epu8(sextet, _mm256_set1_epi8(51));        // 0 for A-Z and a-z, 1..12 above
  const __m256i above_z = _mm256_cmpgt_epi8(sextet, _mm256_set1_epi8(25));  // -1 from 'a' on
  index = _mm256_sub_epi8(index, above_z);
  return _mm256_add_epi8(sextet, _mm256_shuffle_epi8(offsets, index));
}

// Whole groups of 8 triplets while 4 bytes past them can be read (the second load reads 16
// bytes from in + 12); returns the triplets done.
__attribute__((target("avx2"))) std::size_t encode_avx2(const unsigned char* in, std::size_t triplets, char* out) {
  std::size_t t = 0;
  for (; 3 * t + 28 <= 3 * triplets; t += 8)
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + 4 * t), characters(sextets(in + 3 * t)));
  return t;
}
#endif

}  // namespace

void encode_base64_triplets_portable(const unsigned char* in, std::size_t triplets, char* out) {
  for (std::size_t t = 0; t < triplets; ++t, in += 3, out += 4) {
    const unsigned bits = unsigned(in[0]) << 16 | unsigned(in[1]) << 8 | in[2];
    std::memcpy(out, kPairs.pairs[bits >> 12], 2);
    std::memcpy(out + 2, kPairs.pairs[bits & 0xFFF], 2);
  }
}

std::size_t encode_base64_tail(const unsigned char* in, std::size_t n, char* out) {
  if (n == 0) return 0;
  const unsigned bits = unsigned(in[0]) << 16 | (n > 1 ? unsigned(in[1]) << 8 : 0u);
  out[0] = kAlphabet[bits >> 18];
  out[1] = kAlphabet[(bits >> 12) & 63];
  out[2] = n > 1 ? kAlphabet[(bits >> 6) & 63] : '=';
  out[3] = '=';
  return 4;
}

void encode_base64_triplets(const unsigned char* in, std::size_t triplets, char* out) {
  std::size_t done = 0;
#ifdef SUBDIV_BASE64_AVX2
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) done = encode_avx2(in, triplets, out);
#endif
  encode_base64_triplets_portable(in + 3 * done, triplets - done, out + 4 * done);
}

}  // namespace subdiv::io_detail
