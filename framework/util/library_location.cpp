#include "framework/util/library_location.h"

#include <dlfcn.h>

namespace subdiv {

std::filesystem::path library_directory() {
  // dladdr on a function of this library names the file it was loaded from.
  Dl_info info{};
  if (!dladdr(reinterpret_cast<void*>(&library_directory), &info) || !info.dli_fname) return {};
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::weakly_canonical(info.dli_fname, ec);
  if (ec) return {};
  return file.parent_path();
}

}  // namespace subdiv
