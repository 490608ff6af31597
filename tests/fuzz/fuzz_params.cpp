// --param name=value, as `subdiv refine` splits it (tools/subdiv/refine_command.cpp: the
// text before the first '=' is the name), applied to the built-in schemes whose parameters
// are numbers, choices and curve parameters. One --param per input line; the first line
// names the scheme or sequence.
#include <sstream>

#include "fuzz_support.h"
#include "framework/scheme/scheme_sequence.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  std::string scheme;
  std::getline(lines, scheme);
  subdiv::ParameterOverrides overrides;
  for (std::string line; std::getline(lines, line);) {
    const auto eq = line.find('=');
    if (eq == std::string::npos || eq == 0) return 0;  // the CLI refuses these before loading
    overrides[line.substr(0, eq)] = line.substr(eq + 1);
  }
  subdiv::fuzz::expect_only_subdiv_errors([&] { (void)subdiv::load_scheme_sequence(scheme, 2, overrides); });
  return 0;
}
