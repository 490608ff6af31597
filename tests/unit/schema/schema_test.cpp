// schemes/scheme.schema.json against the shipped schemes, the engine and the docs.
//
// No JSON Schema library is packaged for C++ on Debian, so this file carries a small
// validator for exactly the keywords the schema uses (and fails on any other keyword, so a
// new keyword in the schema needs a line here). On top of validation it checks, by walking
// the schema, that the names it lists (top-level keys, elements, contexts, roles, new
// points, splits) are the names the engine accepts, and that every complete scheme file
// shown in docs/scheme-format.md validates, loads and refines a bundled mesh. It also checks
// the schema is at least as strict as the loader: every variation of a term, a rule, a
// split's elements and a step that the loader refuses, the schema refuses too.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <unistd.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/refine/splitter.h"
#include "framework/rules/rule.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"

using Json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

fs::path source(const std::string& relative) { return fs::path(SUBDIV_SOURCE_DIR) / relative; }

Json read_json(const fs::path& file) {
  std::ifstream in(file);
  REQUIRE_MESSAGE(in.good(), "cannot open " << file.string());
  return Json::parse(in);
}

const Json& schema() {
  static const Json s = read_json(source("schemes/scheme.schema.json"));
  return s;
}

std::vector<fs::path> shipped_schemes() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(source("schemes")))
    if (entry.path().extension() == ".json" && entry.path().filename() != "scheme.schema.json")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// ---- a validator for the JSON Schema keywords scheme.schema.json uses -----------------

const std::set<std::string> kAnnotations = {"$schema", "$id", "$defs", "title", "description", "default"};
const std::set<std::string> kKeywords = {
    "type", "enum", "const", "properties", "additionalProperties", "required", "propertyNames",
    "pattern", "items", "prefixItems", "minItems", "maxItems", "anyOf", "oneOf", "allOf", "not", "if",
    "then", "else", "$ref", "minimum", "maximum"};

// "#/$defs/name" -> the definition.
const Json& resolve(const std::string& ref) {
  const std::string prefix = "#/$defs/";
  if (ref.rfind(prefix, 0) != 0) throw std::runtime_error("unsupported $ref " + ref);
  const std::string name = ref.substr(prefix.size());
  if (!schema().contains("$defs") || !schema()["$defs"].contains(name))
    throw std::runtime_error("$ref to a missing definition: " + ref);
  return schema()["$defs"][name];
}

bool has_type(const Json& value, const std::string& type) {
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  if (type == "string") return value.is_string();
  if (type == "number") return value.is_number();
  if (type == "integer") return value.is_number_integer() || (value.is_number_float() && value.get<double>() == std::floor(value.get<double>()));
  if (type == "boolean") return value.is_boolean();
  if (type == "null") return value.is_null();
  throw std::runtime_error("unknown type " + type);
}

// Appends "path: problem" for every violation of `s` by `value`.
void validate(const Json& s, const Json& value, const std::string& path, std::vector<std::string>& errors);

bool valid(const Json& s, const Json& value) {
  std::vector<std::string> errors;
  validate(s, value, "", errors);
  return errors.empty();
}

