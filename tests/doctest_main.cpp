// The test programs' main: the VTK formats registered as the `subdiv` tool registers them,
// so read_mesh and write_mesh handle .vtp/.vtk/.pvd in every test; and a temporary folder
// of this process's own, so that test programs running at the same time (ctest -j, two
// checkouts on one machine) never share the fixed file names tests write under
// std::filesystem::temp_directory_path().
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include "framework/io/vtk/vtk_formats.h"

namespace {

// TMPDIR set to a fresh folder under the system's temporary folder (which
// temp_directory_path() and the programs the tests start read), removed at exit.
class PrivateTemporaryFolder {
public:
  PrivateTemporaryFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "subdivkit-test-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) return;  // keep the shared folder rather than fail
    folder_ = pattern;
    ::setenv("TMPDIR", folder_.c_str(), 1);
  }
  ~PrivateTemporaryFolder() {
    std::error_code ignored;
    if (!folder_.empty()) std::filesystem::remove_all(folder_, ignored);
  }

private:
  std::string folder_;
};

}  // namespace

int main(int argc, char** argv) {
  const PrivateTemporaryFolder temporary;
  subdiv::register_vtk_formats();
  return doctest::Context(argc, argv).run();
}
