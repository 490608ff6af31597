#pragma once
// What `subdiv interpolate` does the same for surfaces (interpolate_command.cpp) and for
// polylines (curve_interpolate.cpp): reading the selection, running the iteration with
// progress, and reporting it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/interpolation/progressive.h"
#include "framework/stencil/stencil_table.h"
#include "framework/topology/level.h"
#include "progress.h"

namespace subdiv::cli {

std::string read_text(const std::filesystem::path& file, const std::string& what);

// --select: "all", a comma list of 0-based ids, or a file of ids ('#' comments).
std::vector<std::uint8_t> read_selection(const std::string& select, Index vertex_count);

struct IterationSettings {
  double tolerance = -1;  // < 0: 1e-10 times the bounding-box diagonal of the targets
  int max_iterations = 1000;
  bool verbose = false;
};

struct IterationRun {
  ProgressiveResult result;
  double tolerance = 0;
  Index moving = 0, vertices = 0;
  std::vector<std::string> log;  // one line per iteration, with `verbose`
  std::string fixed_note;        // local runs: theorem 2's prediction against the result
};

// The iteration over `limit`, showing each residual on the progress line.
IterationRun run_iterations(const StencilTable& limit, const std::vector<double>& targets,
                            const std::vector<std::uint8_t>& moving, const IterationSettings& settings,
                            Progress& progress);

// On stderr, when the iteration stopped above the tolerance; `written` names what was written.
void warn_if_stopped(const IterationRun& run, const std::string& written);

// The report after the input's line: moving set, residuals, theorem 2. `what`: "vertices"
// or "points".
void print_iterations(const IterationRun& run, const std::string& what, bool verbose);

}  // namespace subdiv::cli
