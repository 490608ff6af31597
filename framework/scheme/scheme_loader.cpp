#include "framework/scheme/scheme_loader.h"

#include <cmath>
#include <fmt/format.h>
#include <set>

#include "framework/scheme/json_source.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/util/input_errors.h"
#include "framework/util/json_path_line.h"
#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

using Json = nlohmann::ordered_json;

// The farthest a curve rule may start from its old point (see the "start" check).
constexpr long long kMaxCurveStart = 64;

// Messages name the file and the JSON path of the offending value.
struct Place {
  std::string file;
  std::string path;
  Place operator/(const std::string& key) const { return {file, path.empty() ? key : path + "." + key}; }
  Place operator[](size_t i) const { return {file, fmt::format("{}[{}]", path, i)}; }
  std::string str() const { return path.empty() ? file : file + ": " + path; }
};

[[noreturn]] void fail(const Place& at, const std::string& message) {
  throw Error(fmt::format("{}: {}", at.str(), message));
}

const Json& require(const Json& object, const char* key, const Place& at) {
  if (!object.is_object()) fail(at, "expected a JSON object");
  auto it = object.find(key);
  if (it == object.end()) fail(at, fmt::format("missing \"{}\"", escaped(key)));
  return *it;
}

// A JSON value in words, for "must be a number, got the string \"0\"".
std::string described(const Json& value) {
  if (value.is_string()) return "the string " + shortened(value.dump());
  if (value.is_number()) return "the number " + shortened(value.dump());
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_null()) return "null";
  return value.is_array() ? "an array " + shortened(value.dump()) : "an object " + shortened(value.dump());
}

[[noreturn]] void wrong_type(const Json& value, const char* expected, const Place& at) {
  fail(at, fmt::format("must be {}, got {}", expected, described(value)));
}

std::string as_string(const Json& value, const Place& at) {
  if (!value.is_string()) wrong_type(value, "a string", at);
  return value.get<std::string>();
}

double as_number(const Json& value, const Place& at) {
  if (!value.is_number()) wrong_type(value, "a number", at);
  return value.get<double>();
}

bool as_bool(const Json& value, const Place& at) {
  if (!value.is_boolean()) wrong_type(value, "true or false", at);
  return value.get<bool>();
}

void require_object(const Json& value, const Place& at) {
  if (!value.is_object()) wrong_type(value, "a JSON object {...}", at);
}

// Weights may be written as numbers or as formula text.
std::string as_formula(const Json& value, const Place& at) {
  if (value.is_number()) return fmt::format("{:.17g}", value.get<double>());
  if (!value.is_string()) wrong_type(value, "a number or a formula string", at);
  return value.get<std::string>();
}

std::string optional_string(const Json& object, const char* key) {
  auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

void check_keys(const Json& object, const std::set<std::string>& allowed, const Place& at) {
  require_object(object, at);
  for (auto it = object.begin(); it != object.end(); ++it)
    if (!allowed.count(it.key())) {
      std::string list;
      for (auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
      fail(at, fmt::format("unknown key \"{}\"; the keys here are: {}", escaped(it.key()), list));
    }
}

double parse_number(const std::string& text, const Place& at) {
  try {
    size_t used = 0;
    double v = std::stod(text, &used);
    if (used == text.size() && std::isfinite(v)) return v;
  } catch (...) {
  }
  fail(at, fmt::format("{} is not a number", subdiv::quoted(shortened(text))));
}

// Names formulas already use for themselves.
void check_not_reserved(const std::string& name, const Place& at) {
  static const std::set<std::string> reserved{"n",  "k",  "j",  "l",  "n0", "n1", "k0", "k1", "ci", "cb",
                                              "ex", "fe", "b0", "b1", "m0", "m1", "e0", "e1", "pi"};
  if (reserved.count(name))
    fail(at, fmt::format("{} is a reserved name in formulas (n, k, j, l, n0, n1, k0, k1, ci, cb, ex, fe, b0, b1, m0, m1, e0, e1, pi); rename it",
                         subdiv::quoted(name)));
}

ParameterSpec parse_parameter(const std::string& name, const Json& spec, const Place& at) {
  check_keys(spec, {"default", "min", "max", "min_exclusive", "max_exclusive", "choices", "per_vertex", "description"}, at);
  ParameterSpec p;
  p.name = name;
  p.description = optional_string(spec, "description");
  const Json& def = require(spec, "default", at);
  if (spec.contains("per_vertex")) {
    p.per_vertex = as_bool(spec["per_vertex"], at / "per_vertex");
    if (p.per_vertex && spec.contains("choices"))
      fail(at / "per_vertex", "a choice parameter selects definitions once per scheme; only numeric parameters can be per vertex");
  }
  if (spec.contains("choices")) {
    p.is_choice = true;
    const Json& choices = spec["choices"];
    if (!choices.is_array()) wrong_type(choices, "an array of strings", at / "choices");
    for (size_t i = 0; i < choices.size(); ++i) p.choices.push_back(as_string(choices[i], (at / "choices")[i]));
    p.choice = as_string(def, at / "default");
    return p;
  }
  if (!def.is_number()) fail(at / "default", "a numeric parameter needs a number as default");
  p.value = def.get<double>();
  if (spec.contains("min")) p.has_minimum = true, p.minimum = as_number(spec["min"], at / "min");
  if (spec.contains("max")) p.has_maximum = true, p.maximum = as_number(spec["max"], at / "max");
  if (spec.contains("min_exclusive")) p.minimum_exclusive = as_bool(spec["min_exclusive"], at / "min_exclusive");
  if (spec.contains("max_exclusive")) p.maximum_exclusive = as_bool(spec["max_exclusive"], at / "max_exclusive");
  return p;
}

void apply_override(ParameterSpec& p, const std::string& text, const std::string& file) {
  const Place at{file, "parameters." + p.name};
  if (p.is_choice) {
    if (std::find(p.choices.begin(), p.choices.end(), text) == p.choices.end()) {
      std::string list;
      for (auto& c : p.choices) list += (list.empty() ? "" : ", ") + c;
      fail(at, fmt::format("{} is not a choice of {}; choose one of: {}", subdiv::quoted(text), p.name, list));
    }
    p.choice = text;
    return;
  }
  p.value = parse_number(text, at);
}

void check_range(const ParameterSpec& p, const std::string& file) {
  if (p.is_choice) {
    if (std::find(p.choices.begin(), p.choices.end(), p.choice) == p.choices.end())
      fail({file, "parameters." + p.name}, fmt::format("default {} is not among the choices", subdiv::quoted(p.choice)));
    return;
  }
  if (auto why = range_violation(p, p.value); !why.empty()) fail({file, "parameters." + p.name}, why);
}

std::vector<ParameterSpec> parse_parameters(const Json& root, const Place& at,
                                            const ParameterOverrides& overrides,
                                            std::set<std::string>* used_overrides) {
  std::vector<ParameterSpec> params;
  if (!root.contains("parameters")) return params;
  const Json& list = root["parameters"];
  require_object(list, at / "parameters");
  for (auto it = list.begin(); it != list.end(); ++it) {
    check_not_reserved(it.key(), at / "parameters" / it.key());
    if (!it.value().is_object())
      fail(at / "parameters" / it.key(), "a parameter is an object such as {\"default\": 0.5, \"min\": 0, \"max\": 1}");
    ParameterSpec p = parse_parameter(it.key(), it.value(), at / "parameters" / it.key());
    if (auto o = overrides.find(p.name); o != overrides.end()) {
      apply_override(p, o->second, at.file);
      if (used_overrides) used_overrides->insert(p.name);
    }
    check_range(p, at.file);
    params.push_back(std::move(p));
  }
  return params;
}

// Level-dependent state: "state": {"alpha": {"initial": "alpha0", "next": "sqrt((1 + alpha)/2)"}}.
// The value while level l is refined is `next` applied l times to `initial` (formula.h).
std::vector<NamedFormula> parse_state(const Json& root, const Place& at) {
  std::vector<NamedFormula> state;
  if (!root.contains("state")) return state;
  const Json& list = root["state"];
  if (!list.is_object())
    fail(at / "state", "expected an object of state variables, e.g. \"state\": {\"alpha\": "
                       "{\"initial\": \"alpha0\", \"next\": \"sqrt((1 + alpha)/2)\"}}");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const Place here = at / "state" / it.key();
    check_keys(it.value(), {"initial", "next", "description"}, here);
    NamedFormula f;
    f.name = it.key();
    f.expression = as_formula(require(it.value(), "initial", here), here / "initial");
    f.where = (here / "initial").str();
    f.next = as_formula(require(it.value(), "next", here), here / "next");
    f.next_where = (here / "next").str();
    if (f.next.find_first_not_of(" \t") == std::string::npos) fail(here / "next", "the recurrence is empty");
    state.push_back(std::move(f));
  }
  return state;
}

// Parameters, state variables and definitions share one namespace with the formula
// variables (n, k, j, l, and n0, n1 of edge rules), the constant pi and our functions.
void check_names(const std::vector<ParameterSpec>& params, const std::vector<NamedFormula>& named,
                 const Place& at) {
  std::map<std::string, std::string> seen{{"pi", "a constant"}};
  for (const char* variable : {"n", "k", "j", "l", "n0", "n1", "k0", "k1", "ci", "cb", "ex", "fe", "b0", "b1", "m0",
                               "m1", "e0", "e1"})
    seen[variable] = "a formula variable";
  for (const char* function : {"binom", "floor", "ceil", "mod"}) seen[function] = "a formula function";
  auto claim = [&](const std::string& name, const std::string& what, const Place& here) {
    if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') ||
        name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") !=
            std::string::npos)
      fail(here, fmt::format("{} is not a valid name: use letters, digits and _, starting with a letter", subdiv::quoted(shortened(name))));
    if (auto it = seen.find(name); it != seen.end())
      fail(here, fmt::format("the {} name {} is already {}; choose another name", what, subdiv::quoted(name), it->second));
    seen[name] = "the name of a " + what;
  };
  for (const auto& p : params) claim(p.name, "parameter", at / "parameters" / p.name);
  for (const auto& f : named)
    claim(f.name, f.is_state() ? "state variable" : "definition",
          at / (f.is_state() ? "state" : "definitions") / f.name);
}

