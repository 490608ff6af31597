#pragma once
// The number of worker threads a front-end asks TBB for (--threads, threads=). More threads
// than cores only cost memory (2^31 - 1 threads took 17 GB before failing with a message
// that blamed the input), so a request is capped at the core count, with a note saying so.
#include <string>

namespace subdiv {

struct ThreadCount {
  int threads = 0;   // what to use: 1 .. cores; 0 when `requested` was 0 (all cores)
  std::string note;  // non-empty when the request was capped: say it to the user
};

// `requested` < 0 throws subdiv::Error naming `option` (e.g. "--threads"); 0 means all
// cores; more than the cores is capped at them.
ThreadCount capped_thread_count(long long requested, const std::string& option = "--threads");

// The cores this process may run on (its CPU affinity, as TBB counts them), at least 1.
int available_cores();

}  // namespace subdiv