void validate(const Json& s, const Json& value, const std::string& path, std::vector<std::string>& errors) {
  if (s.is_boolean()) {
    if (!s.get<bool>()) errors.push_back(path + ": not allowed");
    return;
  }
  for (auto it = s.begin(); it != s.end(); ++it)
    if (!kKeywords.count(it.key()) && !kAnnotations.count(it.key()))
      throw std::runtime_error("the test's validator does not know keyword '" + it.key() + "'");
  const std::string at = path.empty() ? "(top)" : path;
  auto fail = [&](const std::string& what) { errors.push_back(at + ": " + what); };

  if (s.contains("$ref")) validate(resolve(s["$ref"]), value, path, errors);
  if (s.contains("type")) {
    const Json& t = s["type"];
    bool ok = false;
    if (t.is_string()) ok = has_type(value, t);
    else for (const auto& one : t) ok = ok || has_type(value, one);
    if (!ok) return fail("expected type " + t.dump() + ", found " + value.dump());
  }
  if (s.contains("enum")) {
    bool found = false;
    for (const auto& e : s["enum"]) found = found || e == value;
    if (!found) fail(value.dump() + " is not one of " + s["enum"].dump());
  }
  if (s.contains("const") && s["const"] != value) fail(value.dump() + " is not " + s["const"].dump());
  if (value.is_number() && s.contains("minimum") && value.get<double>() < s["minimum"].get<double>())
    fail(value.dump() + " is below the minimum " + s["minimum"].dump());
  if (value.is_number() && s.contains("maximum") && value.get<double>() > s["maximum"].get<double>())
    fail(value.dump() + " is above the maximum " + s["maximum"].dump());
  if (s.contains("pattern") && value.is_string() &&
      !std::regex_search(value.get<std::string>(), std::regex(s["pattern"].get<std::string>())))
    fail(value.dump() + " does not match " + s["pattern"].dump());
  if (value.is_object()) {
    if (s.contains("required"))
      for (const auto& key : s["required"])
        if (!value.contains(key.get<std::string>())) fail("missing \"" + key.get<std::string>() + "\"");
    for (auto it = value.begin(); it != value.end(); ++it) {
      const std::string child = path.empty() ? it.key() : path + "." + it.key();
      if (s.contains("propertyNames")) validate(s["propertyNames"], Json(it.key()), child, errors);
      if (s.contains("properties") && s["properties"].contains(it.key()))
        validate(s["properties"][it.key()], it.value(), child, errors);
      else if (s.contains("additionalProperties")) {
        const Json& extra = s["additionalProperties"];
        if (extra.is_boolean() && !extra.get<bool>()) fail("unknown key \"" + it.key() + "\"");
        else validate(extra, it.value(), child, errors);
      }
    }
  }
  if (value.is_array()) {
    if (s.contains("minItems") && value.size() < s["minItems"].get<size_t>())
      fail("needs at least " + s["minItems"].dump() + " items");
    if (s.contains("maxItems") && value.size() > s["maxItems"].get<size_t>())
      fail("allows at most " + s["maxItems"].dump() + " items");
    // Draft 2020-12: prefixItems describe the first items, items the ones after them.
    size_t prefix = 0;
    if (s.contains("prefixItems")) {
      prefix = s["prefixItems"].size();
      for (size_t i = 0; i < std::min(prefix, value.size()); ++i)
        validate(s["prefixItems"][i], value[i], path + "[" + std::to_string(i) + "]", errors);
    }
    if (s.contains("items"))
      for (size_t i = prefix; i < value.size(); ++i)
        validate(s["items"], value[i], path + "[" + std::to_string(i) + "]", errors);
  }
  if (s.contains("allOf"))
    for (const auto& sub : s["allOf"]) validate(sub, value, path, errors);
  if (s.contains("anyOf")) {
    bool any = false;
    for (const auto& sub : s["anyOf"]) any = any || valid(sub, value);
    if (!any) fail("matches none of the allowed forms");
  }
  if (s.contains("oneOf")) {
    int count = 0;
    for (const auto& sub : s["oneOf"]) count += valid(sub, value);
    if (count != 1) fail("must match exactly one form, matches " + std::to_string(count));
  }
  if (s.contains("not") && valid(s["not"], value)) fail("matches a form that is not allowed");
  if (s.contains("if")) {
    if (valid(s["if"], value)) {
      if (s.contains("then")) validate(s["then"], value, path, errors);
    } else if (s.contains("else")) {
      validate(s["else"], value, path, errors);
    }
  }
}

std::string validation_report(const Json& document) {
  std::vector<std::string> errors;
  validate(schema(), document, "", errors);
  std::string report;
  for (const auto& e : errors) report += e + "\n";
  return report;
}

// ---- reading names out of the schema ---------------------------------------------------

const Json& def(const std::string& name) { return resolve("#/$defs/" + name); }