std::vector<NamedFormula> parse_plain_definitions(const Json& root, const Place& at,
                                                  const std::vector<ParameterSpec>& params);

// The state variables first, then the definitions, with their names checked.
std::vector<NamedFormula> parse_definitions(const Json& root, const Place& at,
                                            const std::vector<ParameterSpec>& params) {
  std::vector<NamedFormula> defs = parse_state(root, at);
  for (auto& d : parse_plain_definitions(root, at, params)) defs.push_back(std::move(d));
  check_names(params, defs, at);
  return defs;
}

// Definitions: "name": "formula", or "name": {"select": param, "cases": {choice: formula}}.
std::vector<NamedFormula> parse_plain_definitions(const Json& root, const Place& at,
                                                  const std::vector<ParameterSpec>& params) {
  std::vector<NamedFormula> defs;
  if (!root.contains("definitions")) return defs;
  const Json& list = root["definitions"];
  require_object(list, at / "definitions");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const Place here = at / "definitions" / it.key();
    check_not_reserved(it.key(), here);
    if (!it.value().is_object()) {
      defs.push_back({it.key(), as_formula(it.value(), here), here.str(), "", ""});
      continue;
    }
    check_keys(it.value(), {"select", "cases"}, here);
    const std::string select = as_string(require(it.value(), "select", here), here / "select");
    auto p = std::find_if(params.begin(), params.end(),
                          [&](const ParameterSpec& s) { return s.name == select && s.is_choice; });
    if (p == params.end()) fail(here / "select", fmt::format("{} is not a choice parameter", subdiv::quoted(select)));
    const Json& cases = require(it.value(), "cases", here);
    for (const auto& choice : p->choices)
      if (!cases.contains(choice)) fail(here / "cases", fmt::format("no case for choice {}", subdiv::quoted(choice)));
    const Place chosen = here / "cases" / p->choice;
    defs.push_back({it.key(), as_formula(cases[p->choice], chosen), chosen.str(), "", ""});
  }
  return defs;
}

std::string roles_of(Element element) {
  std::string list;
  for (int r = 0; r <= int(Role::CreasePoint); ++r)
    if (Role(r) != Role::Curve && role_allowed(element, Role(r)))
      list += (list.empty() ? "" : ", ") + std::string(role_name(Role(r)));
  for (const RoleInfo* info : list_registered_roles())
    if (info->element == element) list += fmt::format("{}{} ({})", list.empty() ? "" : ", ", info->name, info->origin);
  return list;
}

// A whole number in [lo, hi], or a message naming the place.
int as_whole(const Json& value, int lo, int hi, const Place& at) {
  if (!value.is_number_integer()) wrong_type(value, "a whole number", at);
  const long long v = value.get<long long>();
  if (v < lo || v > hi) fail(at, fmt::format("{} is outside [{}, {}]", v, lo, hi));
  return int(v);
}

