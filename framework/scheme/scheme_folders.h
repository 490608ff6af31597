#pragma once
// The folders searched for scheme files by name, in order.
#include <filesystem>
#include <string>
#include <vector>

namespace subdiv {

struct SchemeFolder {
  std::filesystem::path path;
  std::string origin;  // "SUBDIV_SCHEME_PATH" or "built-in"
};

// First every folder of $SUBDIV_SCHEME_PATH (':'-separated), then the built-in schemes:
// share/subdivkit/schemes found from libsubdiv's own folder (an installed tree works for
// any prefix and wherever it is moved), or the source tree's schemes/ when libsubdiv is
// the one in its build tree. The folders fixed at configure time are used only where the
// library cannot tell where it is.
std::vector<SchemeFolder> scheme_folders();

}  // namespace subdiv
