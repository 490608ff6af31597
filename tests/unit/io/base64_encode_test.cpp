// The .vtp writer's base64 encoder (framework/io/vtk/base64_encode.h): the AVX2 path, the
// table path and a one-character-at-a-time reference write the same text for every length
// and every byte value, wherever the input starts.
#include <doctest/doctest.h>

#include <random>
#include <string>
#include <vector>

#include "framework/io/vtk/base64_encode.h"

using namespace subdiv::io_detail;

namespace {

std::string reference(const unsigned char* in, std::size_t triplets) {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t t = 0; t < triplets; ++t, in += 3) {
    out += alphabet[in[0] >> 2];
    out += alphabet[((in[0] & 3) << 4) | (in[1] >> 4)];
    out += alphabet[((in[1] & 15) << 2) | (in[2] >> 6)];
    out += alphabet[in[2] & 63];
  }
  return out;
}

}  // namespace

TEST_CASE("base64: every path writes the reference text") {
  std::mt19937 random(18);
  std::vector<unsigned char> bytes(3 * 1200 + 7);
  for (auto& b : bytes) b = static_cast<unsigned char>(random());
  for (int v = 0; v < 256; ++v) bytes[v] = static_cast<unsigned char>(v);  // every value, so every sextet
  for (std::size_t start : {0, 1, 5}) {
    for (std::size_t triplets = 0; triplets <= 1200; triplets += triplets < 40 ? 1 : 97) {
      CAPTURE(start);
      CAPTURE(triplets);
      const std::string expected = reference(bytes.data() + start, triplets);
      std::string fast(4 * triplets, '?'), portable(4 * triplets, '?');
      encode_base64_triplets(bytes.data() + start, triplets, fast.data());
      encode_base64_triplets_portable(bytes.data() + start, triplets, portable.data());
      CHECK(fast == expected);
      CHECK(portable == expected);
    }
  }
}
