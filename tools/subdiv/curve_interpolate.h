#pragma once
// `subdiv interpolate` for polylines: progressive interpolation with a curve scheme, so
// that the limit curve passes through the chosen points (framework/interpolation/
// curve_limits.h gives the limit points).
#include <string>

#include "framework/scheme/scheme_registry.h"

namespace subdiv::cli {

struct CurveInterpolateRequest {
  std::string mesh, scheme, output, refined, select;
  ParameterOverrides params;
  double tolerance = -1;  // < 0: 1e-10 times the bounding-box diagonal
  int max_iterations = 1000;
  int levels = 3;  // for `refined`
  bool verbose = false, quiet = false;
};

void interpolate_curves_command(const CurveInterpolateRequest& request);

}  // namespace subdiv::cli
