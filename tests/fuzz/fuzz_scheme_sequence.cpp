// --scheme "A:1,B:3" with --levels: the first byte is the level count, the rest the spec.
// Names resolve to built-in schemes (or to files, which the input checks guard).
#include "fuzz_support.h"
#include "framework/scheme/scheme_sequence.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int levels = data[0] % 32;
  const std::string spec(reinterpret_cast<const char*>(data + 1), size - 1);
  subdiv::fuzz::expect_only_subdiv_errors([&] { (void)subdiv::load_scheme_sequence(spec, levels, {}); });
  return 0;
}
