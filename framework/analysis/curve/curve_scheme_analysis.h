#pragma once
// Curve analysis of a curve scheme as loaded from JSON (scheme.h CurveScheme): the weight
// formulas are evaluated into a CurveMask (curve_mask.h) and analysed with analyse_curve
// (curve_analysis.h). Level-dependent (non-stationary) schemes are analysed at one level
// and flagged as such: the symbol analysis only proves things about stationary schemes.
#include <map>
#include <memory>
#include <string>

#include "framework/analysis/curve/curve_analysis.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"

namespace subdiv {

// The mask of the curve scheme's rules at level `level` (the formulas' l; j is the index
// of the weight within its rule). Throws subdiv::Error naming the file on a weight that
// is not finite.
CurveMask curve_mask_from_scheme(const CurveScheme& curve, int level = 0);

// True when a weight formula (directly or through a definition) uses the level l.
bool curve_scheme_is_level_dependent(const CurveScheme& curve);

struct CurveSchemeAnalysis {
  std::string name, path;
  int level = 0;                 // the level the weights were evaluated at
  bool level_dependent = false;  // non-stationary: the analysis holds for level `level` frozen
  CurveAnalysis analysis;

};

CurveSchemeAnalysis analyse_curve_scheme(const CurveScheme& curve, int level = 0,
                                         const CurveAnalysisOptions& options = {});

// "surface" or "curve" for a built-in scheme name or a .json path (throws like load_scheme
// for unknown names and missing files).
std::string scheme_kind_of(const std::string& name_or_path);

// Loads a curve scheme by built-in name or path, with --param overrides.
std::shared_ptr<const CurveScheme> load_curve_scheme_named(const std::string& name_or_path,
                                                           const ParameterOverrides& overrides = {});

}  // namespace subdiv