Term parse_term(const Json& j, Element element, const Place& at) {
  check_keys(j, {"at", "sum", "new", "w", "step"}, at);
  Term t;
  t.where = at.str();
  const bool single = j.contains("at"), multi = j.contains("sum");
  if (single == multi) fail(at, "a term needs exactly one of \"at\" (one point) or \"sum\" (all points of a role)");
  const std::string name = as_string(single ? j["at"] : j["sum"], at / (single ? "at" : "sum"));
  auto role = role_from_name(name);
  if (!role || *role == Role::Curve)
    fail(at, fmt::format("unknown role {}; {} rules may use: {}", subdiv::quoted(name), element_name(element),
                         roles_of(element)));
  if (!role_allowed(element, *role))
    fail(at, fmt::format("role {} does not exist around a {}", subdiv::quoted(shortened(name)), element_name(element)));
  const bool one_point = *role == Role::Self || *role == Role::CreasePoint;
  if (single && !one_point) fail(at, fmt::format("role {} has several points: write \"sum\": \"{}\"", subdiv::quoted(name), escaped(name)));
  if (multi && one_point)
    fail(at, fmt::format("role {} is one point: write \"at\": \"{}\"", subdiv::quoted(name), escaped(name)));
  t.role = *role;
  if (*role == Role::CreasePoint)
    t.step = as_whole(require(j, "step", at), -kMaxCreaseReach, kMaxCreaseReach, at / "step");
  else if (j.contains("step"))
    fail(at / "step", fmt::format("\"step\" belongs to role 'crease-point' (a crease vertex that many crease edges along "
                                  "the crease), not to role {}", subdiv::quoted(name)));
  if (j.contains("new")) {
    const std::string np = as_string(j["new"], at / "new");
    auto kind = new_point_from_name(np);
    if (!kind) fail(at / "new", fmt::format("unknown new point {}; use face, edge or vertex", subdiv::quoted(np)));
    t.new_point = *kind;
  }
  const bool needs_new = *role == Role::Faces || (*role == Role::Edges);
  if (needs_new && t.new_point == NewPoint::None)
    fail(at, fmt::format("role {} names {}, not points: add \"new\": \"{}\" to use their new points", subdiv::quoted(name),
                         name, escaped(*role == Role::Faces ? "face" : "edge")));
  if (*role == Role::Faces && t.new_point != NewPoint::Face) fail(at / "new", "faces can only give new face points");
  if (*role == Role::Edges && t.new_point != NewPoint::Edge) fail(at / "new", "edges can only give new edge points");
  if (!needs_new && t.new_point != NewPoint::None && t.new_point != NewPoint::Vertex)
    fail(at / "new", fmt::format("role {} holds vertices: the only new points it can give are new vertex points", subdiv::quoted(name)));
  t.weight = as_formula(require(j, "w", at), at / "w");
  return t;
}

Rule parse_rule(const Json& j, Element element, const Place& at) {
  if (!j.is_array()) fail(at, "a rule is an array of terms");
  Rule rule;
  rule.where = at.str();
  for (size_t i = 0; i < j.size(); ++i) rule.terms.push_back(parse_term(j[i], element, at[i]));
  return rule;
}

// Roles that exist only where a vertex has two crease edges.
bool crease_only_role(Role r) { return r == Role::CreaseNeighbours || r == Role::CreasePoint; }

void refuse_crease_roles(const Rule& rule, const Place& at) {
  for (const Term& t : rule.terms)
    if (crease_only_role(t.role)) fail(at, fmt::format("role {} exists only in crease rules", subdiv::quoted(role_name(t.role))));
}

// The middle vertex of a crease of even length is as far from both corners: its rule must
// read the same either way (a crease-point at step s weighted as the one at -s).
void require_mirrored(const Rule& rule, int length, const Place& at) {
  for (const Term& t : rule.terms) {
    if (t.role != Role::CreasePoint) continue;
    bool mirrored = false;
    for (const Term& u : rule.terms) mirrored = mirrored || (u.role == Role::CreasePoint && u.step == -t.step && u.weight == t.weight);
    if (!mirrored)
      fail(at, fmt::format("the middle vertex of a crease of {} edges is {} edges from both corners, so its rule must "
                           "be symmetric: step {} needs a crease-point at step {} with the same weight \"{}\"",
                           length, length / 2, t.step, -t.step, t.weight));
  }
}

// "crease-ends": [{"distance": D, "length": L, "rule": [terms]}, ...]: vertex crease rules for
// the crease vertices D crease edges from the nearest corner (rule.h: CreaseEndRules); with
// "length", only on a crease of exactly L edges between two corners, where it takes
// precedence. A crease-point may reach the corner (step -D) but not past it, nor past the
// far corner of a crease of length L (step L - D).
CreaseEndRules parse_crease_ends(const Json& j, const Place& at) {
  if (!j.is_array() || j.empty())
    fail(at, "expected a non-empty array of {\"distance\": D, \"rule\": [terms]} (and optionally \"length\": L), D the "
             "number of crease edges from the nearest corner, L the crease's length between its two corners");
  CreaseEndRules ends;
  for (size_t i = 0; i < j.size(); ++i) {
    const Place here = at[i];
    require_object(j[i], here);
    check_keys(j[i], {"distance", "length", "rule"}, here);
    const int length = j[i].contains("length") ? as_whole(j[i]["length"], 2, kMaxCreaseLength, here / "length") : 0;
    const int d = as_whole(require(j[i], "distance", here), 1, length ? length / 2 : kMaxCreaseReach, here / "distance");
    std::vector<std::optional<Rule>>& slots = length ? ends.by_length[length] : ends.by_distance;
    if (size_t(d) < slots.size() && slots[size_t(d)])
      fail(here / "distance", length ? fmt::format("distance {} on creases of length {} has a rule already; give each one rule", d, length)
                                     : fmt::format("distance {} has a rule already; give each distance one rule", d));
    Rule rule = parse_rule(require(j[i], "rule", here), Element::Vertex, here / "rule");
    for (size_t t = 0; t < rule.terms.size(); ++t) {
      const int step = rule.terms[t].step;
      if (rule.terms[t].role != Role::CreasePoint) continue;
      if (step < -d)
        fail((here / "rule")[t] / "step",
             fmt::format("step {} reaches past the corner, which is {} crease edge(s) away at distance {}; "
                         "use a step from {} (the corner) up",
                         step, d, d, -d));
      if (length && step > length - d)
        fail((here / "rule")[t] / "step",
             fmt::format("step {} reaches past the far corner, which is {} crease edge(s) away at distance {} on a "
                         "crease of length {}; use a step up to {}",
                         step, length - d, d, length, length - d));
    }
    if (length && 2 * d == length) require_mirrored(rule, length, here / "rule");
    if (slots.size() <= size_t(d)) slots.resize(size_t(d) + 1);
    slots[size_t(d)] = std::move(rule);
  }
  return ends;
}

