#pragma once
// What `subdiv interpolate` does the same for surfaces (interpolate_command.cpp) and for
// polylines (curve_interpolate.cpp): reading the selection, showing the iteration of the
// pipeline's request (framework/pipeline/interpolate_request.h) as it runs, and reporting it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/pipeline/interpolate_request.h"
#include "framework/topology/level.h"
#include "progress.h"

namespace subdiv::cli {

std::string read_text(const std::filesystem::path& file, const std::string& what);

// --select: "all", a comma list of 0-based ids, or a file of ids ('#' comments).
std::vector<std::uint8_t> read_selection(const std::string& select, Index vertex_count);

// The request's progress: each phase, then each iteration's residuals on the progress line;
// with `verbose`, one table line per iteration in `log` (print_iterations prints them).
void show_iterations(InterpolateRequest& request, Progress& progress, bool verbose, std::vector<std::string>& log);

// On stderr, when the iteration stopped above the tolerance; `written` names what was written.
void warn_if_stopped(const InterpolateResult& result, const std::string& written);

// The report after the input's line: moving set, residuals, theorem 2. `what`: "vertices"
// or "points".
void print_iterations(const InterpolateResult& result, const std::vector<std::string>& log, const std::string& what,
                      bool verbose);

}  // namespace subdiv::cli
