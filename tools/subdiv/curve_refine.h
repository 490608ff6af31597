#pragma once
// `subdiv refine` for polylines: a mesh of OBJ 'l' lines or VTK line cells refined with a
// curve scheme (framework/pipeline/curve_pipeline.h), written as .vtp (finest level), .pvd
// (all levels) or .obj ('l' lines).
#include <string>

#include "framework/scheme/scheme_registry.h"

namespace subdiv::cli {

struct CurveRefineArgs {
  std::string mesh, scheme, output;
  int levels = 1;
  ParameterOverrides params;
  int threads = 0;  // 0: all cores
  bool quiet = false;
  std::string weights;  // the rational weights' point array (rational_weights.h); empty: the default
};

// True when `scheme` (a name or a path) is a curve scheme; false for surface schemes and for
// anything else (the surface path reports unknown names and scheme sequences).
bool is_curve_scheme(const std::string& scheme);

void refine_curves_command(const CurveRefineArgs& args);

}  // namespace subdiv::cli
