#pragma once
// How a benchmark worker process hands its WorkerReport to the parent: a fixed header and
// the sampled points, raw, over a pipe (both ends are the same binary, so the layout needs
// no portability). Shared by subdiv-bench and subdiv-bench-meshlibs.
#include <string>
#include <vector>

#include "bench_common.h"

namespace subdiv_bench {

// Writes the report to fd; throws std::runtime_error if the pipe fails.
void send_report(int fd, const WorkerReport& report);
// Everything the worker wrote, until it closes its end.
std::string read_until_closed(int fd);
// The report in `bytes`; false if they are not one whole report.
bool parse_report(const std::string& bytes, WorkerReport& report);

// Runs this executable again as `args` (args[0] its name) with a pipe as fd 3, waits for it
// and reads its report; returns "" on success, else what went wrong.
std::string run_self_as_worker(std::vector<std::string> args, WorkerReport& report);

}  // namespace subdiv_bench
