// A plugin the user names with --plugin and that is refused makes the command fail:
// the run would not be what they asked for. Plugins found by search stay warnings
// (plugins_cli_test.cpp).
#include <cstdlib>
#include <doctest/doctest.h>
#include <filesystem>

#include "support/cli_runner.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

TEST_CASE("refine with a refused --plugin exits non-zero, names the plugin and writes nothing") {
  ::unsetenv("SUBDIV_PLUGIN_PATH");
  ::setenv("SUBDIV_NO_INSTALLED_PLUGINS", "1", 1);
  const auto dir = fresh_dir("plugin-refusal");
  const std::string cube = source_path("examples/meshes/cube.obj");
  for (const std::string target : {"test_plugin_throws", "test_plugin_wrong_version", "test_plugin_no_entry"}) {
    const CliResult r = run_subdiv("refine " + cube + " --plugin " + plugin_path(target) + " -o " +
                                   (dir / "out.obj").string());
    INFO(target, r.output);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, "subdiv: error: a plugin given with --plugin was refused:\n  " + plugin_path(target)));
    CHECK_FALSE(fs::exists(dir / "out.obj"));
  }
  const CliResult missing = run_subdiv("schemes --plugin " + (dir / "nowhere.so").string());
  CHECK(missing.exit_code == 1);
  CHECK(contains(missing.output, (dir / "nowhere.so").string()));
}

TEST_CASE("refine with a plugin whose splitter or role is broken exits 1 naming the plugin file, writes nothing") {
  ::unsetenv("SUBDIV_PLUGIN_PATH");
  ::setenv("SUBDIV_NO_INSTALLED_PLUGINS", "1", 1);
  const auto dir = fresh_dir("plugin-broken-topology");
  const std::string cube = source_path("examples/meshes/cube.obj");
  const std::string plugin = plugin_path("test_plugin_broken_topology");
  const CliResult split = run_subdiv("refine " + cube + " -s broken-split-scheme --plugin " + plugin + " -o " +
                                     (dir / "out.obj").string());
  INFO(split.output);
  CHECK(split.exit_code == 1);
  CHECK(contains(split.output, "plugin 'broken-topology' (" + plugin + "), splitter 'broken-split': its split "
                               "function (step 0) returned a child level that cannot be used: face_vertices[95] is"));
  CHECK_FALSE(fs::exists(dir / "out.obj"));
  const CliResult role = run_subdiv("refine " + cube + " -s broken-role-scheme --plugin " + plugin + " -o " +
                                    (dir / "out.obj").string());
  INFO(role.output);
  CHECK(role.exit_code == 1);
  CHECK(contains(role.output, "plugin 'broken-topology' (" + plugin + "), role 'broken-role': its points function "
                              "(element 0) threw something that is not a std::exception"));
  CHECK_FALSE(fs::exists(dir / "out.obj"));
}
