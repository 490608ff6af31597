#include "framework/plugin/plugin_registry.h"

#include <cmath>
#include <fmt/format.h>
#include <set>

#include "framework/plugin/checked_rules.h"
#include "framework/plugin/checked_topology.h"
#include "framework/scheme/json_source.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

struct PluginRegistry::Staged {
  std::vector<SplitterInfo> splitters;
  std::vector<RoleInfo> roles;
  std::vector<SurfaceSchemeSpec> surfaces;
  std::vector<CurveSchemeSpec> curves;
  std::vector<std::string> json;
};

namespace {

ParameterValues values_of(const std::vector<ParameterSpec>& params) {
  ParameterValues v;
  for (const auto& p : params) p.is_choice ? void(v.choices[p.name] = p.choice) : void(v.numbers[p.name] = p.value);
  return v;
}

void check_unknown(const ParameterOverrides& overrides, const std::set<std::string>& used, const std::string& label) {
  for (const auto& [name, value] : overrides)
    if (!used.count(name))
      throw OptionError(fmt::format("{}: the scheme has no parameter {} (from {{param}} {}={}); {{scheme_list}} "
                                    "lists each scheme's parameters",
                                    label, subdiv::quoted(name), name, value));
}

// The boundary curve must be linear and refine boundaries the way the split does.
void check_curve_fits(const CurveScheme& c, SplitKind split, const std::string& label) {
  const SplitterInfo& info = splitter_info(split);
  if (c.nonlinear)
    throw Error(fmt::format("{}: curve scheme {} is non-linear; boundaries and creases need a linear curve scheme",
                            label, subdiv::quoted(c.name)));
  if (c.arity != info.curve_arity)
    throw Error(fmt::format("{}: curve scheme {} has arity {}, but the {} split refines boundaries with arity {}",
                            label, subdiv::quoted(c.name), c.arity, info.name, info.curve_arity));
  if (info.primal && 2 * -c.starts[0] + 1 != int(c.weights[0].size()))
    throw Error(fmt::format("{}: curve scheme {} is not primal (its rule 0 is not centred on an old point), so it "
                            "cannot give the boundary rules of the {} split", label, subdiv::quoted(c.name), info.name));
}

std::shared_ptr<const Scheme> make_surface(const SurfaceSchemeSpec& spec, const std::string& label,
                                           const std::string& who, const ParameterOverrides& overrides) {
  auto s = std::make_shared<Scheme>();
  s->name = spec.name;
  s->description = spec.description;
  s->path = label;
  s->required_face_size = spec.required_face_size;
  s->parameters = spec.parameters;
  std::set<std::string> used;
  apply_parameter_overrides(s->parameters, overrides, label, &used);
  const ParameterValues values = values_of(s->parameters);
  StepRules step;
  step.split = split_kind_from_name(spec.split);
  step.where = label;
  if (spec.linear)
    step.code = std::make_shared<const CodeRules>(
        checked_code_rules(call_plugin(who, "making its linear rules", [&] { return spec.linear(values); }), who));
  else
    step.nonlinear = std::make_shared<const NonlinearRule>(checked_nonlinear_rule(
        call_plugin(who, "making its non-linear rule", [&] { return spec.nonlinear(values); }), who));
  if (step.code && !step.code->vertex && !step.code->edge && !step.code->face && !step.code->corner)
    throw Error(fmt::format("{}: the linear rules give no function (vertex, edge, face or corner)", label));
  if (step.nonlinear && !*step.nonlinear) throw Error(fmt::format("{}: the non-linear rule is empty", label));
  s->steps.push_back(std::move(step));
  if (!spec.curve.empty()) {
    ParameterOverrides rest;
    for (const auto& [name, value] : overrides)
      if (!used.count(name)) rest[name] = value;
    s->curve = load_curve(spec.curve, rest, &used);
    check_curve_fits(*s->curve, s->split(), label);
  }
  check_unknown(overrides, used, label);
  return s;
}

std::shared_ptr<const CurveScheme> make_curve(const CurveSchemeSpec& spec, const std::string& label,
                                              const std::string& who, const ParameterOverrides& overrides,
                                              std::set<std::string>* used) {
  std::vector<ParameterSpec> params = spec.parameters;
  std::set<std::string> taken;
  apply_parameter_overrides(params, overrides, label, &taken);
  if (used) used->insert(taken.begin(), taken.end());
  else check_unknown(overrides, taken, label);
  const ParameterValues values = values_of(params);
  auto c = std::make_shared<CurveScheme>();
  c->name = spec.name;
  c->description = spec.description;
  c->path = label;
  c->parameters = values.numbers;
  if (spec.nonlinear) {
    c->nonlinear = std::make_shared<const PolylineRule>(checked_polyline_rule(
        call_plugin(who, "making its non-linear curve rule", [&] { return spec.nonlinear(values); }), who));
    if (!*c->nonlinear) throw Error(fmt::format("{}: the non-linear rule is empty", label));
    return c;
  }
  const CurveRulesSpec rules = call_plugin(who, "making its curve rules", [&] { return spec.linear(values); });
  if (rules.arity < 2 || int(rules.starts.size()) != rules.arity || int(rules.weights.size()) != rules.arity)
    throw Error(fmt::format("{}: a curve of arity {} needs {} rules (starts and weights), one per new point of each "
                            "old point; it has {} starts and {} weight lists", label, rules.arity, rules.arity,
                            rules.starts.size(), rules.weights.size()));
  c->arity = rules.arity;
  c->starts = rules.starts;
  for (int r = 0; r < rules.arity; ++r) {
    double sum = 0;
    std::vector<std::string> weights;
    for (double w : rules.weights[r]) {
      if (!std::isfinite(w)) throw Error(fmt::format("{}: rule {} has the weight {}", label, r, w));
      sum += w;
      weights.push_back(fmt::format("{:.17g}", w));
    }
    if (weights.empty() || std::abs(sum - 1.0) > 1e-9)
      throw Error(fmt::format("{}: the weights of rule {} sum to {}, not 1: a new point must be an affine "
                              "combination of old points", label, r, sum));
    c->weights.push_back(std::move(weights));
  }
  return c;
}

std::string json_name(const nlohmann::ordered_json& root, const std::string& label) {
  if (!root.is_object() || !root.contains("name") || !root["name"].is_string())
    throw Error(fmt::format("{}: a scheme needs a \"name\"", label));
  return root["name"].get<std::string>();
}

}  // namespace

