#pragma once
// Where libsubdiv itself is on disk, so that an installed tree finds its own files (built-in
// schemes, plugins) relative to the library wherever its prefix is, instead of at paths
// fixed when it was configured.
#include <filesystem>

namespace subdiv {

// The folder of the shared library this code is linked into (resolved through symbolic
// links), or an empty path where the system cannot say.
std::filesystem::path library_directory();

}  // namespace subdiv