RuleTable parse_rules(const Json& rules, const Place& at, const std::set<std::string>& elements,
                      CreaseEndRules* crease_ends = nullptr) {
  RuleTable table;
  check_keys(rules, elements, at);
  for (int e = 0; e < kElementCount; ++e) {
    const std::string name(element_name(Element(e)));
    if (!rules.contains(name)) continue;
    const Json& r = rules[name];
    const Place here = at / name;
    if (r.is_array()) {
      table[e][int(Context::Smooth)] = parse_rule(r, Element(e), here);
      refuse_crease_roles(*table[e][int(Context::Smooth)], here);
      continue;
    }
    if (!r.is_object()) fail(here, "expected an array of terms, or an object of contexts (smooth, dart, crease, corner)");
    const bool vertex = Element(e) == Element::Vertex;
    for (auto it = r.begin(); it != r.end(); ++it) {
      if (it.key() == "crease-ends" && vertex && crease_ends) {
        *crease_ends = parse_crease_ends(it.value(), here / it.key());
        continue;
      }
      if (it.key() == "crease-ends")
        fail(here / it.key(), fmt::format("crease-ends belong to vertex rules (a crease vertex's rule chosen by its distance "
                                          "from a corner); a {} rule here has none: its points next to a corner take its "
                                          "crease and corner contexts, and the vertex rules of a later smoothing pass can "
                                          "clamp the crease",
                                          element_name(Element(e))));
      auto ctx = context_from_name(it.key());
      if (!ctx)
        fail(here, fmt::format("unknown context {}; use smooth, dart, crease or corner{}", subdiv::quoted(it.key()),
                               vertex && crease_ends ? " (or crease-ends: crease rules by distance from a corner)" : ""));
      table[e][int(*ctx)] = parse_rule(it.value(), Element(e), here / it.key());
      if (*ctx != Context::Crease) refuse_crease_roles(*table[e][int(*ctx)], here / it.key());
    }
    if (!table[e][int(Context::Smooth)]) fail(here, "the smooth rule is required");
  }
  return table;
}

SplitKind parse_split(const Json& value, const Place& at) {
  const std::string name = as_string(value, at);  // its refusal names the place already
  try {
    return split_kind_from_name(name);
  } catch (const Error& e) {
    fail(at, e.what());
  }
}

// Which elements make new points in each split (and so may have rules).
std::set<std::string> elements_of_split(SplitKind split) {
  std::set<std::string> names;
  for (OriginKind o : splitter_info(split).rule_elements) names.insert(std::string(element_name(Element(int(o)))));
  return names;
}

// Either "split" + "rules" (one step), or "steps": [{"split": .., "rules": ..},
// {"smooth": {"vertex": ..}}, ...] with the split first. Any step may carry "when" (kept
// only where the formula is non-zero) and a pass "repeat"; a split may name its own "curve".
struct Repeat {
  size_t step;
  std::string formula, where;
};

struct ParsedSteps {
  std::vector<StepRules> steps;
  std::vector<Repeat> repeats, whens;
  std::vector<std::string> curves;  // per step: the split's own curve scheme, or ""
  std::vector<Place> curve_places;
};

// Unrolls "repeat" and drops the steps whose "when" is zero, both evaluated once from the
// parameters and definitions (e.g. (d - 1)/2 passes for the degree-d quad B-spline). Returns
// the indices of the kept steps, in order.
// Smoothing passes of one level, repeats included: enough for every scheme of the
// literature (the degree-d Lane-Riesenfeld schemes take (d - 1) / 2 passes), and a bound on
// the work one level may ask for.
constexpr size_t kMaxPassesPerLevel = 64;

std::vector<size_t> unroll_steps(const ParsedSteps& parsed, const Scheme& scheme, const Place& at) {
  FormulaSet formulas(scheme.parameter_values(), scheme.definitions);
  auto value_of = [&](const Repeat& r) {
    const int id = formulas.add(r.formula, r.where);
    for (const ParameterSpec& p : scheme.parameters)
      if (p.per_vertex && formulas.uses(id).reads(p.name))
        throw Error(fmt::format("{}: reads parameter {}, which is per vertex; \"when\" and \"repeat\" are decided "
                                "once for the whole mesh", r.where, subdiv::quoted(p.name)));
    return formulas.evaluate(id, {});
  };
  std::vector<size_t> out;
  for (size_t i = 0; i < parsed.steps.size(); ++i) {
    int count = 1;
    for (const Repeat& r : parsed.whens) {
      if (r.step != i) continue;
      const double v = value_of(r);
      if (!std::isfinite(v))
        throw Error(fmt::format("{}: when {} gives {}; it must give a number (0: leave the step out)", r.where, subdiv::quoted(shortened(r.formula)), v));
      if (v == 0) count = 0;
    }
    for (const Repeat& r : parsed.repeats) {
      if (r.step != i || count == 0) continue;
      const double v = value_of(r);
      if (!(v >= 0) || v != std::floor(v) || v > 64)
        throw Error(fmt::format("{}: repeat {} gives {}, not a whole number from 0 to 64", r.where, subdiv::quoted(shortened(r.formula)), v));
      count = int(v);
    }
    for (int c = 0; c < count; ++c) out.push_back(i);
    // Each step costs a pass over the level; 2,000 smoothing passes took 19 s per level on a cube.
    if (out.size() > kMaxPassesPerLevel + 1)
      fail(at / "steps", fmt::format("with these parameters the smoothing passes (repeats included) come to more "
                                     "than {} per level; a scheme may have at most {}",
                                     kMaxPassesPerLevel, kMaxPassesPerLevel));
  }
  int splits = 0;
  for (size_t i : out) splits += parsed.steps[i].is_split;
  if (splits != 1 || !parsed.steps[out.front()].is_split)
    fail(at / "steps", fmt::format("with these parameters {} split step(s) remain after \"when\"; exactly one must "
                                   "remain (the first step of every level is its split)", splits));
  return out;
}

