// `subdiv` with plugins: --plugin on every subcommand (before or after it), `subdiv plugins`
// listing loaded and refused plugins with reasons, `subdiv schemes` showing origins,
// SUBDIV_PLUGIN_PATH, refusals that leave the command working, plugin schemes in refine.
#include <cmath>
#include <cstdlib>
#include <doctest/doctest.h>
#include <fstream>
#include <sstream>

#include "support/cli_runner.h"
#include "framework/plugin/plugin_api.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

// The built `subdiv`, without plugins from the environment or an installed folder.
CliResult run(const std::string& args) {
  ::unsetenv("SUBDIV_PLUGIN_PATH");
  ::setenv("SUBDIV_NO_INSTALLED_PLUGINS", "1", 1);
  return run_subdiv(args);
}

std::string plugin(const std::string& target) { return " --plugin " + plugin_path(target); }

std::vector<double> obj_positions(const fs::path& file) {
  std::ifstream in(file);
  std::vector<double> p;
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("v ", 0) == 0) {
      std::istringstream s(line.substr(2));
      double x, y, z;
      s >> x >> y >> z;
      p.insert(p.end(), {x, y, z});
    }
  return p;
}

}  // namespace

TEST_CASE("subdiv plugins: nothing found, then loaded and refused plugins with their reasons") {
  const CliResult none = run("plugins");
  CHECK(none.exit_code == 0);
  CHECK(contains(none.output, "no plugins found"));

  const CliResult r = run("plugins" + plugin("subdiv_circle_preserving") + plugin("test_plugin_no_entry") +
                          plugin("test_plugin_wrong_version") + plugin("test_plugin_throws") +
                          plugin("test_plugin_duplicate_scheme") + plugin("test_plugin_clash") +
                          plugin("subdiv_sqrt2"));
  // Everything is listed, and the refusal of plugins the user named makes the exit non-zero.
  CHECK(r.exit_code == 1);
  INFO(r.output);
  CHECK(contains(r.output, "a plugin given with --plugin was refused"));
  CHECK(contains(r.output, "loaded   circle-preserving 1.0.0  " + plugin_path("subdiv_circle_preserving") + " (--plugin)"));
  CHECK(contains(r.output, "curve scheme circle-four-point (non-linear, C++)"));
  CHECK(contains(r.output, "loaded   sqrt2 1.0.0  " + plugin_path("subdiv_sqrt2")));
  CHECK(contains(r.output, "splitter sqrt2"));
  CHECK(contains(r.output, "refused  " + plugin_path("test_plugin_no_entry") + " (--plugin)\n           reason: no entry point"));
  CHECK(contains(r.output, "refused  future-plugin 9.9.9  " + plugin_path("test_plugin_wrong_version")));
  CHECK(contains(r.output, "reason: interface version mismatch"));
  CHECK(contains(r.output, "reason: its registration threw: the test plugin fails on purpose"));
  CHECK(contains(r.output, "reason: duplicate scheme name 'catmull-clark'"));
  CHECK(contains(r.output, "reason: duplicate scheme name 'circle-four-point': plugin circle-preserving already defines it"));

  const CliResult verbose = run("plugins -v");
  CHECK(contains(verbose.output, "plugin interface " + std::to_string(SUBDIV_PLUGIN_INTERFACE_VERSION)));
  CHECK(contains(verbose.output, "installed plugin folder: "));
}

TEST_CASE("--plugin works before and after the subcommand; subdiv schemes shows where schemes come from") {
  const CliResult before = run("--plugin " + plugin_path("subdiv_kobbelt_quad") + " schemes");
  CHECK(before.exit_code == 0);
  CHECK(contains(before.output, "[plugin kobbelt-quad]"));
  const CliResult after = run("schemes" + plugin("subdiv_kobbelt_quad") + plugin("subdiv_circle_preserving"));
  CHECK(after.exit_code == 0);
  INFO(after.output);
  CHECK(contains(after.output, "kobbelt-quad"));
  CHECK(contains(after.output, "circle-four-point      [plugin circle-preserving]"));
  CHECK(contains(after.output, "catmull-clark          [built-in]"));
  CHECK(contains(after.output, "--param w=<number>  (default 0.0625) tension of the 4-point rule"));
  const CliResult plain = run("schemes");
  CHECK_FALSE(contains(plain.output, "[plugin"));
}

