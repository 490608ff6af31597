#include "framework/scheme/scheme_folders.h"

#include <cstdlib>

#include "framework/util/library_location.h"

// Set by framework/CMakeLists.txt for this file only.
#ifndef SUBDIV_SCHEME_DIR_FROM_LIBRARY
#error "SUBDIV_SCHEME_DIR_FROM_LIBRARY (share/subdivkit/schemes relative to the installed library) is not defined"
#endif

namespace subdiv {
namespace fs = std::filesystem;
namespace {

void add_environment_folders(std::vector<SchemeFolder>& folders) {
  const char* env = std::getenv("SUBDIV_SCHEME_PATH");
  if (!env) return;
  const std::string list = env;
  size_t start = 0;
  while (start <= list.size()) {
    size_t end = list.find(':', start);
    if (end == std::string::npos) end = list.size();
    if (end > start) folders.push_back({list.substr(start, end - start), "SUBDIV_SCHEME_PATH"});
    start = end + 1;
  }
}

bool same_folder(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec);
}

}  // namespace

std::vector<SchemeFolder> scheme_folders() {
  std::vector<SchemeFolder> folders;
  add_environment_folders(folders);
  const fs::path library = library_directory();
  if (library.empty()) {
    folders.push_back({SUBDIV_SCHEME_DIR_BUILD, "built-in"});
    folders.push_back({SUBDIV_SCHEME_DIR_INSTALL, "built-in"});
    return folders;
  }
  // The installed folder is looked for first, so that an installed library never even
  // looks at the tree it was built in.
  const fs::path installed = (library / SUBDIV_SCHEME_DIR_FROM_LIBRARY).lexically_normal();
  std::error_code ec;
  if (!fs::is_directory(installed, ec) && same_folder(library, SUBDIV_LIBRARY_DIR_BUILD))
    folders.push_back({SUBDIV_SCHEME_DIR_BUILD, "built-in"});
  else
    folders.push_back({installed, "built-in"});
  return folders;
}

}  // namespace subdiv
