// check_writable: the refusals StagedFiles::stage would give, before any work, and nothing
// left behind by the probe.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "framework/util/atomic_file.h"
#include "framework/util/error.h"

using namespace subdiv;
namespace fs = std::filesystem;

TEST_CASE("check_writable: a missing folder or a folder in the target's place is refused; the probe leaves nothing") {
  const fs::path dir = fs::temp_directory_path() / "subdivkit-check-writable";
  fs::remove_all(dir);
  fs::create_directories(dir / "folder.vtp");
  CHECK_THROWS_WITH_AS(check_writable(dir / "missing" / "a.vtp"), doctest::Contains("does not exist; create it first"),
                       Error);
  CHECK_THROWS_WITH_AS(check_writable(dir / "folder.vtp"), doctest::Contains("it is a directory"), Error);
  CHECK_THROWS_WITH_AS(check_writable(dir / (std::string(300, 'x') + ".vtp")),
                       doctest::Contains("more than the"), Error);
  CHECK_NOTHROW(check_writable(dir / "a.vtp"));
  std::ofstream(dir / "old.vtp") << "kept";
  CHECK_NOTHROW(check_writable(dir / "old.vtp"));
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  CHECK(entries == 2);  // folder.vtp and old.vtp: no probe, no a.vtp
  std::ifstream in(dir / "old.vtp");
  std::string text;
  in >> text;
  CHECK(text == "kept");
  fs::remove_all(dir);
}
