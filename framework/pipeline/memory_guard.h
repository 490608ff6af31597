#pragma once
// Refuses refinements whose result would not fit in memory, before any work is done.
#include <string>

#include "framework/scheme/scheme.h"
#include "framework/topology/level.h"

namespace subdiv {

// About how many bytes refining `base` for `levels` levels keeps at its peak.
double refinement_bytes(const Scheme& scheme, const Level& base, int levels);

// Throws subdiv::Error when that is more than this process may allocate, or than `limit`
// bytes when it is positive (the request's memory budget); `fix` is the advice the message ends with.
void check_fits_in_memory(const Scheme& scheme, const Level& base, int levels, double limit = 0,
                          const std::string& fix = "ask for fewer levels");

// Bytes this process holds now (resident set, /proc/self/statm); 0 where unknown.
double resident_bytes();

// "8G", "512M", "100k" or plain bytes (binary units); throws subdiv::Error naming `option`.
double parse_memory_size(const std::string& text, const std::string& option);

}  // namespace subdiv