double ParameterValues::number(const std::string& name) const {
  auto it = numbers.find(name);
  if (it == numbers.end()) throw Error(fmt::format("the scheme has no numeric parameter {}", subdiv::quoted(name)));
  return it->second;
}

const std::string& ParameterValues::choice(const std::string& name) const {
  auto it = choices.find(name);
  if (it == choices.end()) throw Error(fmt::format("the scheme has no choice parameter {}", subdiv::quoted(name)));
  return it->second;
}

ParameterSpec number_parameter(std::string name, double value, std::string description, std::optional<double> minimum,
                               std::optional<double> maximum) {
  ParameterSpec p;
  p.name = std::move(name);
  p.description = std::move(description);
  p.value = value;
  if (minimum) p.has_minimum = true, p.minimum = *minimum;
  if (maximum) p.has_maximum = true, p.maximum = *maximum;
  return p;
}

PluginRegistry::PluginRegistry(std::string plugin_name, std::string plugin_file)
    : plugin_name_(std::move(plugin_name)), plugin_file_(std::move(plugin_file)), staged_(std::make_unique<Staged>()) {}

PluginRegistry::~PluginRegistry() = default;

void PluginRegistry::add_splitter(SplitterInfo splitter) { staged_->splitters.push_back(std::move(splitter)); }
void PluginRegistry::add_role(RoleInfo role) { staged_->roles.push_back(std::move(role)); }
void PluginRegistry::add_surface_scheme(SurfaceSchemeSpec scheme) { staged_->surfaces.push_back(std::move(scheme)); }
void PluginRegistry::add_curve_scheme(CurveSchemeSpec scheme) { staged_->curves.push_back(std::move(scheme)); }
void PluginRegistry::add_json_scheme(std::string json_text) { staged_->json.push_back(std::move(json_text)); }