ParsedSteps parse_steps(const Json& root, const Place& at) {
  ParsedSteps p;
  if (!root.contains("steps")) {
    StepRules step;
    step.split = parse_split(require(root, "split", at), at / "split");
    step.rules = parse_rules(require(root, "rules", at), at / "rules", elements_of_split(step.split), &step.crease_ends);
    step.where = at.str();
    p.steps.push_back(std::move(step));
    p.curves.emplace_back(), p.curve_places.push_back(at / "curve");
    return p;
  }
  if (root.contains("split") || root.contains("rules"))
    fail(at, "give either \"split\" and \"rules\", or \"steps\", not both");
  const Json& list = root["steps"];
  if (!list.is_array() || list.empty()) fail(at / "steps", "expected a non-empty array of steps");
  if (list.size() > 2 * kMaxPassesPerLevel)
    fail(at / "steps", fmt::format("{} steps; a scheme may list at most {}", list.size(), 2 * kMaxPassesPerLevel));
  bool seen_pass = false;
  for (size_t i = 0; i < list.size(); ++i) {
    const Place here = (at / "steps")[i];
    StepRules step;
    step.where = here.str();
    std::string curve;
    if (list[i].contains("smooth")) {
      check_keys(list[i], {"smooth", "repeat", "when"}, here);
      if (i == 0) fail(here, "the first step must be a split");
      seen_pass = true;
      step.is_split = false;
      step.curve_rules_apply = false;
      step.rules = parse_rules(list[i]["smooth"], here / "smooth", {"vertex"}, &step.crease_ends);
      if (list[i].contains("repeat"))
        p.repeats.push_back({p.steps.size(), as_formula(list[i]["repeat"], here / "repeat"), (here / "repeat").str()});
    } else {
      check_keys(list[i], {"split", "rules", "curve", "when"}, here);
      if (seen_pass)
        fail(here, "splits come first: a later step is a smoothing pass (choose between splits with \"when\")");
      step.split = parse_split(require(list[i], "split", here), here / "split");
      step.rules = parse_rules(require(list[i], "rules", here), here / "rules", elements_of_split(step.split),
                               &step.crease_ends);
      if (list[i].contains("curve")) curve = as_string(list[i]["curve"], here / "curve");
    }
    if (list[i].contains("when"))
      p.whens.push_back({p.steps.size(), as_formula(list[i]["when"], here / "when"), (here / "when").str()});
    p.curves.push_back(curve), p.curve_places.push_back(here / "curve");
    p.steps.push_back(std::move(step));
  }
  return p;
}

int parse_face_requirement(const Json& root, const Place& at) {
  const std::string faces = root.contains("faces") ? as_string(root["faces"], at / "faces") : "any";
  if (faces == "any") return 0;
  if (faces == "triangles") return 3;
  if (faces == "quads") return 4;
  fail(at / "faces", fmt::format("{} is not one of: any, triangles, quads", subdiv::quoted(faces)));
}

// A per-vertex parameter has a value at each vertex, so only a vertex rule (which has one
// vertex) can read it; an edge or face rule would not know whose value to take.
void check_per_vertex_reads(const Scheme& s, const FormulaUses& uses, Element element, const std::string& where) {
  if (element == Element::Vertex) return;
  for (const ParameterSpec& p : s.parameters)
    if (p.per_vertex && uses.reads(p.name))
      throw Error(fmt::format("{}: reads parameter {}, which is per vertex (\"per_vertex\": true); only vertex "
                              "rules can read it, at their own vertex. Read it in a vertex rule, or drop "
                              "\"per_vertex\"", where, subdiv::quoted(p.name)));
}

// Compiles and evaluates every formula once (at a regular valence) so syntax errors and
// unknown names surface at load time with their place.
void check_formulas(const Scheme& s) {
  FormulaSet formulas(s.parameter_values(), s.definitions);
  const FormulaInputs sample{4, 4, 0, 0, 6, 6};
  for (const auto& step : s.steps)
    for (int e = 0; e < kElementCount; ++e)
      for (const auto& rule : step.rules[e])
        if (rule)
          for (const auto& term : rule->terms) {
            const int id = formulas.add(term.weight, term.where);
            formulas.evaluate(id, sample);
            check_per_vertex_reads(s, formulas.uses(id), Element(e), term.where);
          }
}


// The curve scheme a surface scheme names, with errors (an unknown name, a broken curve
// file) placed at the reference.
std::shared_ptr<const CurveScheme> curve_at(const CurveResolver& resolve, const std::string& name, const Place& at,
                                            const ParameterOverrides& overrides, std::set<std::string>* used) {
  try {
    return resolve(name, at.file, overrides, used);
  } catch (const OptionError&) {
    throw;
  } catch (const Error& e) {
    fail(at, e.what());  // the messages name the curve scheme
  }
}

void check_unknown_overrides(const ParameterOverrides& overrides, const std::set<std::string>& used,
                             const std::string& file) {
  for (const auto& [name, value] : overrides)
    if (!used.count(name))
      throw OptionError(fmt::format("{}: the scheme has no parameter {} (from {{param}} {}={}); "
                                    "{{scheme_list}} lists each scheme's parameters",
                                    file, subdiv::quoted(name), name, value));
}

// Primal splits keep old vertices and add points on edges, so the curve's rule 0 must be
// centred on an old point; the arity must match how the split refines boundaries
// (binary for quad, triangle and dual splits, ternary for sqrt3). Dual splits need a
// dual binary curve (two new points per segment, none on old points).
void check_curve_fits_split(const CurveScheme& c, SplitKind split, const Place& at) {
  const SplitterInfo& info = splitter_info(split);
  if (c.nonlinear)
    fail(at, fmt::format("curve scheme {} ({}) is non-linear; boundaries and creases need a linear curve scheme",
                         subdiv::quoted(c.name), c.path));
  if (c.variational())
    fail(at, fmt::format("curve scheme {} ({}) is variational: its new points depend on the whole polyline, "
                         "but boundaries and creases need a local curve rule", subdiv::quoted(c.name), c.path));
  if (c.arity != info.curve_arity)
    fail(at, fmt::format("curve scheme {} has arity {}, but the {} split refines boundaries with arity {}",
                         subdiv::quoted(c.name), c.arity, info.name, info.curve_arity));
  if (!info.primal) return;
  if (2 * -c.starts[0] + 1 != int(c.weights[0].size()))
    fail(at, fmt::format("curve scheme {} ({}) is not primal: its rule 0 is not centred on an old "
                         "point, so it cannot give the boundary rules of a primal split", subdiv::quoted(c.name), c.path));
}

// ---- curve schemes -------------------------------------------------------------------

std::string parameter_note(const CurveScheme& curve) {
  if (curve.parameters.empty()) return "";
  std::string list;
  for (const auto& [name, value] : curve.parameters) list += fmt::format("{}{} = {}", list.empty() ? "" : ", ", name, value);
  return " (parameters: " + list + ")";
}

// Curve formulas see j (index of the weight), l, parameters, state and definitions.
int add_curve_formula(FormulaSet& formulas, const std::string& text, const Place& here) {
  const int id = formulas.add(text, here.str());
  const FormulaUses u = formulas.uses(id);
  if (u.n || u.k)
    fail(here, fmt::format("formula {} uses {}; curve formulas may use j (the index of the weight in "
                           "its rule), l, the parameters, state and definitions; n and k belong to "
                           "surface rules", subdiv::quoted(text), u.n ? "n" : "k"));
  return id;
}

