#pragma once
// `subdiv refine` for polylines: a mesh of OBJ 'l' lines or VTK line cells refined with a
// curve scheme, written as .vtp (finest level), .pvd (all levels) or .obj ('l' lines).
#include <string>

#include "framework/scheme/scheme_registry.h"

namespace subdiv::cli {

struct CurveRefineRequest {
  std::string mesh, scheme, output;
  int levels = 1;
  ParameterOverrides params;
  bool quiet = false;
};

// True when `scheme` (a name or a path) is a curve scheme.
bool is_curve_scheme(const std::string& scheme);

void refine_curves_command(const CurveRefineRequest& request);

}  // namespace subdiv::cli
