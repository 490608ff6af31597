// The plugin loader's check before dlopen (issue 33): mutated and cut-off shared libraries
// (seeded with the built plugins) must be judged from their bytes without reading outside
// them. dlopen itself is not run on fuzzed files: it executes the library's constructors
// and trusts its relocations, which no check short of a full ELF verifier makes safe; the
// check's job is that a half-copied or damaged file never reaches it (elf_check.h).
#include <string_view>

#include "fuzz_support.h"
#include "framework/plugin/elf_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const auto problem = subdiv::elf_problem(bytes);
  // A file cut short by one byte or more must never pass when its tables reach the end.
  if (!problem && size > 0) (void)subdiv::elf_problem(bytes.substr(0, size - 1));
  return 0;
}
