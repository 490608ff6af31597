// Test fixture: a plugin that loads fine but whose splitter writes a child face past the
// child's vertices and whose role throws an int. Refining with either must end in a message
// naming this file and the function, never in a crash (issue 33).
#include "framework/plugin/plugin_api.h"
#include "framework/refine/splitter.h"

namespace {
subdiv::CodeRules rules() {
  subdiv::CodeRules r;
  r.vertex = [](const subdiv::CodeRuleInput&, subdiv::Index v, subdiv::Context, subdiv::RowWriter& row) {
    row.add(v, 1.0);
  };
  r.edge = [](const subdiv::CodeRuleInput& in, subdiv::Index e, int, subdiv::Context, subdiv::RowWriter& row) {
    row.add(in.parent.edge_vertices[2 * e], 0.5);
    row.add(in.parent.edge_vertices[2 * e + 1], 0.5);
  };
  r.face = [](const subdiv::CodeRuleInput& in, subdiv::Index f, subdiv::RowWriter& row) {
    for (subdiv::Index v : in.parent.face(f)) row.add(v, 1.0 / in.parent.face_size(f));
  };
  r.handles_features = true;
  return r;
}

void register_broken(subdiv::PluginRegistry& registry) {
  subdiv::SplitterInfo split;
  split.name = "broken-split";
  split.split = [](const subdiv::Level& parent, int) {
    subdiv::SplitResult r = subdiv::split_quad(parent);
    r.child.face_vertices.back() = r.child.vertex_count + 100000;
    return r;
  };
  split.rule_elements = {subdiv::OriginKind::Vertex, subdiv::OriginKind::Edge, subdiv::OriginKind::Face};
  registry.add_splitter(split);
  subdiv::SurfaceSchemeSpec scheme;
  scheme.name = "broken-split-scheme";
  scheme.split = "broken-split";
  scheme.linear = [](const subdiv::ParameterValues&) { return rules(); };
  registry.add_surface_scheme(scheme);

  subdiv::RoleInfo role;
  role.name = "broken-role";
  role.element = subdiv::Element::Edge;
  role.max_points = [](int, int) { return 2; };
  role.points = [](const subdiv::Level&, subdiv::Index, int, std::vector<subdiv::Index>&) { throw 42; };
  registry.add_role(role);
  registry.add_json_scheme(R"({"name": "broken-role-scheme", "split": "quad", "curve": "cubic-bspline",
    "rules": {"vertex": [{"at": "self", "w": "1"}], "edge": [{"sum": "broken-role", "w": "1/2"}],
              "face": [{"sum": "vertices", "w": "1/k"}]}})");
}
}  // namespace

SUBDIV_PLUGIN("broken-topology", "1.0.0", register_broken)
