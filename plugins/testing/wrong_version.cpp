// Test fixture: a plugin that claims to be built for another plugin interface. It must be
// refused before its registration function is called.
#include <stdexcept>

#include "framework/plugin/plugin_api.h"

namespace {
void never_called(subdiv::PluginRegistry&) { throw std::logic_error("a refused plugin's registration ran"); }
}  // namespace

SUBDIV_PLUGIN_EXPORT const SubdivPluginInfo* subdiv_plugin_info(void) {
  static const SubdivPluginInfo info{SUBDIV_PLUGIN_INTERFACE_VERSION + 98, "future-plugin", "9.9.9", "9.0.0",
                                     never_called};
  return &info;
}
