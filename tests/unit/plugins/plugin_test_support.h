#pragma once
// Plugin tests: where the built plugins are, and loading the example plugins once per test
// process (plugin registries are process-wide, as in `subdiv`).
#include <cmath>
#include <doctest/doctest.h>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "framework/plugin/plugin_loader.h"

namespace subdiv::test {

// A plugin built in-tree (plugins/CMakeLists.txt), by target name.
inline std::string plugin_path(const std::string& target) {
  return std::string(SUBDIV_BINARY_DIR) + "/plugins/" + target + ".so";
}

inline void load_example_plugins() {
  static const bool loaded = [] {
    for (const char* target : {"subdiv_circle_preserving", "subdiv_sqrt2", "subdiv_kobbelt_quad"}) {
      const PluginStatus s = load_plugin(plugin_path(target));
      if (!s.loaded) throw std::runtime_error(s.file + ": " + s.reason);
    }
    return true;
  }();
  (void)loaded;
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Distance of p from the torus with radii R (tube centre circle in the xy plane) and r.
inline double torus_error(const double* p, double R, double r) {
  const double rho = std::hypot(p[0], p[1]) - R;
  return std::abs(std::hypot(rho, p[2]) - r);
}

}  // namespace subdiv::test
