#include "framework/analysis/curve/curve_scheme_analysis.h"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <set>

#include "framework/analysis/curve/variational_curve.h"
#include "framework/rules/formula.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace fs = std::filesystem;


CurveMask curve_mask_from_scheme(const CurveScheme& curve, int level) {
  if (curve.variational()) {
    // Its bi-infinite rules: the closed polygon's solution, translation invariant.
    std::vector<int> starts;
    std::vector<std::vector<double>> weights;
    variational_rules(variational_energy(curve, level), starts, weights);
    return mask_from_rules(curve.arity, starts, weights);
  }
  FormulaSet formulas(curve.parameters, curve.definitions);
  std::vector<std::vector<double>> weights(curve.weights.size());
  for (size_t r = 0; r < curve.weights.size(); ++r)
    for (size_t t = 0; t < curve.weights[r].size(); ++t) {
      const std::string where = fmt::format("{}: rules[{}].w[{}]", curve.path, r, t);
      const int id = formulas.add(curve.weights[r][t], where);
      const double w = formulas.evaluate(id, {0, 0, double(t), double(level)});
      if (!std::isfinite(w)) throw Error(fmt::format("{}: {} is not finite ({})", where, subdiv::quoted(curve.weights[r][t]), w));
      weights[r].push_back(w);
    }
  return mask_from_rules(curve.arity, curve.starts, weights);
}

bool curve_scheme_is_level_dependent(const CurveScheme& curve) {
  FormulaSet formulas(curve.parameters, curve.definitions);
  for (size_t r = 0; r < curve.weights.size(); ++r)
    for (size_t t = 0; t < curve.weights[r].size(); ++t)
      if (formulas.uses(formulas.add(curve.weights[r][t], curve.path)).l) return true;
  for (const std::string& a : curve.variational_alpha)
    if (formulas.uses(formulas.add(a, curve.path)).l) return true;
  return false;
}

CurveSchemeAnalysis analyse_curve_scheme(const CurveScheme& curve, int level, const CurveAnalysisOptions& options) {
  CurveSchemeAnalysis out;
  out.name = curve.name;
  out.path = curve.path;
  out.level = level;
  out.level_dependent = curve_scheme_is_level_dependent(curve);
  out.analysis = analyse_curve(curve_mask_from_scheme(curve, level), options);
  return out;
}

// Both go through the scheme registry, so plugin schemes are found as well as files.
std::string scheme_kind_of(const std::string& name_or_path) { return scheme_kind(name_or_path); }

std::shared_ptr<const CurveScheme> load_curve_scheme_named(const std::string& name_or_path,
                                                           const ParameterOverrides& overrides) {
  return load_curve(name_or_path, overrides);
}

}  // namespace subdiv
