#include "framework/pipeline/scheme_source.h"

#include "framework/scheme/scheme_registry.h"

namespace subdiv {

SchemeSequence load_surface_sequence(const SchemeSource& source, int levels, const ParameterOverrides& parameters) {
  if (!source.is_json_text) return load_scheme_sequence(source.text, levels, parameters);
  SchemeSequence seq;
  seq.schemes = {load_scheme_text(source.text, source.label, parameters)};
  seq.runs = {{seq.schemes.front().get(), levels}};
  seq.total_levels = levels;
  return seq;
}

bool declares_parameter(const SchemeSequence& sequence, const std::string& name) {
  for (const auto& scheme : sequence.schemes)
    for (const auto& p : scheme->parameters)
      if (p.name == name) return true;
  return false;
}

}  // namespace subdiv