std::set<std::string> property_names(const Json& s) {
  std::set<std::string> names;
  for (auto it = s["properties"].begin(); it != s["properties"].end(); ++it) names.insert(it.key());
  return names;
}

std::set<std::string> enum_of(const Json& s) {
  std::set<std::string> names;
  for (const auto& e : s["enum"]) names.insert(e.get<std::string>());
  return names;
}

// The contexts a rule of this element may name: the object form among the rule's anyOf.
std::set<std::string> contexts_of(const std::string& rule_def) {
  for (const auto& form : def(rule_def)["anyOf"])
    if (form.contains("properties")) return property_names(form);
  return {};
}

std::string term_def(subdiv::Element e) { return std::string(subdiv::element_name(e)) + "Term"; }

// The split a scheme file names: top-level, or in its first step.
std::string split_of(const Json& scheme) {
  if (scheme.contains("split")) return scheme["split"];
  return scheme["steps"][0]["split"];
}

// Roles a term of this element may name in the schema, "at" and "sum" together.
std::set<std::string> roles_of(subdiv::Element e) {
  const Json& term = def(term_def(e));
  std::set<std::string> roles = enum_of(term["properties"]["sum"]);
  if (term["properties"].contains("at")) roles.merge(enum_of(term["properties"]["at"]));
  return roles;
}

// ---- the docs: complete scheme files in ```json blocks --------------------------------

std::vector<std::string> json_blocks(const fs::path& markdown) {
  std::ifstream in(markdown);
  std::vector<std::string> blocks;
  std::string line, block;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside && line == "```json") inside = true, block.clear();
    else if (inside && line.rfind("```", 0) == 0) inside = false, blocks.push_back(block);
    else if (inside) block += line + "\n";
  }
  return blocks;
}

}  // namespace

TEST_CASE("the schema parses and uses only what this test's validator understands") {
  const Json& s = schema();
  REQUIRE(s.is_object());
  CHECK(s["$schema"] == "https://json-schema.org/draft/2020-12/schema");
  CHECK(s["$defs"].contains("surfaceScheme"));
  CHECK(s["$defs"].contains("curveScheme"));
  // Walk every subschema: known keywords only, every $ref resolves.
  std::vector<const Json*> todo{&s};
  int visited = 0;
  while (!todo.empty()) {
    const Json& node = *todo.back();
    todo.pop_back();
    ++visited;
    if (!node.is_object()) continue;
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string& key = it.key();
      CHECK_MESSAGE((kKeywords.count(key) || kAnnotations.count(key)), "unknown keyword " << key);
      if (key == "$ref") CHECK_NOTHROW(resolve(it.value()));
      if (key == "properties" || key == "$defs")
        for (const auto& sub : it.value()) todo.push_back(&sub);
      else if (key == "anyOf" || key == "oneOf" || key == "allOf" || key == "prefixItems")
        for (const auto& sub : it.value()) todo.push_back(&sub);
      else if (key == "items" || key == "not" || key == "if" || key == "then" || key == "else" ||
               key == "propertyNames" || (key == "additionalProperties" && it.value().is_object()))
        todo.push_back(&it.value());
    }
  }
  CHECK(visited > 50);
}

TEST_CASE("every shipped scheme validates against the schema and says where the schema is") {
  const auto files = shipped_schemes();
  REQUIRE(files.size() >= 6);
  for (const auto& file : files) {
    CAPTURE(file.string());
    const Json scheme = read_json(file);
    CHECK(scheme.value("$schema", "") == "./scheme.schema.json");
    const std::string report = validation_report(scheme);
    CHECK_MESSAGE(report.empty(), report);
  }
}

