// The feature sidecar (--features FILE.json): creases and corners by vertex index.
#include "fuzz_support.h"
#include "framework/io/feature_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  subdiv::fuzz::expect_only_subdiv_errors([&] { (void)subdiv::parse_feature_json(text, "fuzz-features.json"); });
  return 0;
}
