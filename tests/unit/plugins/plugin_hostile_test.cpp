// Plugins that would crash or hang SubdivKit (issue 33): a half-copied library (dlopen died
// with SIGBUS), a FIFO (dlopen blocked for ever), C++ rules that write rows outside the
// parent level or throw what is not a std::exception.
#include <doctest/doctest.h>

#include <chrono>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <sys/stat.h>

#include "framework/plugin/elf_check.h"
#include "framework/plugin/plugin_api.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"
#include "support/test_meshes.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv;
using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct ScratchFolder {
  fs::path path = fs::temp_directory_path() / ("subdiv_plugin_hostile_" + std::to_string(::getpid()));
  ScratchFolder() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// Registers a one-scheme plugin in this process whose face rule is `face`; returns the
// scheme's name.
std::string register_face_rule(const std::string& name,
                               std::function<void(const CodeRuleInput&, Index, RowWriter&)> face) {
  PluginRegistry registry(name, "/plugins/" + name + ".so");
  SurfaceSchemeSpec spec;
  spec.name = name + "-scheme";
  spec.split = "quad";
  spec.linear = [face](const ParameterValues&) {
    CodeRules rules;
    rules.vertex = [](const CodeRuleInput&, Index v, Context, RowWriter& row) { row.add(v, 1.0); };
    rules.edge = [](const CodeRuleInput& in, Index e, int, Context, RowWriter& row) {
      row.add(in.parent.edge_vertices[2 * e], 0.5);
      row.add(in.parent.edge_vertices[2 * e + 1], 0.5);
    };
    rules.face = face;
    return rules;
  };
  registry.add_surface_scheme(spec);
  registry.commit();
  return spec.name;
}

std::string refine_error(const std::string& scheme) {
  try {
    refine_mesh(cube(), scheme, 1);
  } catch (const Error& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace

TEST_CASE("a half-copied plugin library is refused before dlopen, at any length") {
  const std::string whole = read_bytes(plugin_path("subdiv_sqrt2"));
  REQUIRE(whole.size() > 4096);
  CHECK(!elf_problem(whole));
  ScratchFolder dir;
  for (const std::size_t size : {std::size_t(0), std::size_t(3), std::size_t(63), std::size_t(64), std::size_t(1000),
                                 whole.size() / 3, whole.size() / 2, whole.size() - 1}) {
    CAPTURE(size);
    const fs::path file = dir.path / fmt::format("cut_{}.so", size);
    std::ofstream(file, std::ios::binary).write(whole.data(), std::streamsize(size));
    const PluginStatus s = load_plugin(file);
    CHECK(!s.loaded);
    CHECK((contains(s.reason, "cut off") || contains(s.reason, "no ELF header")));
  }
}

TEST_CASE("a broken library in a plugin folder is skipped with its reason; named explicitly it is refused") {
  ScratchFolder dir;
  const std::string whole = read_bytes(plugin_path("subdiv_sqrt2"));
  std::ofstream(dir.path / "half.so", std::ios::binary).write(whole.data(), std::streamsize(whole.size() / 2));
  const auto statuses = load_plugins({{dir.path.string()}, false, false});
  REQUIRE(statuses.size() == 1);
  CHECK(!statuses[0].loaded);
  CHECK(statuses[0].found_by == "--plugin folder");  // front-ends warn about these, and go on
  CHECK(contains(statuses[0].reason, "cut off"));
}

TEST_CASE("a FIFO named as a plugin is refused at once, not opened") {
  ScratchFolder dir;
  const fs::path fifo = dir.path / "plugin.so";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const auto start = std::chrono::steady_clock::now();
  const PluginStatus s = load_plugin(fifo);
  CHECK(!s.loaded);
  CHECK(contains(s.reason, "not a regular file"));
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
}

TEST_CASE("a C++ rule's row is checked: indices within the parent level, finite weights") {
  const std::string past = register_face_rule("rows-past-end", [](const CodeRuleInput& in, Index, RowWriter& row) {
    row.add(in.parent.vertex_count + 1000, 1.0);
  });
  CHECK(contains(refine_error(past), "plugin 'rows-past-end' (/plugins/rows-past-end.so), scheme 'rows-past-end-scheme'"));
  CHECK(contains(refine_error(past), "adds parent vertex 1008, but the level has 8 vertices (0 to 7)"));
  const std::string negative = register_face_rule("rows-negative", [](const CodeRuleInput&, Index, RowWriter& row) {
    row.add(-5, 1.0);
  });
  CHECK(contains(refine_error(negative), "adds parent vertex -5"));
  const std::string nan = register_face_rule("rows-nan", [](const CodeRuleInput&, Index f, RowWriter& row) {
    row.add(f % 8, std::numeric_limits<double>::quiet_NaN());
  });
  CHECK(contains(refine_error(nan), "the weight nan; weights must be finite"));
}

TEST_CASE("whatever a C++ rule throws becomes a subdiv::Error naming the plugin and the scheme") {
  const std::string odd = register_face_rule("throws-int", [](const CodeRuleInput&, Index, RowWriter&) { throw 42; });
  CHECK(contains(refine_error(odd), "plugin 'throws-int'"));
  CHECK(contains(refine_error(odd), "scheme 'throws-int-scheme'"));
  CHECK(contains(refine_error(odd), "not a std::exception"));
  const std::string std_error = register_face_rule(
      "throws-std", [](const CodeRuleInput&, Index, RowWriter&) { throw std::out_of_range("vector::at"); });
  CHECK(contains(refine_error(std_error), "scheme 'throws-std-scheme': its face rule for face 0 threw an exception: vector::at"));
}
