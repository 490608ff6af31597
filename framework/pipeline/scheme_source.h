#pragma once
// Loading a request's SchemeSource (refine_request.h) as a surface scheme sequence: a name,
// a .json path or a sequence "A:1,B:3" through the registry, or a scheme file's JSON text
// as one scheme run for all levels.
#include <string>

#include "framework/pipeline/refine_request.h"
#include "framework/scheme/scheme_sequence.h"

namespace subdiv {

// `levels` completes a sequence (a scheme without :N takes the rest) or is the run of a
// single scheme. Throws subdiv::Error naming the scheme.
SchemeSequence load_surface_sequence(const SchemeSource& source, int levels, const ParameterOverrides& parameters);

// Whether any scheme of `sequence` declares a parameter `name` (e.g. "lambda", "triangles").
bool declares_parameter(const SchemeSequence& sequence, const std::string& name);

}  // namespace subdiv
