// Where scheme names are looked up: SUBDIV_SCHEME_PATH first, then the built-in folder,
// which for the library of this build tree is the source tree's schemes/.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "framework/scheme/scheme_folders.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/library_location.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

struct SchemePathScope {
  explicit SchemePathScope(const std::string& value) { ::setenv("SUBDIV_SCHEME_PATH", value.c_str(), 1); }
  ~SchemePathScope() { ::unsetenv("SUBDIV_SCHEME_PATH"); }
};

}  // namespace

TEST_CASE("library_directory is the folder libsubdiv was loaded from") {
  const fs::path dir = library_directory();
  REQUIRE_FALSE(dir.empty());
  CHECK(fs::exists(dir / "libsubdiv.so"));
}

TEST_CASE("scheme folders: SUBDIV_SCHEME_PATH's folders in order, then the source tree's schemes/") {
  ::unsetenv("SUBDIV_SCHEME_PATH");
  const auto plain = scheme_folders();
  REQUIRE(plain.size() == 1);
  CHECK(plain[0].origin == "built-in");
  CHECK(fs::equivalent(plain[0].path, fs::path(SUBDIV_SOURCE_DIR) / "schemes"));

  SchemePathScope scope("/first::/second");  // an empty entry is skipped
  const auto folders = scheme_folders();
  REQUIRE(folders.size() == 3);
  CHECK(folders[0].path == "/first");
  CHECK(folders[1].path == "/second");
  CHECK(folders[0].origin == "SUBDIV_SCHEME_PATH");
  CHECK(folders[2].origin == "built-in");
}

TEST_CASE("a scheme on SUBDIV_SCHEME_PATH comes before the built-in one of the same name") {
  const fs::path dir = fs::temp_directory_path() / "subdivkit-scheme-folders-test";
  fs::create_directories(dir);
  // A curve scheme named like the built-in surface scheme: whichever is found says its kind.
  std::ofstream(dir / "loop.json") << R"({"name": "loop", "kind": "curve", "arity": 2,
    "mask": {"even": [0.25, 0.75], "odd": [0.75, 0.25]}})";
  CHECK(scheme_kind("loop") == "surface");
  {
    SchemePathScope scope(dir.string());
    CHECK(scheme_file_path("loop") == (dir / "loop.json").string());
    bool listed = false;
    for (const auto& s : list_schemes())
      if (s.name == "loop") listed = s.origin == "SUBDIV_SCHEME_PATH" && s.path == (dir / "loop.json").string();
    CHECK(listed);
  }
  fs::remove_all(dir);
}
