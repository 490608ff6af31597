#pragma once
// Base64 of whole byte triplets (RFC 4648's alphabet, no padding: the caller pads the tail),
// the encoder behind the .vtp writer's inline binary data. Internal to io/.
#include <cstddef>

namespace subdiv::io_detail {

// Writes 4 * triplets characters to `out` for the 3 * triplets bytes at `in`. With AVX2
// (checked at run time) 24 bytes at a time, after Muła, Kurz and Lemire, "Faster Base64
// Encoding and Decoding Using AVX2 Instructions" (ACM TOWEB 2018); otherwise two characters
// per 12-bit table look-up. Both write the same characters.
void encode_base64_triplets(const unsigned char* in, std::size_t triplets, char* out);

// The padded end of a run: the last `n` bytes (0, 1 or 2) as 4 characters ending in '=', as
// vtkBase64OutputStream ends a run. Returns the characters written (0 for n = 0).
std::size_t encode_base64_tail(const unsigned char* in, std::size_t n, char* out);

// The table path alone (tests compare the two).
void encode_base64_triplets_portable(const unsigned char* in, std::size_t triplets, char* out);

}  // namespace subdiv::io_detail