TEST_CASE("every key, element, context and role a shipped scheme uses is listed in the schema") {
  const std::set<std::string> surface_keys = property_names(def("surfaceScheme"));
  const std::set<std::string> curve_keys = property_names(def("curveScheme"));
  const std::set<std::string> elements = property_names(def("surfaceRules"));
  for (const auto& file : shipped_schemes()) {
    CAPTURE(file.string());
    const Json scheme = read_json(file);
    const bool curve = scheme.value("kind", "surface") == "curve";
    for (auto it = scheme.begin(); it != scheme.end(); ++it)
      CHECK_MESSAGE((curve ? curve_keys : surface_keys).count(it.key()), "top-level key " << it.key());
    if (curve) {
      if (!scheme.contains("rules")) continue;  // a curve may state its mask instead
      for (const auto& rule : scheme["rules"])
        for (auto it = rule.begin(); it != rule.end(); ++it)
          CHECK_MESSAGE(property_names(def("curveRule")).count(it.key()), "curve rule key " << it.key());
      continue;
    }
    // The rule objects of the scheme: its split's rules, and each smoothing pass's.
    std::vector<std::pair<const Json*, bool>> rule_objects;  // (rules, is a smoothing pass)
    if (scheme.contains("rules")) rule_objects.push_back({&scheme["rules"], false});
    if (scheme.contains("steps"))
      for (const auto& step : scheme["steps"]) {
        if (step.contains("rules")) rule_objects.push_back({&step["rules"], false});
        if (step.contains("smooth")) rule_objects.push_back({&step["smooth"], true});
        for (auto k = step.begin(); k != step.end(); ++k)
          CHECK_MESSAGE((property_names(def("splitStep")).count(k.key()) || property_names(def("smoothStep")).count(k.key())),
                        "step key " << k.key());
      }
    REQUIRE(!rule_objects.empty());
    for (const auto& [rules_object, pass] : rule_objects)
      for (auto it = rules_object->begin(); it != rules_object->end(); ++it) {
        const std::string element = it.key();
        REQUIRE_MESSAGE(elements.count(element), "element " << element);
        const subdiv::Element e = element == "face" ? subdiv::Element::Face
                                  : element == "edge" ? subdiv::Element::Edge
                                  : element == "corner" ? subdiv::Element::Corner
                                                        : subdiv::Element::Vertex;
        const std::set<std::string> roles = roles_of(e);
        const Json& term_schema = def(term_def(e));
        const std::string rule_def = pass ? "passVertexRule" : element + "Rule";
        std::vector<const Json*> rules;
        if (it.value().is_array()) rules.push_back(&it.value());
        else
          for (auto c = it.value().begin(); c != it.value().end(); ++c) {
            CHECK_MESSAGE(contexts_of(rule_def).count(c.key()), element << " context " << c.key());
            if (c.key() == "crease-ends")  // rules by distance from a corner: each entry holds one
              for (const auto& entry : c.value()) rules.push_back(&entry["rule"]);
            else rules.push_back(&c.value());
          }
        for (const Json* rule : rules)
          for (const auto& term : *rule) {
            for (auto k = term.begin(); k != term.end(); ++k)
              CHECK_MESSAGE(term_schema["properties"].contains(k.key()), element << " term key " << k.key());
            const std::string role = term.contains("at") ? term["at"] : term["sum"];
            CHECK_MESSAGE(roles.count(role), element << " role " << role);
            if (term.contains("new"))
              CHECK_MESSAGE(enum_of(term_schema["properties"]["new"]).count(term["new"].get<std::string>()), "new " << term["new"]);
          }
      }
  }
}

