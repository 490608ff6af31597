// load_plugin: a plugin library registers its schemes, splitters and roles in this process.
#include <filesystem>
#include <fmt/format.h>

#include "bindings.h"

namespace subdivkit {
namespace {

// The library refuses a second load of a plugin (its name is taken by then); a notebook
// cell run twice should not fail, so the first load's status is returned instead.
subdiv::PluginStatus already_loaded(const std::string& path) {
  std::error_code ec;
  for (const auto& s : subdiv::plugin_statuses())
    if (s.loaded && std::filesystem::equivalent(s.file, path, ec)) return s;
  return {};
}

}  // namespace

void bind_plugins(py::module_& m) {
  m.def(
      "load_plugin",
      [](const std::string& path) {
        subdiv::PluginStatus s = already_loaded(path);
        if (s.file.empty()) {
          py::gil_scoped_release unlocked;
          s = subdiv::load_plugin(path, "load_plugin");
        }
        if (!s.loaded) throw subdiv::Error(fmt::format("plugin {} refused: {}", s.file, s.reason));
        py::dict d;
        d["name"] = s.name, d["version"] = s.version, d["file"] = s.file, d["provides"] = s.provides;
        return d;
      },
      py::arg("path"),
      R"doc(Load a SubdivKit plugin (a shared library, docs/plugins.md) into this process.

Its schemes then load by name with Scheme.load and appear in schemes(). Returns a dict with
the plugin's name, version, file and what it provides (one line each). A faulty plugin
(not a plugin, built for another interface version, a name that is taken) raises
subdivkit.Error with the reason and leaves nothing registered. Loading the same file again
returns its first result. Plugins are native code: load only plugins you trust.)doc");
}

}  // namespace subdivkit
