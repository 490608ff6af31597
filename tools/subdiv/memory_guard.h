#pragma once
// Refuses refinements whose result would not fit in memory, before any work is done.
#include "framework/scheme/scheme.h"
#include "framework/topology/level.h"

namespace subdiv::cli {

void check_fits_in_memory(const Scheme& scheme, const Level& base, int levels);

// What this process may still allocate, in bytes: MemAvailable, ulimits and the cgroup's
// limit (framework/util/memory_limit.h); very large when unknown: do not refuse then.
double available_memory_bytes();

}  // namespace subdiv::cli