TEST_CASE("the schema's names are the engine's names") {
  using namespace subdiv;
  // Splits.
  const std::set<std::string> splits = enum_of(def("split"));
  for (const auto& split : splits) CHECK_NOTHROW(split_kind_from_name(split));
  CHECK(splits == std::set<std::string>{"quad", "triangle", "sqrt3", "dual", "mid-edge"});
  CHECK_THROWS_AS(split_kind_from_name("hex"), Error);
  // Elements.
  std::set<std::string> engine_elements;
  for (int e = 0; e < kElementCount; ++e) engine_elements.insert(std::string(element_name(Element(e))));
  CHECK(property_names(def("surfaceRules")) == engine_elements);
  // Contexts: vertex rules (of a split and of a pass) may name all of them; every context
  // named anywhere exists.
  std::set<std::string> engine_contexts;
  for (int c = 0; c < kContextCount; ++c) engine_contexts.insert(std::string(context_name(Context(c))));
  // Vertex rules also take "crease-ends", crease rules by distance from a corner.
  for (const char* rule : {"vertexRule", "passVertexRule"}) {
    std::set<std::string> contexts = contexts_of(rule);
    CHECK(contexts.erase("crease-ends") == 1);
    CHECK(contexts == engine_contexts);
  }
  for (const char* rule : {"faceRule", "edgeRule", "cornerRule"})
    for (const auto& c : contexts_of(rule)) CHECK_MESSAGE(context_from_name(c).has_value(), rule << " " << c);
  // Roles: per element, the schema lists exactly the roles the engine allows there, except
  // 'curve', which only the engine's crease defaults use and a file cannot name.
  std::set<std::string> all_roles;
  for (int r = 0; r <= int(Role::CreasePoint); ++r)
    if (Role(r) != Role::Curve) all_roles.insert(std::string(role_name(Role(r))));
  CHECK(all_roles.size() == 19);
  for (int e = 0; e < kElementCount; ++e) {
    std::set<std::string> engine_roles;
    for (const auto& name : all_roles) {
      const auto role = role_from_name(name);
      REQUIRE(role.has_value());
      if (role_allowed(Element(e), *role)) engine_roles.insert(name);
    }
    CHECK_MESSAGE(roles_of(Element(e)) == engine_roles, element_name(Element(e)));
    if (def(term_def(Element(e)))["properties"].contains("new"))
      for (const auto& n : enum_of(def(term_def(Element(e)))["properties"]["new"]))
        CHECK(new_point_from_name(n).has_value());
  }
  // Curve arities.
  CHECK(def("curveScheme")["properties"]["arity"]["enum"] == Json::array({2, 3}));
}

