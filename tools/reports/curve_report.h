#pragma once
// The readable and the machine forms of curve analyses (`subdiv analyze` on a curve scheme).
#include <nlohmann/json.hpp>
#include <string>

#include "framework/analysis/curve/curve_analysis.h"
#include "framework/analysis/curve/curve_scheme_analysis.h"

namespace subdiv {

std::string curve_summary(const CurveAnalysis& analysis);  // plain text, one fact per line
nlohmann::json curve_json(const CurveAnalysis& analysis);

// curve_summary with a header naming the scheme and the stationarity note.
std::string curve_scheme_summary(const CurveSchemeAnalysis& analysis);
nlohmann::json curve_scheme_json(const CurveSchemeAnalysis& analysis);

}  // namespace subdiv
