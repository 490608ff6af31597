#pragma once
// What a plugin registers. The plugin's registration callback (plugin_api.h) receives a
// PluginRegistry and adds schemes, curve schemes, splitters and rule roles to it. Nothing
// reaches SubdivKit until the callback has returned: then everything is checked (names
// free, functions present, JSON schemes load) and registered together, or the plugin is
// refused as a whole and nothing of it stays.
//
// Geometry written in C++ comes in two kinds:
//  - linear: CodeRules write one stencil row per new point (rules/code_rules.h). The scheme
//    then has stencil tables like any JSON scheme: composition, analysis, fast apply;
//  - non-linear: a NonlinearRule computes the child values from the parent values after
//    the topology is refined. No stencils; the engine applies it directly.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/refine/splitter.h"
#include "framework/rules/code_rules.h"
#include "framework/rules/rule.h"
#include "framework/scheme/scheme.h"

namespace subdiv {

// Parameter values after --param overrides, as a scheme's make function sees them.
struct ParameterValues {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> choices;
  // Throw subdiv::Error naming the parameter when it does not exist.
  double number(const std::string& name) const;
  const std::string& choice(const std::string& name) const;
};

// A numeric parameter with its default and range, for the specs below.
ParameterSpec number_parameter(std::string name, double value, std::string description,
                               std::optional<double> minimum = std::nullopt,
                               std::optional<double> maximum = std::nullopt);

// A surface scheme whose geometry is C++ code. Give exactly one of `linear` or
// `nonlinear`: a function called with the parameter values each time the scheme is loaded
// (once per `subdiv refine`), returning the rules.
struct SurfaceSchemeSpec {
  std::string name, description;
  std::string split = "quad";      // a built-in splitter or one a plugin registered
  int required_face_size = 0;      // 0: whatever the splitter accepts; 3 or 4 to insist
  // Curve scheme for boundaries and creases (a name, e.g. "cubic-bspline"); empty: none,
  // and then meshes with boundaries or creases are refused unless the code rules handle
  // features themselves (CodeRules::handles_features) or the scheme is non-linear.
  std::string curve;
  std::vector<ParameterSpec> parameters;
  std::function<CodeRules(const ParameterValues&)> linear;
  std::function<NonlinearRule(const ParameterValues&)> nonlinear;
};

// Rules of a linear curve scheme computed in C++: new point m*i + r is
// sum_t weights[r][t] * old point (i + starts[r] + t), for r = 0 .. arity - 1.
struct CurveRulesSpec {
  int arity = 2;
  std::vector<int> starts;
  std::vector<std::vector<double>> weights;
};

// A curve scheme written in C++. Give exactly one of `linear` (its rules: the scheme can
// then be the boundary curve of surface schemes and gets the curve analysis) or
// `nonlinear` (a function from one polyline to the next level).
struct CurveSchemeSpec {
  std::string name, description;
  std::vector<ParameterSpec> parameters;
  std::function<CurveRulesSpec(const ParameterValues&)> linear;
  std::function<PolylineRule(const ParameterValues&)> nonlinear;
};

class PluginRegistry {
public:
  // `plugin_name` and `plugin_file` label everything registered ("plugin NAME", the file).
  PluginRegistry(std::string plugin_name, std::string plugin_file);
  ~PluginRegistry();
  PluginRegistry(const PluginRegistry&) = delete;
  PluginRegistry& operator=(const PluginRegistry&) = delete;

  // A topology rule (refine/splitter.h). Schemes of this plugin and JSON files may name it
  // in "split" once the plugin is loaded.
  void add_splitter(SplitterInfo splitter);
  // A rule role (rules/rule.h) that JSON rules of the given element may use with "sum".
  void add_role(RoleInfo role);
  void add_surface_scheme(SurfaceSchemeSpec scheme);
  void add_curve_scheme(CurveSchemeSpec scheme);
  // A surface or curve scheme in the JSON language (docs/scheme-format.md) as text; it may
  // use this plugin's splitters and roles.
  void add_json_scheme(std::string json_text);

  const std::string& plugin_name() const { return plugin_name_; }
  const std::string& plugin_file() const { return plugin_file_; }

  // Engine side: checks and registers everything added, or throws subdiv::Error (and
  // registers nothing) naming the first problem. Returns one line per item, e.g.
  // "surface scheme circle-quad (non-linear)".
  std::vector<std::string> commit();

private:
  struct Staged;
  std::string plugin_name_, plugin_file_;
  std::unique_ptr<Staged> staged_;
};

}  // namespace subdiv
