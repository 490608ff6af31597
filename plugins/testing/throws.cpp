// Test fixture: a plugin whose registration throws after adding a scheme. It must be
// refused with the exception's message, and the scheme must not appear.
#include <stdexcept>

#include "framework/plugin/plugin_api.h"

namespace {
void register_throwing(subdiv::PluginRegistry& registry) {
  subdiv::SurfaceSchemeSpec scheme;
  scheme.name = "never-registered";
  scheme.linear = [](const subdiv::ParameterValues&) { return subdiv::CodeRules{}; };
  registry.add_surface_scheme(scheme);
  throw std::runtime_error("the test plugin fails on purpose");
}
}  // namespace

SUBDIV_PLUGIN("throws-on-register", "1.0.0", register_throwing)
