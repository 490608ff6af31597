#include "curve_report.h"

#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace subdiv {

namespace {

constexpr double kShownImaginary = 1e-6;  // smaller imaginary parts are printed as real

std::string number(double x) { return fmt::format("{:.6g}", std::abs(x) < 5e-13 ? 0.0 : x); }

std::string complex_text(std::complex<double> z) {
  if (std::abs(z.imag()) < kShownImaginary) return number(z.real());
  return fmt::format("{}{}{}i", number(z.real()), z.imag() < 0 ? "-" : "+", number(std::abs(z.imag())));
}

std::string list_text(const std::vector<double>& values) {
  std::string out;
  for (double v : values) out += (out.empty() ? "" : ", ") + number(v);
  return out;
}

std::string factor_text(int arity) {
  if (arity == 2) return "(1+z)";
  if (arity == 3) return "(1+z+z^2)";
  return fmt::format("(1+z+...+z^{})", arity - 1);
}

std::string points_text(const LocalSubdivisionMatrix& s) {
  return fmt::format("points {}..{}", s.first_index, s.first_index + s.size() - 1);
}

std::string level_line(const SmoothnessLevel& level, int arity) {
  const auto& c = level.contractivity;
  if (!level.factor_divides)
    return fmt::format("C{}: symbol has no factor {}^{} (relative remainder {})", level.order,
                       factor_text(arity), level.order + 1, number(level.remainder));
  if (c.contractive) {
    const std::string what = level.order == 0 ? "contractive difference scheme"
                                              : fmt::format("C{}: contractive difference scheme", level.order);
    return fmt::format("{} at L={} (norm {}) -> C{}", what, c.power, number(c.norms.back()), level.order);
  }
  return fmt::format("C{}: difference scheme not contractive up to L={} (last norm {}){}", level.order,
                     c.searched_up_to, number(c.norms.empty() ? 0.0 : c.norms.back()),
                     c.stopped_by_size ? ", stopped by the coefficient budget" : "");
}

std::string not_proven_reason(const CurveAnalysis& r, int order) {
  if (order >= static_cast<int>(r.levels.size())) return "";
  const SmoothnessLevel& level = r.levels[static_cast<std::size_t>(order)];
  if (!level.factor_divides)
    return fmt::format("(symbol has no factor {}^{})", factor_text(r.mask.arity), order + 1);
  return fmt::format("up to L={}", level.contractivity.searched_up_to);
}

std::string verdict(const CurveAnalysis& r) {
  if (!r.necessary_conditions_hold) {
    for (const auto& c : r.conditions)
      if (!c.holds)
        return fmt::format("not convergent: necessary condition {} = {} fails", c.name, number(c.expected));
  }
  if (r.smoothness < 0) return fmt::format("convergence not proven {}", not_proven_reason(r, 0));
  const auto& best = r.levels[static_cast<std::size_t>(r.smoothness)];
  return fmt::format("C{} proven (L={}); C{} not proven {}", r.smoothness, best.contractivity.power,
                     r.smoothness + 1, not_proven_reason(r, r.smoothness + 1));
}

void add_symbol_lines(const CurveAnalysis& r, std::vector<std::string>& lines) {
  lines.push_back(fmt::format("arity {}", r.mask.arity));
  lines.push_back(fmt::format("mask a_{}..a_{} = {}", r.mask.first, r.mask.last(), list_text(r.mask.coefficients)));
  lines.push_back("symbol a(z) = " + to_string(r.symbol));
  if (r.mask.arity > 2) lines.push_back(fmt::format("w = exp(2 pi i/{})", r.mask.arity));
  for (const auto& c : r.conditions)
    lines.push_back(fmt::format("{} = {} {}", c.name, complex_text(c.value),
                                c.holds ? "ok" : fmt::format("FAILS (must be {})", number(c.expected))));
  lines.push_back("sub-mask sums: " + list_text(r.sub_mask_sums));
}

void add_eigen_lines(const CurveAnalysis& r, std::vector<std::string>& lines) {
  const auto& s = r.local_matrix;
  const auto& e = r.eigen;
  if (s.size() == 0) {
    lines.push_back("no invariant neighbourhood (degenerate mask)");
    return;
  }
  lines.push_back(fmt::format("local subdivision matrix on {} ({}x{})", points_text(s), s.size(), s.size()));
  std::string values;
  for (const auto& v : e.eigenvalues) values += (values.empty() ? "" : ", ") + complex_text(v);
  lines.push_back("eigenvalues: " + values);
  lines.push_back(e.has_limit_mask ? fmt::format("limit mask on {}: {}", points_text(s), list_text(e.limit_mask))
                                   : "no limit mask (eigenvalue 1 is not simple and dominant)");
  lines.push_back(e.has_tangent_mask
                      ? fmt::format("tangent mask (eigenvalue {}) on {}: {}", complex_text(e.subdominant),
                                    points_text(s), list_text(e.tangent_mask))
                      : "no tangent mask (subdominant eigenvalue not real, simple and strictly dominant)");
  if (!e.indication.empty()) lines.push_back(e.indication);
}

nlohmann::json complex_json(std::complex<double> z) { return nlohmann::json::array({z.real(), z.imag()}); }

nlohmann::json polynomial_json(const LaurentPolynomial& p) {
  return {{"lowest_power", p.lowest}, {"coefficients", p.coefficients}};
}

nlohmann::json level_json(const SmoothnessLevel& level) {
  nlohmann::json j = {{"order", level.order}, {"factor_divides", level.factor_divides},
                      {"remainder", level.remainder}, {"proven", level.proven()}};
  if (!level.factor_divides) return j;
  const auto& c = level.contractivity;
  j["difference_symbol"] = polynomial_json(level.difference_symbol);
  j["contractive"] = c.contractive;
  j["L"] = c.contractive ? nlohmann::json(c.power) : nlohmann::json(nullptr);
  j["searched_up_to"] = c.searched_up_to;
  j["stopped_by_size"] = c.stopped_by_size;
  j["norms"] = c.norms;
  return j;
}

nlohmann::json eigen_json(const CurveAnalysis& r) {
  nlohmann::json values = nlohmann::json::array();
  for (const auto& v : r.eigen.eigenvalues) values.push_back(complex_json(v));
  nlohmann::json j = {{"first_index", r.local_matrix.first_index},
                      {"matrix", r.local_matrix.rows},
                      {"eigenvalues", values},
                      {"indication", r.eigen.indication}};
  j["limit_mask"] = r.eigen.has_limit_mask ? nlohmann::json(r.eigen.limit_mask) : nlohmann::json(nullptr);
  j["subdominant_eigenvalue"] = complex_json(r.eigen.subdominant);
  j["tangent_mask"] = r.eigen.has_tangent_mask ? nlohmann::json(r.eigen.tangent_mask) : nlohmann::json(nullptr);
  return j;
}

}  // namespace

