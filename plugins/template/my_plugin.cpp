// A SubdivKit plugin template: one linear surface scheme whose rules are C++ code.
// Rename "my-plugin" and "my-scheme", then replace the rules with your own.
//
// Linear rules write stencil rows: for each new point, add (parent vertex, weight) pairs
// whose weights sum to 1. The engine turns them into stencil tables, so the scheme gets
// composition, analysis and the parallel apply like the built-in JSON schemes. Boundaries
// and creases follow the curve scheme named in `curve`.
#include "framework/plugin/plugin_api.h"

namespace {

using subdiv::CodeRuleInput;
using subdiv::Context;
using subdiv::Index;
using subdiv::RowWriter;

// The rules for one set of parameter values (called once per loaded scheme).
subdiv::CodeRules my_rules(const subdiv::ParameterValues& parameters) {
  const double s = parameters.number("s");  // how far old vertices move to their neighbours
  subdiv::CodeRules rules;
  // New point of face f: its centroid.
  rules.face = [](const CodeRuleInput& in, Index f, RowWriter& row) {
    const auto corners = in.parent.face(f);
    for (Index v : corners) row.add(v, 1.0 / double(corners.size()));
  };
  // New point of edge e: its midpoint.
  rules.edge = [](const CodeRuleInput& in, Index e, int, Context, RowWriter& row) {
    row.add(in.parent.edge_vertices[2 * e], 0.5);
    row.add(in.parent.edge_vertices[2 * e + 1], 0.5);
  };
  // New point of vertex v: (1 - s) v + s (mean of its ring neighbours).
  rules.vertex = [s](const CodeRuleInput& in, Index v, Context, RowWriter& row) {
    const auto ring = in.parent.ring_edges(v);
    row.add(v, 1.0 - s);
    for (Index e : ring) row.add(in.parent.other_end(e, v), s / double(ring.size()));
  };
  return rules;
}

void register_my_plugin(subdiv::PluginRegistry& registry) {
  subdiv::SurfaceSchemeSpec scheme;
  scheme.name = "my-scheme";
  scheme.description = "template plugin: face centroids, edge midpoints, vertices moved s of the way to their ring";
  scheme.split = "quad";          // a built-in splitter (or one a plugin registers)
  scheme.curve = "two-point";     // boundaries and creases: linear interpolation
  scheme.parameters.push_back(subdiv::number_parameter("s", 0.25, "vertex smoothing, 0 = bilinear", 0.0, 1.0));
  scheme.linear = my_rules;
  registry.add_surface_scheme(std::move(scheme));
}

}  // namespace

// The entry point SubdivKit looks for: plugin name, plugin version, registration function.
SUBDIV_PLUGIN("my-plugin", "0.1.0", register_my_plugin)