std::vector<std::string> parse_curve_weights(const Json& w, const Place& at, FormulaSet& formulas) {
  if (!w.is_array() || w.empty()) fail(at, "expected a non-empty array of weights");
  std::vector<std::string> weights;
  for (size_t t = 0; t < w.size(); ++t) {
    weights.push_back(as_formula(w[t], at[t]));
    add_curve_formula(formulas, weights.back(), at[t]);
  }
  return weights;
}

// "variational": {"alpha": [alpha_0, ..., alpha_s], "r": r} (Kobbelt 1996): the new points
// minimise sum_i K(P_i)^2, K(P_i) = sum_j alpha_j P_{i+j-r}; solved per level by the curve
// refiner (analysis/curve/variational_curve.h). The alpha may be formulas of the parameters.
void parse_variational(const Json& v, const Place& at, FormulaSet& formulas, CurveScheme& curve) {
  check_keys(v, {"alpha", "r"}, at);
  const Json& alpha = require(v, "alpha", at);
  if (!alpha.is_array() || alpha.size() < 2)
    fail(at / "alpha", "expected an array of at least 2 coefficients alpha_0 .. alpha_s of K(P_i) = sum_j "
                       "alpha_j P_{i+j-r}");
  double sum = 0, magnitude = 0;
  for (size_t j = 0; j < alpha.size(); ++j) {
    curve.variational_alpha.push_back(as_formula(alpha[j], (at / "alpha")[j]));
    const int id = add_curve_formula(formulas, curve.variational_alpha.back(), (at / "alpha")[j]);
    const double a = formulas.evaluate(id, {0, 0, double(j), 0});
    if (!std::isfinite(a)) fail((at / "alpha")[j], fmt::format("{} is {} at level 0", subdiv::quoted(curve.variational_alpha.back()), a));
    sum += a, magnitude += std::abs(a);
  }
  if (magnitude == 0.0 || std::abs(sum) > 1e-12 * magnitude)
    fail(at / "alpha", fmt::format("the coefficients sum to {} at level 0; K must vanish on constant polygons "
                                   "(alpha(1) = 0), and not all may be 0", sum));
  const Json& r = require(v, "r", at);
  if (!r.is_number_integer() || r.get<long long>() < 0 || r.get<long long>() >= (long long)alpha.size())
    fail(at / "r", fmt::format("expected a whole number from 0 to {} (K(P_i) reads P_(i-r) .. P_(i-r+{})), found {}",
                               alpha.size() - 1, alpha.size() - 1, shortened(r.dump())));
  curve.variational_r = r.get<int>();
}

long floor_div(long a, long b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

// "mask": {"first": F, "size": S, "a": "formula of j"} or {"first": F, "a": [a_F, a_F+1, ...]}:
// the coefficients a_i of P^{k+1}_i = sum_j a_{i - m j} P^k_j (Dyn, Gregory & Levin 1991), i from F.
// They are evaluated once (they may not depend on l or state) and turned into the
// equivalent rules: rule r has weight a_{r - m (start_r + t)} on old point i + start_r + t.
void expand_mask(const Json& mask, const Place& at, FormulaSet& formulas, CurveScheme& curve) {
  check_keys(mask, {"first", "size", "a"}, at);
  const std::string note = parameter_note(curve);
  auto stationary = [&](int id, const Place& here, bool j_allowed) {
    const FormulaUses u = formulas.uses(id);
    if (u.l)
      fail(here, "mask coefficients are stationary: they may not use l or state variables; state a "
                 "level-dependent scheme with \"rules\"");
    if (u.j && !j_allowed) fail(here, "\"first\" and \"size\" may use only parameters and definitions, not j");
  };
  auto whole_value = [&](const Json& v, const Place& here, const char* what) -> long {
    if (v.is_number_integer()) return v.get<long>();
    const int id = add_curve_formula(formulas, as_formula(v, here), here);
    stationary(id, here, false);
    const double x = formulas.evaluate(id, {});
    if (!std::isfinite(x) || x != std::floor(x) || std::abs(x) > 1e6)
      fail(here, fmt::format("{} evaluates to {}, not a whole number{}", what, x, note));
    return long(x);
  };
  const long first = whole_value(require(mask, "first", at), at / "first", "the index of the first coefficient");
  const Json& a = require(mask, "a", at);
  std::vector<double> coefficients;
  if (a.is_array()) {
    if (mask.contains("size")) fail(at / "size", "an array \"a\" gives the size itself; remove \"size\"");
    if (a.empty()) fail(at / "a", "expected a non-empty array of coefficients");
    for (size_t i = 0; i < a.size(); ++i) {
      const int id = add_curve_formula(formulas, as_formula(a[i], (at / "a")[i]), (at / "a")[i]);
      stationary(id, (at / "a")[i], true);
      coefficients.push_back(formulas.evaluate(id, {0, 0, double(i), 0}));
    }
  } else {
    const long size = whole_value(require(mask, "size", at), at / "size", "the number of coefficients");
    if (size < 1 || size > 1024)
      fail(at / "size", fmt::format("the mask has {} coefficients; it needs 1 to 1024{}", size, note));
    const int id = add_curve_formula(formulas, as_formula(a, at / "a"), at / "a");
    stationary(id, at / "a", true);
    for (long j = 0; j < size; ++j) coefficients.push_back(formulas.evaluate(id, {0, 0, double(j), 0}));
  }
  for (size_t j = 0; j < coefficients.size(); ++j)
    if (!std::isfinite(coefficients[j]))
      fail(at / "a", fmt::format("coefficient j = {} (a_{}) is {}{}", j, first + long(j), coefficients[j], note));
  const long last = first + long(coefficients.size()) - 1, m = curve.arity;
  for (long r = 0; r < m; ++r) {
    // Old points i + s with first <= r - m s <= last.
    long s_lo = -floor_div(last - r, m), s_hi = floor_div(r - first, m);
    auto coefficient = [&](long s) { return coefficients[size_t(r - m * s - first)]; };
    while (s_lo <= s_hi && coefficient(s_lo) == 0.0) ++s_lo;  // trim zeros at both ends
    while (s_hi >= s_lo && coefficient(s_hi) == 0.0) --s_hi;
    if (s_lo > s_hi)
      fail(at, fmt::format("the mask gives new point {} of each old point (a_i with i = {} mod {}) no "
                           "non-zero coefficient{}", r, r, m, note));
    curve.starts.push_back(int(s_lo));
    std::vector<std::string> weights;
    for (long s = s_lo; s <= s_hi; ++s) weights.push_back(fmt::format("{:.17g}", coefficient(s)));
    curve.weights.push_back(std::move(weights));
  }
}

// "ends": "interpolate" (default) | "uniform" | {"rules": [{"w": [...]}, ...]}.
void parse_ends(const Json& root, const Place& at, FormulaSet& formulas, CurveScheme& curve) {
  if (!root.contains("ends")) return;
  const Json& ends = root["ends"];
  const Place here = at / "ends";
  if (ends.is_string()) {
    const std::string mode = ends.get<std::string>();
    if (mode == "interpolate") curve.ends = CurveEnds::Interpolate;
    else if (mode == "uniform") curve.ends = CurveEnds::Uniform;
    else
      fail(here, fmt::format("{} is not one of: interpolate, uniform, or an object of end rules "
                             "{{\"rules\": [{{\"w\": [...]}}, ...]}}", subdiv::quoted(mode)));
    return;
  }
  if (!ends.is_object())
    fail(here, "expected \"interpolate\", \"uniform\" or an object {\"rules\": [{\"w\": [...]}, ...]}");
  check_keys(ends, {"rules"}, here);
  const Json& rules = require(ends, "rules", here);
  if (!rules.is_array() || rules.empty())
    fail(here / "rules", "expected a non-empty array of end rules; rule 0 gives the end point itself");
  for (size_t e = 0; e < rules.size(); ++e) {
    check_keys(rules[e], {"w"}, (here / "rules")[e]);
    curve.end_rules.push_back(parse_curve_weights(require(rules[e], "w", (here / "rules")[e]),
                                                  (here / "rules")[e] / "w", formulas));
  }
  curve.ends = CurveEnds::Rules;
}

// Every rule must give an affine combination (weights summing to 1) with finite weights.
// Checked here at level 0 so a bad file fails when loaded; the curve refiner checks every
// level it builds.
void check_curve_rules_at_level0(const CurveScheme& curve, const Place& at, bool from_mask) {
  FormulaSet formulas(curve.parameters, curve.definitions);
  auto check = [&](const std::vector<std::string>& weights, const Place& here) {
    double sum = 0, magnitude = 0;
    for (size_t t = 0; t < weights.size(); ++t) {
      const Place place = (here / "w")[t];
      const double w = formulas.evaluate(formulas.add(weights[t], place.str()), {0, 0, double(t), 0});
      if (!std::isfinite(w))
        fail(place, fmt::format("weight {} is {} at level 0{}", subdiv::quoted(weights[t]), w, parameter_note(curve)));
      sum += w, magnitude += std::abs(w);
    }
    if (std::abs(sum - 1.0) > 1e-9 * std::max(1.0, magnitude))
      fail(here, fmt::format("weights sum to {} at level 0, not 1{}: a new point must be an affine "
                             "combination of old points", sum, parameter_note(curve)));
  };
  // Places name the rule ("rules[1]: weights sum to ..."), weights within it by index.
  for (size_t r = 0; r < curve.weights.size(); ++r)
    check(curve.weights[r], from_mask ? at / fmt::format("mask (rule {} made from it)", r) : (at / "rules")[r]);
  for (size_t e = 0; e < curve.end_rules.size(); ++e) check(curve.end_rules[e], (at / "ends" / "rules")[e]);
}

}  // namespace

