// Linear schemes written in C++: the plugin produces stencil rows, so its schemes get what
// every JSON scheme gets (stencil tables, composition, analysis, the parallel apply).
//
// Registered:
//  - surface scheme "kobbelt-quad": L. Kobbelt, "Interpolatory subdivision on open
//    quadrilateral nets with arbitrary topology", Computer Graphics Forum 15(3) (1996).
//    Old vertices stay. An edge point is the four-point rule (-w, 1/2 + w, 1/2 + w, -w)
//    along the mesh line through the edge; a face point is the four-point rule across the
//    face through the new points of its opposite edges, averaged over the two directions
//    (on a regular grid both give the tensor-product point). Where a line stops (boundary,
//    extraordinary vertex) the missing point is extrapolated linearly, P = 2 B - C, as
//    Kobbelt does. The rows need the mesh lines, which the JSON roles cannot express;
//  - curve scheme "dubuc-deslauriers": the interpolatory 2m-point scheme of Dubuc and
//    Deslauriers for any m (m = 2 is the four-point scheme with w = 1/16, m = 3 the
//    six-point scheme): the weights are the Lagrange basis at 1/2, computed in C++. It is
//    linear, so it serves as kobbelt-quad's boundary curve and the curve analysis can
//    take its rules;
//  - rule role "line" for edge rules: the four points along the mesh line through an edge
//    (j = 0 before the first end, 1 and 2 the ends, 3 after the second end; where the line
//    stops the end itself stands in). JSON schemes can use it once the plugin is loaded.
#include <vector>

#include "framework/plugin/mesh_lines.h"
#include "framework/plugin/plugin_api.h"
#include "framework/util/error.h"

namespace {

using subdiv::Index;
using subdiv::kNone;

// A short row: parent vertex and weight pairs.
using Terms = std::vector<std::pair<Index, double>>;

void add(Terms& t, const Terms& other, double scale) {
  for (const auto& [v, w] : other) t.emplace_back(v, scale * w);
}

// The four-point rule along edge e: -w A + (1/2 + w)(a + b) - w D, A and D the vertices
// beyond the ends on the edge's line or, where the line stops, extrapolated (2a - b).
Terms edge_terms(const subdiv::CodeRuleInput& in, Index e, double w) {
  const subdiv::Level& L = in.parent;
  const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
  Terms t{{a, 0.5 + w}, {b, 0.5 + w}};
  for (auto [end, other] : {std::pair{a, b}, std::pair{b, a}}) {
    const Index beyond = subdiv::vertex_beyond(L, in.features, e, end);
    if (beyond != kNone) t.emplace_back(beyond, -w);
    else t.emplace_back(end, -2 * w), t.emplace_back(other, w);
  }
  return t;
}

// The four-point rule across quad f through the new points of edges e0 and e2 (opposite).
Terms across_terms(const subdiv::CodeRuleInput& in, Index f, Index e0, Index e2, double w) {
  const Terms B = edge_terms(in, e0, w), C = edge_terms(in, e2, w);
  Terms t;
  add(t, B, 0.5 + w);
  add(t, C, 0.5 + w);
  for (auto [e, near, far] : {std::tuple{e0, &B, &C}, std::tuple{e2, &C, &B}}) {
    const Index beyond = subdiv::parallel_edge_across(in.parent, in.features, f, e);
    if (beyond != kNone) add(t, edge_terms(in, beyond, w), -w);
    else add(t, *near, -2 * w), add(t, *far, w);
  }
  return t;
}

subdiv::CodeRules kobbelt_rules(const subdiv::ParameterValues& p) {
  const double w = p.number("w");
  subdiv::CodeRules rules;
  rules.vertex = [](const subdiv::CodeRuleInput&, Index v, subdiv::Context, subdiv::RowWriter& row) { row.add(v, 1.0); };
  rules.edge = [w](const subdiv::CodeRuleInput& in, Index e, int, subdiv::Context, subdiv::RowWriter& row) {
    for (const auto& [v, weight] : edge_terms(in, e, w)) row.add(v, weight);
  };
  rules.face = [w](const subdiv::CodeRuleInput& in, Index f, subdiv::RowWriter& row) {
    if (in.parent.face_size(f) != 4) throw subdiv::Error("kobbelt-quad refines quads only");
    const auto edges = in.parent.face_edge_list(f);
    for (int dir = 0; dir < 2; ++dir)
      for (const auto& [v, weight] : across_terms(in, f, edges[dir], edges[dir + 2], w)) row.add(v, 0.5 * weight);
  };
  return rules;
}

// Dubuc-Deslauriers 2m-point scheme: old points stay (rule 0); the new point between old
// points 0 and 1 is the degree 2m-1 interpolant through points -m+1 .. m evaluated at 1/2.
subdiv::CurveRulesSpec dubuc_deslauriers(const subdiv::ParameterValues& p) {
  const double m_value = p.number("m");
  const int m = int(m_value);
  if (m != m_value) throw subdiv::Error("dubuc-deslauriers: m must be a whole number");
  subdiv::CurveRulesSpec rules;
  rules.arity = 2;
  rules.starts = {0, -(m - 1)};
  std::vector<double> odd;
  for (int i = -(m - 1); i <= m; ++i) {
    double l = 1.0;  // Lagrange basis polynomial of node i at t = 1/2
    for (int k = -(m - 1); k <= m; ++k)
      if (k != i) l *= (0.5 - k) / double(i - k);
    odd.push_back(l);
  }
  rules.weights = {{1.0}, odd};
  return rules;
}

void register_kobbelt_quad(subdiv::PluginRegistry& registry) {
  subdiv::CurveSchemeSpec dd;
  dd.name = "dubuc-deslauriers";
  dd.description = "interpolatory 2m-point scheme (Dubuc, Deslauriers); m = 2 is the 4-point scheme, m = 3 six-point";
  dd.parameters.push_back(subdiv::number_parameter("m", 2, "points on each side of a new point", 1, 8));
  dd.linear = dubuc_deslauriers;
  registry.add_curve_scheme(std::move(dd));

  subdiv::SurfaceSchemeSpec quad;
  quad.name = "kobbelt-quad";
  quad.description = "Kobbelt's interpolatory 4-point quad scheme (linear, C++ rules; quads only)";
  quad.split = "quad";
  quad.required_face_size = 4;
  quad.curve = "dubuc-deslauriers";
  quad.parameters.push_back(subdiv::number_parameter("w", 1.0 / 16, "tension of the 4-point rule", 0, 0.2));
  quad.linear = kobbelt_rules;
  registry.add_surface_scheme(std::move(quad));

  subdiv::RoleInfo line;
  line.name = "line";
  line.description = "edge rules: the 4 points on the mesh line through the edge (the end stands in where it stops)";
  line.element = subdiv::Element::Edge;
  line.max_points = [](int, int) { return 4; };
  line.points = [](const subdiv::Level& L, Index e, int, std::vector<Index>& points) {
    // No feature contexts here: lines continue through regular interior vertices only.
    const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
    auto beyond = [&](Index end) {
      if (L.on_boundary(end) || L.valence(end) != 4) return end;
      const auto ring = L.ring_edges(end);
      for (int i = 0; i < 4; ++i)
        if (ring[i] == e) return L.other_end(ring[(i + 2) % 4], end);
      return end;
    };
    points.insert(points.end(), {beyond(a), a, b, beyond(b)});
  };
  registry.add_role(std::move(line));
}

}  // namespace

SUBDIV_PLUGIN("kobbelt-quad", "1.0.0", register_kobbelt_quad)