std::vector<std::string> PluginRegistry::commit() {
  const std::string origin = "plugin " + plugin_name_;
  Staged& st = *staged_;
  std::vector<std::string> provides;

  // Entries first, checked for names used twice within the plugin; then registered in
  // order, undone in reverse if anything fails.
  std::vector<CodeSchemeEntry> entries;
  std::set<std::string> names;
  auto claim = [&](const std::string& what, const std::string& name) {
    if (name.empty()) throw Error(fmt::format("a {} has no name", what));
    if (!names.insert(what + ":" + name).second)
      throw Error(fmt::format("the plugin registers the {} name {} twice", what, subdiv::quoted(name)));
  };
  for (auto& s : st.splitters) {
    claim("splitter", s.name);
    provides.push_back(fmt::format("splitter {}", s.name));
  }
  for (auto& r : st.roles) {
    claim("role", r.name);
    provides.push_back(fmt::format("role {} ({} rules)", r.name, element_name(r.element)));
  }
  for (auto& spec : st.surfaces) {
    claim("scheme", spec.name);
    if (bool(spec.linear) == bool(spec.nonlinear))
      throw Error(fmt::format("surface scheme {}: give exactly one of linear or nonlinear", subdiv::quoted(spec.name)));
    auto shared = std::make_shared<const SurfaceSchemeSpec>(spec);
    const std::string label = plugin_file_ + ":" + spec.name;
    const std::string who = fmt::format("plugin {} ({}), scheme {}", subdiv::quoted(plugin_name_), plugin_file_, subdiv::quoted(spec.name));
    CodeSchemeEntry e{spec.name, spec.description, "surface", origin, plugin_file_, nullptr, nullptr};
    e.make_surface = [shared, label, who](const ParameterOverrides& o) { return make_surface(*shared, label, who, o); };
    entries.push_back(std::move(e));
    provides.push_back(fmt::format("surface scheme {} ({}, {} split)", spec.name,
                                   spec.linear ? "linear, C++" : "non-linear, C++", spec.split));
  }
  for (auto& spec : st.curves) {
    claim("scheme", spec.name);
    if (bool(spec.linear) == bool(spec.nonlinear))
      throw Error(fmt::format("curve scheme {}: give exactly one of linear or nonlinear", subdiv::quoted(spec.name)));
    auto shared = std::make_shared<const CurveSchemeSpec>(spec);
    const std::string label = plugin_file_ + ":" + spec.name;
    const std::string who = fmt::format("plugin {} ({}), scheme {}", subdiv::quoted(plugin_name_), plugin_file_, subdiv::quoted(spec.name));
    CodeSchemeEntry e{spec.name, spec.description, "curve", origin, plugin_file_, nullptr, nullptr};
    e.make_curve = [shared, label, who](const ParameterOverrides& o, std::set<std::string>* used) {
      return make_curve(*shared, label, who, o, used);
    };
    entries.push_back(std::move(e));
    provides.push_back(fmt::format("curve scheme {} ({}, C++)", spec.name, spec.linear ? "linear" : "non-linear"));
  }
  for (size_t i = 0; i < st.json.size(); ++i) {
    const std::string text = st.json[i];
    const auto root = parse_json_text(text, fmt::format("{}: JSON scheme {}", plugin_file_, i + 1));
    const std::string name = json_name(root, fmt::format("{}: JSON scheme {}", plugin_file_, i + 1));
    claim("scheme", name);
    const std::string label = plugin_file_ + ":" + name;
    const std::string kind = scheme_text_kind(text, label);
    CodeSchemeEntry e{name, root.value("description", ""), kind, origin, plugin_file_, nullptr, nullptr};
    if (kind == "surface")
      e.make_surface = [text, label](const ParameterOverrides& o) { return load_scheme_text(text, label, o); };
    else
      e.make_curve = [text, label](const ParameterOverrides& o, std::set<std::string>* used) {
        return load_curve_text(text, label, o, used);
      };
    entries.push_back(std::move(e));
    provides.push_back(fmt::format("{} scheme {} (JSON)", kind, name));
  }

  std::vector<SplitKind> splits;
  std::vector<Role> roles;
  std::vector<std::string> schemes;
  auto undo = [&] {
    for (auto it = schemes.rbegin(); it != schemes.rend(); ++it) unregister_code_scheme(*it);
    for (auto it = roles.rbegin(); it != roles.rend(); ++it) unregister_role(*it);
    for (auto it = splits.rbegin(); it != splits.rend(); ++it) unregister_splitter(*it);
  };
  try {
    // Splitters and roles run as guarded functions: what they throw or return out of range
    // becomes a message naming the plugin's file and the function (checked_topology.h).
    const std::string who = fmt::format("plugin {} ({})", subdiv::quoted(plugin_name_), plugin_file_);
    for (auto& s : st.splitters) {
      s.origin = origin;
      splits.push_back(register_splitter(checked_splitter(s, who)));
    }
    for (auto& r : st.roles) {
      r.origin = origin;
      roles.push_back(register_role(checked_role(r, who)));
    }
    for (auto& e : entries) {
      register_code_scheme(e);
      schemes.push_back(e.name);
    }
    // Every scheme must build with its default parameters: a bad split name, curve scheme,
    // JSON text or a make function that throws refuses the plugin now, not at refine time.
    for (auto& e : entries) {
      try {
        if (e.kind == "surface") e.make_surface({});
        else e.make_curve({}, nullptr);
      } catch (const Error& err) {
        throw Error(fmt::format("scheme {} does not load: {}", subdiv::quoted(e.name), err.what()));
      }
    }
  } catch (...) {
    undo();
    throw;
  }
  return provides;
}

}  // namespace subdiv