// The loaders below share these, from a parsed file or from text (plugins); `label` stands
// for the file in messages.
std::string scheme_json_kind(const Json& root, const std::string& label);
std::shared_ptr<const CurveScheme> curve_scheme_from_json(const Json& root, const std::string& label,
                                                          const ParameterOverrides& overrides,
                                                          std::set<std::string>* used);
std::shared_ptr<const Scheme> surface_scheme_from_json(const Json& root, const std::string& label,
                                                       const ParameterOverrides& overrides,
                                                       const CurveResolver& resolve_curve);

std::map<std::string, double> Scheme::parameter_values() const {
  std::map<std::string, double> values;
  for (const auto& p : parameters)
    if (!p.is_choice) values[p.name] = p.value;
  return values;
}

std::string scheme_file_kind(const std::filesystem::path& path) {
  return scheme_json_kind(read_json_file(path), path.string());
}

std::string scheme_text_kind(const std::string& text, const std::string& label) {
  return scheme_json_kind(parse_json_text(text, label), label);
}

std::string scheme_json_kind(const Json& root, const std::string& label) {
  const std::filesystem::path path = label;
  if (!root.is_object()) throw Error(fmt::format("{}: a scheme file holds a JSON object", path.string()));
  std::string kind = root.contains("kind") && root["kind"].is_string() ? root["kind"].get<std::string>() : "surface";
  if (kind != "surface" && kind != "curve")
    throw Error(fmt::format("{}: kind: {} is not one of: surface, curve", path.string(), subdiv::quoted(kind)));
  return kind;
}

// A value of the wrong JSON type the checks below did not foresee, as an error naming the
// file; any other exception (bad_alloc, length_error, ...) as an error naming the file.
// Messages that name a JSON path get the path's line ("FILE:LINE: path: ...").
template <class Load>
auto with_type_errors(const std::string& label, const std::string& text, Load load) {
  return naming_file_on_failure(label, [&] {
    try {
      return load(parse_json_text(text, label));
    } catch (const OptionError&) {
      throw;
    } catch (const Error& e) {
      throw Error(with_json_line(e.what(), label, text));
    } catch (const nlohmann::json::exception& e) {
      std::string what = e.what();
      if (auto pos = what.find("] "); pos != std::string::npos) what = what.substr(pos + 2);
      throw Error(fmt::format("{}: a value has the wrong JSON type ({}); docs/scheme-format.md shows each key's type",
                              label, shortened(what, 2 * kQuotedTextChars)));
    }
  });
}

std::shared_ptr<const CurveScheme> load_curve_scheme(const std::filesystem::path& path,
                                                     const ParameterOverrides& overrides,
                                                     std::set<std::string>* used) {
  return with_type_errors(path.string(), read_scheme_text(path),
                          [&](const Json& root) { return curve_scheme_from_json(root, path.string(), overrides, used); });
}

std::shared_ptr<const CurveScheme> load_curve_scheme_text(const std::string& text, const std::string& label,
                                                          const ParameterOverrides& overrides,
                                                          std::set<std::string>* used) {
  return with_type_errors(label, text, [&](const Json& root) { return curve_scheme_from_json(root, label, overrides, used); });
}

