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

TEST_CASE("a read-only file is refused as the target, by check_writable and by the writer; a writable one is replaced") {
  // The finished temporary was renamed onto it: a file its owner made read-only (chmod 444)
  // was replaced without a word, also by root, whom permissions do not stop.
  const fs::path dir = fs::temp_directory_path() / "subdivkit-check-read-only";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "kept.obj") << "kept";
  fs::permissions(dir / "kept.obj", fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  const char* message = "it is read-only (no write permission); make it writable (chmod u+w) or name another output";
  CHECK_THROWS_WITH_AS(check_writable(dir / "kept.obj"), doctest::Contains(message), Error);
  CHECK_THROWS_WITH_AS(write_file_atomically(dir / "kept.obj", [](const fs::path& tmp) { std::ofstream(tmp) << "new"; }),
                       doctest::Contains(message), Error);
  std::ifstream in(dir / "kept.obj");
  std::string text;
  in >> text;
  CHECK(text == "kept");
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  CHECK(entries == 1);  // no temporary left
  fs::permissions(dir / "kept.obj", fs::perms::owner_write, fs::perm_options::add);
  CHECK_NOTHROW(write_file_atomically(dir / "kept.obj", [](const fs::path& tmp) { std::ofstream(tmp) << "new"; }));
  fs::remove_all(dir);
}
