// Test fixture: a plugin whose splitter registers fine but whose scheme does not load (it
// names a curve scheme that does not exist). The whole plugin must be refused and its
// splitter must not stay registered.
#include "framework/plugin/plugin_api.h"
#include "framework/refine/splitter.h"

namespace {
void register_partial(subdiv::PluginRegistry& registry) {
  subdiv::SplitterInfo split;
  split.name = "partial-split";
  split.split = [](const subdiv::Level& parent, int) { return subdiv::split_quad(parent); };
  split.rule_elements = {subdiv::OriginKind::Vertex, subdiv::OriginKind::Edge, subdiv::OriginKind::Face};
  registry.add_splitter(split);
  subdiv::SurfaceSchemeSpec scheme;
  scheme.name = "partial-scheme";
  scheme.split = "partial-split";
  scheme.curve = "no-such-curve";
  scheme.linear = [](const subdiv::ParameterValues&) {
    subdiv::CodeRules rules;
    rules.vertex = [](const subdiv::CodeRuleInput&, subdiv::Index v, subdiv::Context, subdiv::RowWriter& row) {
      row.add(v, 1.0);
    };
    return rules;
  };
  registry.add_surface_scheme(scheme);
}
}  // namespace

SUBDIV_PLUGIN("partial", "1.0.0", register_partial)