std::shared_ptr<const CurveScheme> curve_scheme_from_json(const Json& root, const std::string& label,
                                                          const ParameterOverrides& overrides,
                                                          std::set<std::string>* used) {
  const std::filesystem::path path = label;
  const Place at{path.string(), ""};
  check_keys(root, {"$schema", "name", "kind", "description", "reference", "arity", "parameters", "state",
                    "definitions", "rules", "mask", "ends", "variational"}, at);
  auto curve = std::make_shared<CurveScheme>();
  curve->path = path.string();
  curve->name = as_string(require(root, "name", at), at / "name");
  curve->description = optional_string(root, "description");
  if (root.contains("arity") && !root["arity"].is_number_integer())
    fail(at / "arity", fmt::format("expected 2 or 3, found {}", shortened(root["arity"].dump())));
  curve->arity = root.value("arity", 2);
  if (curve->arity != 2 && curve->arity != 3) fail(at / "arity", "arity must be 2 or 3");
  curve->parameter_specs = parse_parameters(root, at, overrides, used);
  for (const auto& p : curve->parameter_specs)
    if (!p.is_choice) curve->parameters[p.name] = p.value;
  curve->definitions = parse_definitions(root, at, curve->parameter_specs);
  FormulaSet formulas(curve->parameters, curve->definitions);

  const bool has_rules = root.contains("rules"), has_mask = root.contains("mask");
  const bool has_variational = root.contains("variational");
  if (int(has_rules) + int(has_mask) + int(has_variational) != 1)
    fail(at, "a curve scheme states exactly one of \"rules\" (one rule per new point of each old "
             "point), \"mask\" (the coefficients a_i of the refinement equation) or \"variational\" (the "
             "fairness energy its new points minimise)");
  if (has_variational) {
    if (root.contains("ends"))
      fail(at / "ends", "a variational scheme has no end rules: its energy decides the ends (docs/curves.md)");
    parse_variational(root["variational"], at / "variational", formulas, *curve);
    return curve;
  }
  if (has_rules) {
    const Json& rules = root["rules"];
    if (!rules.is_array() || int(rules.size()) != curve->arity)
      fail(at / "rules", fmt::format("a curve of arity {} needs {} rules, one per new point of each old point",
                                     curve->arity, curve->arity));
    for (size_t r = 0; r < rules.size(); ++r) {
      const Place here = (at / "rules")[r];
      check_keys(rules[r], {"start", "w"}, here);
      const Json& start = require(rules[r], "start", here);
      if (!start.is_number_integer())
        fail(here / "start", fmt::format("expected a whole number (the offset of the first old point), found {}",
                                         shortened(start.dump())));
      // A rule reaches old points i + start ... i + start + len(w) - 1: a start beyond this
      // is no local rule (-2^31 ran 14.5 s and exited 0).
      if (start.get<long long>() < -kMaxCurveStart || start.get<long long>() > kMaxCurveStart)
        fail(here / "start", fmt::format("{} is out of range: a rule starts at most {} old points away (from -{} to {})",
                                         shortened(start.dump()), kMaxCurveStart, kMaxCurveStart, kMaxCurveStart));
      curve->starts.push_back(start.get<int>());
      curve->weights.push_back(parse_curve_weights(require(rules[r], "w", here), here / "w", formulas));
    }
  } else {
    expand_mask(root["mask"], at / "mask", formulas, *curve);
  }
  parse_ends(root, at, formulas, *curve);
  check_curve_rules_at_level0(*curve, at, has_mask);
  return curve;
}

std::shared_ptr<const Scheme> load_surface_scheme(const std::filesystem::path& path,
                                                  const ParameterOverrides& overrides,
                                                  const CurveResolver& resolve_curve) {
  return with_type_errors(path.string(), read_scheme_text(path), [&](const Json& root) {
    return surface_scheme_from_json(root, path.string(), overrides, resolve_curve);
  });
}

std::shared_ptr<const Scheme> load_surface_scheme_text(const std::string& text, const std::string& label,
                                                       const ParameterOverrides& overrides,
                                                       const CurveResolver& resolve_curve) {
  return with_type_errors(label, text, [&](const Json& root) {
    return surface_scheme_from_json(root, label, overrides, resolve_curve);
  });
}

std::shared_ptr<const Scheme> surface_scheme_from_json(const Json& root, const std::string& label,
                                                       const ParameterOverrides& overrides,
                                                       const CurveResolver& resolve_curve) {
  const std::filesystem::path path = label;
  if (!root.is_object()) throw Error(fmt::format("{}: a scheme holds a JSON object", label));
  const Place at{path.string(), ""};
  check_keys(root, {"$schema", "name", "kind", "description", "reference", "split", "faces", "curve", "state",
                    "parameters", "definitions", "rules", "steps"}, at);
  auto s = std::make_shared<Scheme>();
  s->path = path.string();
  s->name = as_string(require(root, "name", at), at / "name");
  s->description = optional_string(root, "description");
  s->required_face_size = parse_face_requirement(root, at);
  std::set<std::string> used;
  s->parameters = parse_parameters(root, at, overrides, &used);
  s->definitions = parse_definitions(root, at, s->parameters);
  const ParsedSteps parsed = parse_steps(root, at);
  const std::vector<size_t> kept = unroll_steps(parsed, *s, at);
  for (size_t i : kept) s->steps.push_back(parsed.steps[i]);
  const SplitKind split = s->split();
  if (s->required_face_size == 4 && splitter_info(split).required_face_size == 3)
    fail(at / "faces", "this split works on triangles; \"faces\" must be \"triangles\"");
  if (s->steps.size() > 1) s->steps.front().curve_rules_apply = false;
  if (root.contains("curve")) {
    // Overrides the surface scheme does not take go to its curve scheme (e.g. a tension).
    ParameterOverrides curve_overrides;
    for (const auto& [name, value] : overrides)
      if (!used.count(name)) curve_overrides[name] = value;
    s->curve = curve_at(resolve_curve, as_string(root["curve"], at / "curve"), at / "curve", curve_overrides, &used);
    check_curve_fits_split(*s->curve, s->split(), at / "curve");
  }
  // A split's own curve scheme: its boundaries and creases follow it even when smoothing
  // passes come after it (a dual split in a composite scheme cuts features like Chaikin).
  // Every split's curve is checked, whether or not "when" keeps the split.
  ParameterOverrides curve_overrides;
  for (const auto& [name, value] : overrides)
    if (!used.count(name)) curve_overrides[name] = value;
  for (size_t i = 0; i < parsed.steps.size(); ++i) {
    if (parsed.curves[i].empty()) continue;
    auto curve = curve_at(resolve_curve, parsed.curves[i], parsed.curve_places[i], curve_overrides, &used);
    check_curve_fits_split(*curve, parsed.steps[i].split, parsed.curve_places[i]);
    if (i == kept.front()) s->steps.front().curve = std::move(curve);
  }
  check_unknown_overrides(overrides, used, path.string());
  check_formulas(*s);
  return s;
}

void apply_parameter_overrides(std::vector<ParameterSpec>& params, const ParameterOverrides& overrides,
                               const std::string& label, std::set<std::string>* used) {
  for (ParameterSpec& p : params) {
    if (auto o = overrides.find(p.name); o != overrides.end()) {
      apply_override(p, o->second, label);
      if (used) used->insert(p.name);
    }
    check_range(p, label);
  }
}

}  // namespace subdiv
