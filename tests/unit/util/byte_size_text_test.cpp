// Sizes in messages: a readable unit, and a refusal's two sizes never printed alike.
#include <doctest/doctest.h>

#include <string>
#include <tuple>

#include "framework/util/byte_size_text.h"

using namespace subdiv;

namespace {
constexpr double MiB = 1024.0 * 1024.0, GiB = 1024.0 * MiB, PiB = GiB * 1024.0 * 1024.0;
}

TEST_CASE("byte_size_text: the unit that reads best, never '0.0 GiB' nor '1932735283200.0 GiB'") {
  CHECK(byte_size_text(512) == "512 bytes");
  CHECK(byte_size_text(1536) == "1.5 KiB");
  CHECK(byte_size_text(390.625 * MiB) == "390.6 MiB");
  CHECK(byte_size_text(3.81 * GiB) == "3.8 GiB");
  CHECK(byte_size_text(2 * PiB) == "2.0 PiB");
  CHECK(byte_size_text(1.84e6 * PiB) == "1.84e+06 PiB");
}

TEST_CASE("byte_sizes_compared: whenever need > have, the two texts differ and keep their order") {
  // The refusal of --samples 500 under ulimit -v 400000 read "would need about 0.3 GiB, but
  // only 0.3 GiB is available".
  std::string need, have;  // not a structured binding: clang 14's INFO cannot capture one
  std::tie(need, have) = byte_sizes_compared(0.34 * GiB, 0.26 * GiB);
  CHECK(need == "348.2 MiB");
  CHECK(have == "266.2 MiB");
  std::tie(need, have) = byte_sizes_compared(1.04 * GiB, 1.01 * GiB);
  CHECK(need == "1.04 GiB");
  CHECK(have == "1.01 GiB");
  // In the unit of the larger: 1.1 GiB against 0.9 GiB, not 1.1 GiB against 921.6 MiB.
  std::tie(need, have) = byte_sizes_compared(1.1 * GiB, 0.9 * GiB);
  CHECK(need == "1.1 GiB");
  CHECK(have == "0.9 GiB");
  // As many digits as it takes, down to a byte and below.
  for (const double base : {100.0, 5000.0, 3 * MiB, 2.5 * GiB, 7 * PiB, 3e6 * PiB})
    for (const double step : {1e-9, 1e-3, 1.0, 1024.0}) {
      if (base + step == base) continue;
      std::tie(need, have) = byte_sizes_compared(base + step, base);
      INFO(base, " + ", step, ": ", need, " against ", have);
      CHECK(need != have);
    }
  std::tie(need, have) = byte_sizes_compared(2 * GiB, 2 * GiB);
  CHECK(need == have);
  // tessellate(10**9) in Python: "would need about 1.28e+06 PiB, but only 0.0 PiB" with 20 GiB free.
  std::tie(need, have) = byte_sizes_compared(1.28e6 * 1024 * 1024 * GiB, 20 * GiB);
  CHECK(need == "1.28e+06 PiB");
  CHECK(have == "20.0 GiB");
  std::tie(need, have) = byte_sizes_compared(3 * GiB, 100 * 1024.0);
  CHECK(need == "3.0 GiB");
  CHECK(have == "100.0 KiB");
}
