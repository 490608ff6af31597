#pragma once
// "A:1,B:3": scheme A for one level, then scheme B for three. A name without ":N" takes the
// levels left over from the total. Parameter overrides go to every scheme (or its curve
// scheme) that has a parameter of that name; one that no scheme has is an error.
#include <memory>
#include <string>
#include <vector>

#include "framework/scheme/scheme_run.h"
#include "framework/scheme/scheme_registry.h"

namespace subdiv {

struct SchemeSequence {
  std::vector<std::shared_ptr<const Scheme>> schemes;
  std::vector<SchemeRun> runs;
  int total_levels = 0;
};

SchemeSequence load_scheme_sequence(const std::string& spec, int levels, const ParameterOverrides& overrides);

}  // namespace subdiv