TEST_CASE("SUBDIV_PLUGIN_PATH: files and folders are searched") {
  const auto dir = fresh_dir("cli-plugin-path");
  fs::copy_file(plugin_path("subdiv_sqrt2"), dir / "sqrt2.so");
  ::setenv("SUBDIV_NO_INSTALLED_PLUGINS", "1", 1);
  ::setenv("SUBDIV_PLUGIN_PATH", (dir.string() + ":" + plugin_path("subdiv_kobbelt_quad")).c_str(), 1);
  const CliResult r = run_subdiv("plugins");
  ::unsetenv("SUBDIV_PLUGIN_PATH");
  INFO(r.output);
  CHECK(contains(r.output, "loaded   sqrt2 1.0.0  " + (dir / "sqrt2.so").string() + " (SUBDIV_PLUGIN_PATH)"));
  CHECK(contains(r.output, "loaded   kobbelt-quad 1.0.0  " + plugin_path("subdiv_kobbelt_quad") + " (SUBDIV_PLUGIN_PATH)"));
}

TEST_CASE("refine --normals with a plugin split's scheme that is not C1: the advice names the mesh and --plugin") {
  // The sqrt2 plugin's scheme keeping 0.9 of the vertex: not C1 at regular vertices. The
  // refusal's `subdiv analyze` must load the plugin, or the split is unknown there.
  const auto dir = fresh_dir("cli-plugin-not-c1");
  const std::string torus = source_path("examples/meshes/torus-quads.obj");
  std::ofstream(dir / "stiff-sqrt2.json") << R"({"name": "stiff-sqrt2", "split": "sqrt2", "curve": "cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "vertex": [{"at": "self", "w": "0.9"}, {"sum": "faces", "new": "face", "w": "0.1/n"}],
              "edge": [{"sum": "ends", "w": "1/2"}]}})";
  const std::string json = (dir / "stiff-sqrt2.json").string();
  const fs::path out = dir / "out.vtp";
  const CliResult r =
      run("refine " + torus + plugin("subdiv_sqrt2") + " -s " + json + " -l 2 --normals -o " + out.string());
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "subdiv: error: " + torus + ": scheme 'stiff-sqrt2' is not C1"));
  const std::string advice = "subdiv analyze" + plugin("subdiv_sqrt2") + " " + json;
  CHECK(contains(r.output, "`" + advice + "`"));
  CHECK_FALSE(fs::exists(out));
  // The advice runs as written.
  const CliResult analyze = run(advice.substr(std::string("subdiv ").size()) + " --valence 4");
  CHECK_MESSAGE(analyze.exit_code == 0, analyze.output);
  CHECK(contains(analyze.output, "0 of 1 valences C1"));
}

TEST_CASE("refine with plugin schemes; a refused plugin found by search is a warning and the others work") {
  const auto dir = fresh_dir("cli-plugin-refine");
  const std::string cube = source_path("examples/meshes/cube.obj");

  const CliResult missing = run("refine " + cube + " --scheme sqrt2 -o " + (dir / "no.obj").string());
  CHECK(missing.exit_code != 0);
  CHECK(contains(missing.output, "unknown scheme 'sqrt2'"));

  const auto out = dir / "cube-sqrt2.obj";
  ::setenv("SUBDIV_NO_INSTALLED_PLUGINS", "1", 1);
  ::setenv("SUBDIV_PLUGIN_PATH", plugin_path("test_plugin_throws").c_str(), 1);
  const CliResult r = run_subdiv("refine " + cube + plugin("subdiv_sqrt2") + " --scheme sqrt2 --levels 3 -o " + out.string());
  ::unsetenv("SUBDIV_PLUGIN_PATH");
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(contains(r.output, "subdiv: warning: plugin " + plugin_path("test_plugin_throws") +
                               " refused: its registration threw: the test plugin fails on purpose"));
  CHECK(obj_positions(out).size() == 3 * 50);  // 8 + 6 + 12 + 24 vertices

  // A JSON file naming the plugin's split: unknown without the plugin, fine with it.
  std::ofstream(dir / "sqrt2-linear.json") << R"({"name": "sqrt2-linear", "split": "sqrt2", "curve": "two-point",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}], "vertex": [{"at": "self", "w": "1"}]}})";
  const std::string json = (dir / "sqrt2-linear.json").string();
  const CliResult unknown = run("refine " + cube + " --scheme " + json + " -o " + (dir / "no.obj").string());
  CHECK(unknown.exit_code != 0);
  CHECK(contains(unknown.output, "unknown split 'sqrt2'"));
  CHECK(run("validate " + json + plugin("subdiv_sqrt2")).exit_code == 0);
  CHECK(run("refine " + cube + " --scheme " + json + plugin("subdiv_sqrt2") + " -q -o " + (dir / "j.obj").string())
            .exit_code == 0);
}