namespace {

// Loads a scheme text with the engine's loader: true if it loads.
bool loader_accepts(const Json& scheme) {
  // One directory per process (test runs in other checkouts share /tmp), removed at exit.
  struct ProbeDir {
    fs::path path = fs::temp_directory_path() / ("subdivkit-schema-loader-" + std::to_string(getpid()));
    ProbeDir() { fs::create_directories(path); }
    ~ProbeDir() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const ProbeDir dir;
  const fs::path file = dir.path / "probe.json";
  std::ofstream(file) << scheme.dump(2);
  try {
    subdiv::load_scheme(file.string());
    return true;
  } catch (const std::exception&) {  // subdiv::Error, or a JSON type error the loader lets through
    return false;
  }
}

// The smallest valid term of each element's rules.
Json simple_term(subdiv::Element e) {
  switch (e) {
    case subdiv::Element::Vertex: return {{"at", "self"}, {"w", "1"}};
    case subdiv::Element::Edge: return {{"sum", "ends"}, {"w", "1/2"}};
    case subdiv::Element::Face: return {{"sum", "vertices"}, {"w", "1/k"}};
    case subdiv::Element::Corner: return {{"at", "self"}, {"w", "1"}};
  }
  return {};
}

// A split that makes new points of element e.
std::string split_with(subdiv::Element e) {
  switch (e) {
    case subdiv::Element::Vertex: case subdiv::Element::Edge: case subdiv::Element::Face: return "quad";
    case subdiv::Element::Corner: return "dual";
  }
  return "quad";
}

// Every term the language could spell for a role: at or sum, with and without each "new".
std::vector<Json> term_variants(const std::string& role) {
  std::vector<Json> out;
  for (const char* how : {"at", "sum"})
    for (const char* np : {"", "face", "edge", "vertex"}) {
      Json t = {{how, role}, {"w", "1"}};
      if (*np) t["new"] = np;
      out.push_back(t);
    }
  return out;
}

}  // namespace

TEST_CASE("the schema refuses what the loader refuses") {
  const Json cc = read_json(source("schemes/catmull-clark.json"));
  auto refused = [&](const std::string& what, const Json& base, const std::function<void(Json&)>& change) {
    Json s = base;
    change(s);
    CHECK_MESSAGE(!validation_report(s).empty(), what);
    CHECK_MESSAGE(!loader_accepts(s), what << " (the loader should refuse it too)");
  };
  CHECK(validation_report(cc).empty());
  CHECK(loader_accepts(cc));
  refused("unknown role", cc, [](Json& s) { s["rules"]["vertex"][1]["sum"] = "neighbours"; });
  refused("unknown top-level key", cc, [](Json& s) { s["splits"] = "quad"; });
  refused("unknown split", cc, [](Json& s) { s["split"] = "hex"; });
  refused("faces without new", cc, [](Json& s) { s["rules"]["vertex"][2].erase("new"); });
  refused("at with a role of several points", cc, [](Json& s) { s["rules"]["vertex"][1] = {{"at", "ring"}, {"w", "1"}}; });
  refused("both at and sum", cc, [](Json& s) { s["rules"]["vertex"][0]["sum"] = "ring"; });
  refused("a term without w", cc, [](Json& s) { s["rules"]["vertex"][0].erase("w"); });
  refused("contexts without smooth", cc, [](Json& s) { s["rules"]["vertex"] = {{"corner", Json::array()}}; });
  refused("unknown context", cc, [](Json& s) {
    s["rules"]["vertex"] = {{"smooth", s["rules"]["vertex"]}, {"boundary", Json::array()}};
  });
  refused("crease-neighbours outside a crease rule", cc, [](Json& s) {
    s["rules"]["vertex"] = {{"smooth", s["rules"]["vertex"]},
                            {"dart", Json::array({{{"sum", "crease-neighbours"}, {"w", "1/2"}}})}};
  });
  refused("a vertex role in a face rule", cc, [](Json& s) { s["rules"]["face"][0]["sum"] = "ring"; });
  refused("a corner rule in a quad split", cc, [](Json& s) { s["rules"]["corner"] = Json::array({simple_term(subdiv::Element::Corner)}); });
  refused("a choice default that is a number", cc, [](Json& s) {
    s["parameters"] = {{"b", {{"default", 1}, {"choices", {"x", "y"}}}}};
  });
  refused("min_exclusive that is not a boolean", cc, [](Json& s) {
    s["parameters"] = {{"b", {{"default", 1}, {"min", 0}, {"min_exclusive", "yes"}}}};
  });
  refused("a bound that is not a number", cc, [](Json& s) { s["parameters"] = {{"b", {{"default", 1}, {"max", "2"}}}}; });
  refused("split and steps together", cc, [&](Json& s) {
    s["steps"] = Json::array({{{"split", "quad"}, {"rules", cc["rules"]}}});
  });
  const Json qb = read_json(source("schemes/quad-bspline.json"));
  CHECK(validation_report(qb).empty());
  CHECK(loader_accepts(qb));
  refused("no steps", qb, [](Json& s) { s["steps"] = Json::array(); });
  // quad-bspline: steps[0] and steps[1] are splits chosen by "when", steps[2] the pass.
  refused("a smoothing pass first", qb, [](Json& s) { std::swap(s["steps"][0], s["steps"][2]); });
  refused("a second split without when", qb, [](Json& s) {
    s["steps"][1] = s["steps"][0];
    s["steps"][1].erase("when");
  });
  refused("a curve that is not a string", qb, [](Json& s) { s["steps"][1]["curve"] = 2; });
  refused("an edge rule in a smoothing pass", qb, [](Json& s) {
    s["steps"][2]["smooth"]["edge"] = Json::array({simple_term(subdiv::Element::Edge)});
  });
  refused("an unknown key in a step", qb, [](Json& s) { s["steps"][2]["repeats"] = 2; });
  // steps[3]: the pass with crease rules by distance from a corner (crease-ends).
  auto ends = [](Json& s) -> Json& { return s["steps"][3]["smooth"]["vertex"]["crease-ends"]; };
  refused("a crease-end distance 0", qb, [&](Json& s) { ends(s)[0]["distance"] = 0; });
  refused("a crease-end distance that is not whole", qb, [&](Json& s) { ends(s)[0]["distance"] = 1.5; });
  refused("a crease-end without its rule", qb, [&](Json& s) { ends(s)[0].erase("rule"); });
  refused("crease-point without step", qb, [&](Json& s) { ends(s)[1]["rule"][0].erase("step"); });
  refused("step on self", qb, [&](Json& s) { ends(s)[0]["rule"][0]["step"] = 1; });
  refused("a step beyond 24", qb, [&](Json& s) { ends(s)[1]["rule"][2]["step"] = 25; });
  refused("crease-point in a smooth rule", qb, [](Json& s) {
    s["steps"][3]["smooth"]["vertex"]["smooth"] = Json::array({{{"at", "crease-point"}, {"step", 1}, {"w", "1"}}});
  });
  // What only the loader can see: "when" leaving two splits (or a split after a pass), and
  // a split's own curve that does not fit it, even where "when" drops that split.
  auto loader_refuses = [&](const std::string& what, const std::function<void(Json&)>& change) {
    Json s = qb;
    change(s);
    CHECK_MESSAGE(!loader_accepts(s), what);
  };
  loader_refuses("two splits left by when", [](Json& s) { s["steps"][1]["when"] = "1"; });
  loader_refuses("no split left by when", [](Json& s) { s["steps"][0]["when"] = "0"; });
  loader_refuses("a split after a pass", [](Json& s) {
    s["steps"] = Json::array({s["steps"][0], s["steps"][2], s["steps"][1]});
  });
  loader_refuses("a ternary curve on a dual split", [](Json& s) { s["steps"][1]["curve"] = "ternary-cubic-bspline"; });
  refused("a face rule in the triangle split of a composite scheme", read_json(source("schemes/loop-composite.json")),
          [](Json& s) { s["steps"][0]["rules"]["face"] = Json::array({simple_term(subdiv::Element::Face)}); });
  Json curve = read_json(source("schemes/cubic-bspline.json"));
  CHECK(validation_report(curve).empty());
  curve["arity"] = 3;
  CHECK_MESSAGE(!validation_report(curve).empty(), "arity 3 with 2 rules");
}

TEST_CASE("each split's elements: the schema and the loader agree") {
  using namespace subdiv;
  for (const auto& split : enum_of(def("split")))
    for (int e = 0; e < kElementCount; ++e) {
      const Json scheme = {{"name", "probe"}, {"split", split},
                           {"rules", {{std::string(element_name(Element(e))), Json::array({simple_term(Element(e))})}}}};
      CAPTURE(scheme.dump());
      CHECK(validation_report(scheme).empty() == loader_accepts(scheme));
    }
}

TEST_CASE("every term, rule context and smoothing-pass term the loader refuses, the schema refuses") {
  using namespace subdiv;
  std::vector<std::string> roles;
  for (int r = 0; r <= int(Role::Curve); ++r) roles.push_back(std::string(role_name(Role(r))));
  roles.push_back("neighbours");
  int accepted_by_both = 0, schema_stricter = 0;
  auto compare = [&](const Json& scheme) {
    const bool schema_ok = validation_report(scheme).empty(), loader_ok = loader_accepts(scheme);
    if (!loader_ok) CHECK_MESSAGE(!schema_ok, "the schema accepts what the loader refuses: " << scheme.dump());
    accepted_by_both += schema_ok && loader_ok;
    schema_stricter += !schema_ok && loader_ok;
    if (!schema_ok && loader_ok && std::getenv("SUBDIV_SCHEMA_TEST_LIST")) MESSAGE("schema only refuses: " << scheme.dump());
  };
  for (int e = 0; e < kElementCount; ++e) {
    const std::string element(element_name(Element(e)));
    for (int c = 0; c < kContextCount; ++c)
      for (const auto& role : roles)
        for (const Json& term : term_variants(role)) {
          Json rule = {{"smooth", Json::array({simple_term(Element(e))})}};
          rule[std::string(context_name(Context(c)))] = Json::array({term});
          compare({{"name", "probe"}, {"split", split_with(Element(e))}, {"rules", {{element, rule}}}});
          if (c == 0) compare({{"name", "probe"}, {"split", split_with(Element(e))}, {"rules", {{element, Json::array({term})}}}});
        }
  }
  // Smoothing passes: vertex rules only.
  for (int c = 0; c < kContextCount; ++c)
    for (const auto& role : roles)
      for (const Json& term : term_variants(role)) {
        Json rule = {{"smooth", Json::array({simple_term(Element::Vertex)})}};
        rule[std::string(context_name(Context(c)))] = Json::array({term});
        const Json split_step = {{"split", "quad"}, {"rules", {{"vertex", Json::array({simple_term(Element::Vertex)})}}}};
        compare({{"name", "probe"}, {"steps", Json::array({split_step, {{"smooth", {{"vertex", rule}}}}})}});
      }
  // Both accept the useful terms; the schema is stricter only where the loader accepts a
  // term that has no effect or always fails when a mesh is refined (contexts the engine
  // never uses, "new": "vertex" outside face rules, faces and edges in smoothing passes,
  // crease-neighbours in an array-form rule). SUBDIV_SCHEMA_TEST_LIST=1 lists them.
  CHECK(accepted_by_both > 60);
  MESSAGE("terms accepted by both: " << accepted_by_both << ", refused by the schema only: " << schema_stricter);
}

TEST_CASE("every complete scheme file in docs/scheme-format.md validates, loads and refines") {
  const fs::path doc = source("docs/scheme-format.md");
  REQUIRE(fs::exists(doc));
  const auto blocks = json_blocks(doc);
  REQUIRE(blocks.size() >= 4);
  // Written under their names into one directory, in the order of the doc, and loaded at
  // once: a surface example can refer to a curve example shown before it by file name.
  const fs::path dir = fs::temp_directory_path() / "subdivkit-schema-doc-examples";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& text : blocks) {
    CAPTURE(text);
    Json scheme;
    REQUIRE_NOTHROW(scheme = Json::parse(text));
    const std::string report = validation_report(scheme);
    CHECK_MESSAGE(report.empty(), report);
    const fs::path file = dir / (scheme["name"].get<std::string>() + ".json");
    std::ofstream(file) << text;
    if (scheme.value("kind", "surface") == "curve") {
      CHECK_NOTHROW(subdiv::load_curve_scheme(file, {}));
      continue;
    }
    std::shared_ptr<const subdiv::Scheme> loaded;
    try {
      loaded = subdiv::load_scheme(file.string());
    } catch (const subdiv::Error& e) {
      FAIL(std::string(e.what()));
    }
    // Refine bundled meshes of the faces the scheme takes: closed, creased, with boundaries.
    const std::string split = split_of(scheme);
    const bool triangles = split == "triangle" || split == "sqrt3" || scheme.value("faces", "any") == "triangles";
    const bool quads = scheme.value("faces", "any") == "quads";
    const std::vector<std::string> meshes =
        triangles ? std::vector<std::string>{"octahedron.obj", "tetrahedron.obj"}
        : quads   ? std::vector<std::string>{"cube.obj", "cube-creased.obj", "plane-with-hole.obj", "torus-quads.obj"}
                  : std::vector<std::string>{"cube.obj", "cube-creased.obj", "plane-with-hole.obj", "pyramid.obj"};
    for (const auto& name : meshes) {
      CAPTURE(name);
      const fs::path mesh_file = source("examples/meshes/" + name);
      const subdiv::MeshData mesh = subdiv::read_mesh(mesh_file);
      subdiv::RefineOptions options;
      options.levels = 2;
      try {
        const auto h = subdiv::refine(*loaded, subdiv::level_from_mesh(mesh, mesh_file.string()), options);
        CHECK(h.levels.size() == 3);
      } catch (const subdiv::Error& e) {
        FAIL(std::string(e.what()));
      }
    }
  }
  fs::remove_all(dir);
}
