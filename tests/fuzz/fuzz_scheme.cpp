// The scheme loader: JSON text as a scheme file would hold it, surface or curve, with every
// formula compiled and checked (the loader evaluates them at the valences it checks).
#include "fuzz_support.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/scheme/scheme_registry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  subdiv::fuzz::expect_only_subdiv_errors([&] {
    if (subdiv::scheme_text_kind(text, "fuzz.json") == "curve") (void)subdiv::load_curve_text(text, "fuzz.json");
    else (void)subdiv::load_scheme_text(text, "fuzz.json");
  });
  return 0;
}
