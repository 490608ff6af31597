// analyze: the eigen-analysis of surface schemes at extraordinary vertices (or faces) and
// the symbol analysis of curve schemes, as `subdiv analyze` runs them, returned as arrays.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bindings.h"
#include "curve_report.h"
#include "surface_report.h"

namespace subdivkit {
namespace {

py::array_t<std::complex<double>> complex_array(const std::vector<std::complex<double>>& values) {
  py::array_t<std::complex<double>> a(py::ssize_t(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

py::array_t<double> real_array(std::vector<double> values) {
  const auto n = py::ssize_t(values.size());
  return adopt(std::move(values), {n});
}

py::array_t<double> matrix_array(const std::vector<std::vector<double>>& rows) {
  const size_t n = rows.size(), m = rows.empty() ? 0 : rows.front().size();
  std::vector<double> flat;
  flat.reserve(n * m);
  for (const auto& r : rows) flat.insert(flat.end(), r.begin(), r.end());
  return adopt(std::move(flat), {py::ssize_t(n), py::ssize_t(m)});
}

py::dict surface_dict(const subdiv::SurfaceAnalysis& a) {
  py::dict d;
  d["valence"] = a.config.valence;
  d["boundary"] = a.config.boundary;
  d["configuration"] = a.config.describe();
  d["steps"] = a.steps;
  d["error"] = a.error;
  d["minimal_ring"] = a.minimal_ring, d["ring"] = a.ring;
  d["matrix"] = matrix_array(a.matrix);
  d["eigenvalues"] = complex_array(a.eigenvalues);
  d["minimal_eigenvalues"] = complex_array(a.minimal_eigenvalues);
  d["crease_eigenvalues"] = complex_array(a.crease_eigenvalues);
  d["lambda1"] = a.lambda1, d["lambda2"] = a.lambda2, d["lambda3"] = a.lambda3;
  py::dict checks;
  checks["affine"] = a.affine;
  checks["lambda0_one"] = a.lambda0_one;
  checks["subdominant_real"] = a.subdominant_real;
  checks["subdominant_equal"] = a.subdominant_equal;
  checks["subdominant_semisimple"] = a.subdominant_semisimple;
  checks["subdominant_dominates"] = a.subdominant_dominates;
  checks["characteristic_map_regular"] = a.characteristic_map.regular;
  checks["characteristic_map_injective"] = a.characteristic_map.injective;
  d["checks"] = checks;
  d["curvature"] = a.curvature;
  d["c1"] = a.c1;
  d["verdict"] = a.verdict;
  d["limit_mask"] = real_array(a.has_limit_mask ? a.limit_mask : std::vector<double>{});
  d["tangent_masks"] = a.has_tangent_masks ? matrix_array({a.tangent_u, a.tangent_v}) : matrix_array({});
  d["summary"] = subdiv::surface_summary_lines(a);
  return d;
}

py::dict curve_dict(const subdiv::CurveSchemeAnalysis& r) {
  const subdiv::CurveAnalysis& a = r.analysis;
  py::dict d;
  d["name"] = r.name;
  d["level"] = r.level;
  d["level_dependent"] = r.level_dependent;
  d["arity"] = a.mask.arity;
  d["mask"] = real_array(a.mask.coefficients);
  d["mask_first"] = a.mask.first;
  d["symbol"] = real_array(a.symbol.coefficients);
  d["symbol_lowest"] = a.symbol.lowest;
  d["necessary_conditions_hold"] = a.necessary_conditions_hold;
  d["convergent"] = a.convergent;
  d["smoothness"] = a.smoothness;
  d["matrix"] = matrix_array(a.local_matrix.rows);
  d["eigenvalues"] = complex_array(a.eigen.eigenvalues);
  d["subdominant"] = a.eigen.subdominant;
  d["limit_mask"] = real_array(a.eigen.has_limit_mask ? a.eigen.limit_mask : std::vector<double>{});
  d["tangent_mask"] = real_array(a.eigen.has_tangent_mask ? a.eigen.tangent_mask : std::vector<double>{});
  d["indication"] = a.eigen.indication;
  d["summary"] = subdiv::curve_scheme_summary(r);
  return d;
}

py::object analyze(py::handle scheme, const std::vector<int>& valences, bool boundary, bool crease, bool corner,
                   const std::string& interpolation, int level, int max_ring, bool characteristic_map) {
  if (!py::isinstance<SchemeHandle>(scheme))
    throw subdiv::Error("analyze: expected a subdivkit.Scheme (subdivkit.analyze loads names)");
  const SchemeHandle& h = scheme.cast<const SchemeHandle&>();
  if (level < 0) throw subdiv::Error(fmt::format("level={}: give 0 or more", level));
  if (h.kind == "curve") {
    subdiv::CurveSchemeAnalysis r;
    {
      py::gil_scoped_release unlocked;
      r = subdiv::analyse_curve_scheme(*h.curve, level);
    }
    return curve_dict(r);
  }
  const subdiv::ValenceAnalysisRequest request{
      h.surface, valences, boundary, level, analysis_options(interpolation, max_ring, characteristic_map), crease, corner};
  std::vector<subdiv::SurfaceAnalysis> results;
  {
    py::gil_scoped_release unlocked;
    results = subdiv::analyse_valences(request);
  }
  py::list out;
  for (const auto& r : results) out.append(surface_dict(r));
  return out;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("_analyze", &analyze, py::arg("scheme"), py::arg("valences"), py::arg("boundary"), py::arg("crease"),
        py::arg("corner"), py::arg("boundary_interpolation"), py::arg("level"), py::arg("max_ring"), py::arg("characteristic_map"),
        "Analyses as dicts of arrays (subdivkit.analyze gathers them).");
}

}  // namespace subdivkit