TEST_CASE("refine a torus with the non-linear circle-quad: the output stays on the torus") {
  const auto dir = fresh_dir("cli-circle-quad");
  const double pi = std::acos(-1.0), R = 2.0, r = 0.5;
  const int nu = 16, nv = 8;
  {
    std::ofstream obj(dir / "torus.obj");
    obj.precision(17);
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
        obj << "v " << (R + r * std::cos(v)) * std::cos(u) << " " << (R + r * std::cos(v)) * std::sin(u) << " "
            << r * std::sin(v) << "\n";
      }
    auto id = [&](int i, int j) { return ((j + nv) % nv) * nu + (i + nu) % nu + 1; };
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i)
        obj << "f " << id(i, j) << " " << id(i + 1, j) << " " << id(i + 1, j + 1) << " " << id(i, j + 1) << "\n";
  }
  const auto out = dir / "torus-3.obj";
  const CliResult res = run("refine " + (dir / "torus.obj").string() + plugin("subdiv_circle_preserving") +
                            " --scheme circle-quad --levels 3 -o " + out.string());
  INFO(res.output);
  REQUIRE(res.exit_code == 0);
  const auto p = obj_positions(out);
  CHECK(p.size() == 3 * size_t(nu * nv * 64));
  double worst = 0;
  for (size_t i = 0; i < p.size(); i += 3) worst = std::max(worst, torus_error(&p[i], R, r));
  CHECK(worst < 1e-12);
  // A triangle mesh is refused with the scheme's requirement.
  const CliResult tri = run("refine " + source_path("examples/meshes/octahedron.obj") + plugin("subdiv_circle_preserving") +
                            " --scheme circle-quad -o " + (dir / "no.obj").string());
  CHECK(tri.exit_code != 0);
  CHECK(contains(tri.output, "scheme 'circle-quad' needs quads"));
}

TEST_CASE("subdiv refine runs a non-linear plugin curve scheme on polylines: points stay on the circle") {
  const auto dir = subdiv::test::fresh_dir("plugin-curve-cli");
  const auto out = dir / "circle.obj";
  const auto r = subdiv::test::run_subdiv("refine " + subdiv::test::source_path("examples/curves/circle8.obj") +
                                          " --plugin " + plugin_path("subdiv_circle_preserving") +
                                          " --scheme circle-four-point -l 6 -o " + out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  std::ifstream in(out);
  int points = 0;
  double worst = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) != 0) continue;
    double x, y, z;
    std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z);
    worst = std::max(worst, std::abs(std::sqrt(x * x + y * y + z * z) - 1.0));
    ++points;
  }
  CHECK(points == 8 * 64);
  CHECK(worst < 1e-12);
}

TEST_CASE("validate takes a plugin's scheme by name: C++ rules are reported as skipped, exit 0") {
  const CliResult r = run("validate circle-quad" + plugin("subdiv_circle_preserving"));
  CHECK(r.exit_code == 0);
  CHECK(contains(r.output, "circle-quad: skipped (surface scheme 'circle-quad'"));
  CHECK(run("validate sqrt2" + plugin("subdiv_sqrt2")).exit_code == 0);
}
