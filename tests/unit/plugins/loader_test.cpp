// Loading plugins in-process: the record checks, each refusal with its reason, atomic
// registration, discovery through SUBDIV_PLUGIN_PATH, and the others still working.
#include <cstdlib>
#include <fstream>
#include <doctest/doctest.h>

#include "framework/plugin/plugin_loader.h"
#include "framework/refine/splitter.h"
#include "framework/rules/rule.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/cli_runner.h"
#include "support/test_meshes.h"
#include "framework/plugin/plugin_api.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv;
using namespace subdiv::test;
namespace fs = std::filesystem;

TEST_CASE("the example plugins load and register their schemes, splitter and role") {
  load_example_plugins();
  bool circle = false;
  for (const PluginStatus& s : plugin_statuses())
    if (s.name == "circle-preserving") {
      circle = true;
      CHECK(s.loaded);
      CHECK(s.version == "1.0.0");
      CHECK(s.reason.empty());
      CHECK(s.provides.size() == 2);
    }
  CHECK(circle);
  const CodeSchemeEntry* cfp = find_code_scheme("circle-four-point");
  REQUIRE(cfp);
  CHECK(cfp->kind == "curve");
  CHECK(cfp->origin == "plugin circle-preserving");
  CHECK(contains(cfp->path, "subdiv_circle_preserving.so"));
  CHECK(splitter_info(split_kind_from_name("sqrt2")).origin == "plugin sqrt2");
  const auto line = role_from_name("line");
  REQUIRE(line);
  CHECK(role_allowed(Element::Edge, *line));
  CHECK_FALSE(role_allowed(Element::Vertex, *line));
  // Plugin schemes are listed next to the JSON ones, with their origin.
  bool listed = false;
  for (const auto& s : list_schemes()) {
    if (s.name == "kobbelt-quad") {
      listed = true;
      CHECK(s.origin == "plugin kobbelt-quad");
    }
    if (s.name == "loop") CHECK(s.origin == "built-in");
  }
  CHECK(listed);
}

TEST_CASE("faulty plugins are refused with the file and the reason; nothing of them stays") {
  load_example_plugins();
  struct Case {
    const char* target;
    std::string reason;
  };
  // wrong_version.cpp claims the interface 98 versions ahead of ours.
  const std::string future = std::to_string(SUBDIV_PLUGIN_INTERFACE_VERSION + 98);
  const Case cases[] = {
      {"test_plugin_no_entry", "no entry point 'subdiv_plugin_info': not a SubdivKit plugin"},
      {"test_plugin_wrong_version", "interface version mismatch: the plugin was built for plugin interface " + future},
      {"test_plugin_throws", "its registration threw: the test plugin fails on purpose"},
      {"test_plugin_duplicate_scheme", "duplicate scheme name 'catmull-clark': the scheme file"},
      {"test_plugin_clash", "duplicate scheme name 'circle-four-point': plugin circle-preserving already defines it"},
      {"test_plugin_partial", "scheme 'partial-scheme' does not load: unknown scheme 'no-such-curve'"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.target);
    const PluginStatus s = load_plugin(plugin_path(c.target));
    CHECK_FALSE(s.loaded);
    CHECK(s.file == plugin_path(c.target));
    CHECK_MESSAGE(contains(s.reason, c.reason), s.reason);
    CHECK(s.provides.empty());
  }
  // The wrong-version plugin is refused before its registration runs (it would throw).
  // Nothing of the refused plugins is registered, not even what they registered first.
  CHECK(find_code_scheme("never-registered") == nullptr);
  CHECK(find_code_scheme("partial-scheme") == nullptr);
  CHECK_THROWS_WITH_AS(split_kind_from_name("partial-split"), doctest::Contains("unknown split 'partial-split'"), Error);
  CHECK(load_scheme("catmull-clark")->path.ends_with("catmull-clark.json"));  // still the file
  CHECK(find_code_scheme("circle-four-point")->origin == "plugin circle-preserving");

  // The plugins loaded before still work.
  const auto scheme = load_scheme("kobbelt-quad");
  const Mesh grid4 = grid(4, 4);
  RefineOptions options;
  options.levels = 1;
  const Hierarchy h = refine(*scheme, grid4.level(), options);
  CHECK(h.levels[1].face_count() == 64);
}

TEST_CASE("a file that is not there, and a second copy of a loaded plugin, are refused") {
  load_example_plugins();
  const PluginStatus missing = load_plugin("/no/such/plugin.so");
  CHECK_FALSE(missing.loaded);
  CHECK(missing.reason == "no such file");

  const fs::path dir = fresh_dir("plugin-copy");
  const fs::path copy = dir / "circle_copy.so";
  fs::copy_file(plugin_path("subdiv_circle_preserving"), copy);
  const PluginStatus twice = load_plugin(copy);
  CHECK_FALSE(twice.loaded);
  CHECK(twice.name == "circle-preserving");
  CHECK_MESSAGE(contains(twice.reason, "duplicate plugin name: a plugin named 'circle-preserving' is already loaded from"),
                twice.reason);
}

TEST_CASE("load_plugins tries each file once, and finds plugins in SUBDIV_PLUGIN_PATH folders") {
  load_example_plugins();
  // Already tried in this process: not tried again.
  CHECK(load_plugins({{plugin_path("subdiv_sqrt2")}, false, false}).empty());

  const fs::path dir = fresh_dir("plugin-path");
  fs::copy_file(plugin_path("test_plugin_no_entry"), dir / "a_not_a_plugin.so");
  fs::copy_file(plugin_path("subdiv_template_plugin"), dir / "b_template.so");
  std::ofstream(dir / "notes.txt") << "not a library\n";
  ::setenv("SUBDIV_PLUGIN_PATH", (dir.string() + ":/no/such/folder").c_str(), 1);
  const auto found = load_plugins({{}, true, false});
  ::unsetenv("SUBDIV_PLUGIN_PATH");
  REQUIRE(found.size() == 2);  // the .so files, in name order; the text file and the missing folder are skipped
  CHECK(found[0].found_by == "SUBDIV_PLUGIN_PATH");
  CHECK_FALSE(found[0].loaded);
  CHECK(contains(found[0].reason, "no entry point"));
  CHECK(found[1].loaded);
  CHECK(found[1].name == "my-plugin");
  CHECK(find_code_scheme("my-scheme") != nullptr);
}
