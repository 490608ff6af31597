#pragma once
// Little-endian binary values for the PLY and STL writers, whatever the host's order.
#include <algorithm>
#include <bit>
#include <cstring>

#include "framework/util/buffered_output.h"

namespace subdiv::io_detail {

template <typename T>
void put_le(BufferedOutput& out, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
  out.write(raw, sizeof(T));
}

}  // namespace subdiv::io_detail
