#pragma once
// Readable forms of surface analyses over a range of valences: a text table, JSON, and an
// SVG plot of the spectrum (eigenvalue moduli against valence).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/analysis/surface/surface_analysis.h"

namespace subdiv {

// One analysis: the configuration, the checks and the verdict, a line each.
std::vector<std::string> surface_summary_lines(const SurfaceAnalysis& analysis);
nlohmann::json surface_json(const SurfaceAnalysis& analysis);

// One line per analysis: valence, steps, ring sizes, lambda_1, lambda_2, |lambda_3|,
// lambda_1^2, the checks that hold, the characteristic map, the verdict.
std::string surface_table(const std::vector<SurfaceAnalysis>& analyses);

// {"scheme", "path", "kind": "surface", "centre", "analyses": [surface_json(a)...]}.
nlohmann::json surface_report_json(const std::vector<SurfaceAnalysis>& analyses);

// A hand-written SVG: for each valence, the moduli of the leading `shown` eigenvalues as
// dots (lambda_1 = lambda_2 highlighted, lambda_1^2 as a line), 0 <= |lambda| <= 1.
std::string spectrum_svg(const std::vector<SurfaceAnalysis>& analyses, const std::string& title, int shown = 8);

// A plot of one list of eigenvalues (modulus against index), for curve schemes.
std::string eigenvalue_svg(const std::vector<std::complex<double>>& eigenvalues, const std::string& title);

}  // namespace subdiv
