#include "framework/engine/vertex_parameters.h"

#include <cmath>
#include <fmt/format.h>

#include "framework/scheme/step_tables.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

const ParameterSpec* find_parameter(const Scheme& scheme, const std::string& name) {
  for (const ParameterSpec& p : scheme.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

// The names `scheme` declares per vertex and `values` gives, in map order.
std::vector<std::string> read_here(const Scheme& scheme, const VertexParameters& values) {
  std::vector<std::string> names;
  for (const auto& [name, per_vertex] : values)
    if (const ParameterSpec* p = find_parameter(scheme, name); p && p->per_vertex) names.push_back(name);
  return names;
}

std::string declared_by(std::span<const SchemeRun> runs, const std::string& name) {
  std::string plain;
  for (const SchemeRun& run : runs)
    if (const ParameterSpec* p = find_parameter(*run.scheme, name); p && !p->per_vertex)
      plain = fmt::format(" ({} has a parameter {}, but not per vertex: its file does not say \"per_vertex\": true)",
                          subdiv::quoted(run.scheme->name), subdiv::quoted(name));
  return plain;
}

}  // namespace

void check_vertex_parameters(std::span<const SchemeRun> runs, const Level& base, const VertexParameters& values) {
  for (const auto& [name, per_vertex] : values) {
    bool declared = false;
    for (const SchemeRun& run : runs) {
      const ParameterSpec* p = find_parameter(*run.scheme, name);
      if (!p || !p->per_vertex) continue;
      declared = true;
      if (per_vertex.size() != size_t(base.vertex_count))
        throw Error(fmt::format("per-vertex parameter {}: {} values for a mesh of {} vertices; give one per vertex, "
                                "in vertex order", subdiv::quoted(name), per_vertex.size(), base.vertex_count));
      for (size_t v = 0; v < per_vertex.size(); ++v)
        if (auto why = range_violation(*p, per_vertex[v]); !why.empty())
          throw Error(fmt::format("per-vertex parameter {} (vertex {}): {} in scheme {}", subdiv::quoted(name), v, why,
                                  subdiv::quoted(run.scheme->name)));
    }
    if (!declared)
      throw Error(fmt::format("per-vertex parameter {}: no scheme of the run reads it per vertex{}", subdiv::quoted(name),
                              declared_by(runs, name)));
  }
}

VertexParameters carry_vertex_parameters(const Level& parent, const ChildOrigins& origins,
                                         const VertexParameters& values) {
  VertexParameters out;
  for (const auto& [name, at] : values) {
    std::vector<double>& child = out[name];
    child.resize(origins.kind.size());
    for (size_t c = 0; c < origins.kind.size(); ++c) {
      const Index p = origins.parent[c];
      switch (origins.kind[c]) {
        case OriginKind::Vertex: child[c] = at[p]; break;
        case OriginKind::Edge: child[c] = 0.5 * (at[parent.edge_vertices[2 * p]] + at[parent.edge_vertices[2 * p + 1]]); break;
        case OriginKind::Face: {
          double sum = 0;
          for (Index v : parent.face(p)) sum += at[v];
          child[c] = sum / parent.face_size(p);
          break;
        }
        case OriginKind::Corner: child[c] = at[parent.face(p)[origins.local[c]]]; break;
      }
    }
  }
  return out;
}

std::unique_ptr<PerVertexTables> per_vertex_tables(const Scheme& scheme, const StepRules& step, const Level& parent,
                                                   const VertexParameters& values, int max_n, int max_k, int level) {
  const std::vector<std::string> names = read_here(scheme, values);
  if (names.empty()) return nullptr;
  // Only the vertex rules read per-vertex parameters (the loader refuses them elsewhere).
  StepRules vertex_only = step;
  for (int e = 0; e < kElementCount; ++e)
    if (Element(e) != Element::Vertex)
      for (auto& rule : vertex_only.rules[e]) rule.reset();
  auto out = std::make_unique<PerVertexTables>();
  out->group.resize(size_t(parent.vertex_count));
  std::map<std::vector<double>, std::uint32_t> group_of;
  std::vector<double> key(names.size());
  for (Index v = 0; v < parent.vertex_count; ++v) {
    for (size_t i = 0; i < names.size(); ++i) key[i] = values.at(names[i])[v];
    auto [it, added] = group_of.emplace(key, std::uint32_t(group_of.size()));
    out->group[v] = it->second;
    if (!added) continue;
    std::map<std::string, double> parameters = scheme.parameter_values();
    for (size_t i = 0; i < names.size(); ++i) parameters[names[i]] = key[i];
    out->tables.push_back(step_weight_tables(scheme, vertex_only, max_n, max_k, level, &parameters));
  }
  return out;
}

}  // namespace subdiv