std::string curve_summary(const CurveAnalysis& a) {
  std::vector<std::string> lines;
  add_symbol_lines(a, lines);
  for (const auto& level : a.levels) lines.push_back(level_line(level, a.mask.arity));
  lines.push_back(verdict(a));
  add_eigen_lines(a, lines);
  std::string out;
  for (const auto& line : lines) out += line + "\n";
  return out;
}

nlohmann::json curve_json(const CurveAnalysis& a) {
  nlohmann::json conditions_json = nlohmann::json::array();
  for (const auto& c : a.conditions)
    conditions_json.push_back({{"name", c.name}, {"value", complex_json(c.value)},
                               {"expected", c.expected}, {"holds", c.holds}});
  nlohmann::json levels_json = nlohmann::json::array();
  for (const auto& level : a.levels) levels_json.push_back(level_json(level));
  return {{"arity", a.mask.arity},
          {"mask", {{"first", a.mask.first}, {"coefficients", a.mask.coefficients}}},
          {"symbol", polynomial_json(a.symbol)},
          {"necessary_conditions", conditions_json},
          {"sub_mask_sums", a.sub_mask_sums},
          {"necessary_conditions_hold", a.necessary_conditions_hold},
          {"max_L", a.max_power},
          {"levels", levels_json},
          {"convergent", a.convergent},
          {"smoothness", a.smoothness},
          {"verdict", verdict(a)},
          {"local", eigen_json(a)}};
}

std::string curve_scheme_summary(const CurveSchemeAnalysis& r) {
  std::string out = fmt::format("curve scheme {} ({})\n", r.name, r.path);
  if (r.level_dependent)
    out += fmt::format("non-stationary: the weights depend on the level l; analysed with the weights of level {} "
                       "(the symbol analysis proves nothing about the level-dependent scheme itself)\n",
                       r.level);
  return out + curve_summary(r.analysis);
}

nlohmann::json curve_scheme_json(const CurveSchemeAnalysis& r) {
  nlohmann::json j = curve_json(r.analysis);
  j["scheme"] = r.name;
  j["path"] = r.path;
  j["kind"] = "curve";
  j["level"] = r.level;
  j["stationary"] = !r.level_dependent;
  return j;
}

}  // namespace subdiv
