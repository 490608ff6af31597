#pragma once
// Refuses refinements whose result would not fit in memory, before any work is done.
#include "framework/scheme/scheme.h"
#include "framework/topology/level.h"

namespace subdiv::cli {

void check_fits_in_memory(const Scheme& scheme, const Level& base, int levels);

}  // namespace subdiv::cli
