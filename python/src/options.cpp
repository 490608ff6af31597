// The keyword arguments boundary=, crease_method=, threads= as the library's option
// structs: the names of framework/pipeline/option_names.h, spelled as Python's keywords.
#include <fmt/format.h>

#include "bindings.h"
#include "framework/pipeline/refine_request.h"

namespace subdivkit {

const subdiv::OptionSpelling& python_option_spelling() {
  static const subdiv::OptionSpelling spelling = {
      {"scheme", "scheme"},           {"levels", "levels"},
      {"start_level", "start_level"}, {"boundary", "boundary"},
      {"crease_method", "crease_method"}, {"fvar_boundary", "fvar_boundary"},
      {"smooth_triangles", "params={'triangles': 'smooth'}"}, {"threads", "threads"},
      {"normals", "limit_positions()"}, {"limit", "limit_positions()"},
      {"param", "params"},            {"scheme_list", "subdivkit.schemes()"},
      {"min_valence", "min_valence"}, {"max_valence", "max_valence"},
      {"select", "select"},           {"max_iterations", "max_iterations"},
      {"valences", "valences"},       {"boundary_analysis", "boundary=True"},
      {"samples", "samples"},         {"transitions", "transitions"},         {"approximate_bezier", "approximate_bezier()"},
      {"approximate_gregory", "approximate_gregory()"}};
  return spelling;
}

const subdiv::OptionSpelling& python_keyword_spelling() {
  static const subdiv::OptionSpelling spelling = [] {
    subdiv::OptionSpelling s = python_option_spelling();
    s["param"] = "keyword argument";
    return s;
  }();
  return spelling;
}

subdiv::BoundaryInterpolation boundary_from(const std::string& text) {
  return subdiv::boundary_from_name(text, "boundary=");
}

subdiv::CreaseMethod crease_method_from(const std::string& text) {
  return subdiv::crease_method_from_name(text, "crease_method=");
}

void check_levels(int levels) {
  if (levels < 0 || levels > 30) throw subdiv::Error(fmt::format("levels={}: give 0 to 30 levels", levels));
}

namespace {

// As refine's (the pipeline's) range: Evaluator, stencils and limit_positions build their
// options here, and a start level near 2^31 overflowed the step count of a split that
// alternates (sqrt3).
void check_start_level(int first_step) {
  if (first_step < 0 || first_step > subdiv::kMaxStartLevel)
    throw subdiv::Error(fmt::format("start_level={}: give 0 to {}", first_step, subdiv::kMaxStartLevel));
}

}  // namespace

subdiv::RefineOptions refine_options(const std::string& boundary, const std::string& crease_method, int threads,
                                     int first_step) {
  if (threads < 0) throw subdiv::Error(fmt::format("threads={}: give 0 (all cores) or more", threads));
  check_start_level(first_step);
  subdiv::RefineOptions o;
  o.features.boundary = boundary_from(boundary);
  o.features.crease_method = crease_method_from(crease_method);
  o.first_step = first_step;
  return o;
}

subdiv::SurfaceAnalysisOptions analysis_options(const std::string& boundary, int max_ring, bool characteristic_map) {
  if (max_ring < 1 || max_ring > 8) throw subdiv::Error(fmt::format("max_ring={}: give 1 to 8", max_ring));
  subdiv::SurfaceAnalysisOptions o;
  o.features.boundary = boundary_from(boundary);
  o.max_ring = max_ring;
  o.characteristic_map = characteristic_map;
  return o;
}

subdiv::LimitOptions limit_options(const std::string& boundary, const std::string& crease_method, int first_step) {
  check_start_level(first_step);
  subdiv::LimitOptions o;
  o.features.boundary = boundary_from(boundary);
  o.features.crease_method = crease_method_from(crease_method);
  o.first_step = first_step;
  return o;
}

subdiv::LimitSelectionOptions limit_selection_options(const std::string& boundary, int first_step) {
  subdiv::LimitSelectionOptions o;
  o.features.boundary = boundary_from(boundary);
  o.first_step = first_step;
  return o;
}

}  // namespace subdivkit
