// Test fixture: a plugin that registers a scheme whose name is taken: "catmull-clark" (a
// built-in scheme file) or, with -DCLASH_WITH_PLUGIN, "circle-four-point" (the
// circle-preserving plugin's). It must be refused naming the scheme and its owner.
#include "framework/plugin/plugin_api.h"

namespace {
void register_duplicate(subdiv::PluginRegistry& registry) {
  subdiv::SurfaceSchemeSpec scheme;
#ifdef CLASH_WITH_PLUGIN
  subdiv::CurveSchemeSpec curve;
  curve.name = "circle-four-point";
  curve.linear = [](const subdiv::ParameterValues&) { return subdiv::CurveRulesSpec{2, {0, 0}, {{1.0}, {0.5, 0.5}}}; };
  registry.add_curve_scheme(curve);
#else
  scheme.name = "catmull-clark";
  scheme.linear = [](const subdiv::ParameterValues&) {
    subdiv::CodeRules rules;
    rules.vertex = [](const subdiv::CodeRuleInput&, subdiv::Index v, subdiv::Context, subdiv::RowWriter& row) {
      row.add(v, 1.0);
    };
    return rules;
  };
  registry.add_surface_scheme(scheme);
#endif
}
}  // namespace

#ifdef CLASH_WITH_PLUGIN
SUBDIV_PLUGIN("clashes-with-circle", "1.0.0", register_duplicate)
#else
SUBDIV_PLUGIN("duplicate-scheme", "1.0.0", register_duplicate)
#endif
