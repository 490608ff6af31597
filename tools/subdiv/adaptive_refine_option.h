#pragma once
// subdiv refine --adaptive [L] [--tolerance T] [--limit]: the options and their run, kept out
// of refine_command.cpp (framework/pipeline/adaptive_request.h does the work).
#include <chrono>
#include <string>

#include <CLI/CLI.hpp>

#include "framework/pipeline/refine_request.h"
#include "progress.h"

namespace subdiv::cli {

struct AdaptiveArgs {
  int levels = -1;        // --adaptive L, or -l's L after resolve_adaptive_level; < 0: not given
  double tolerance = 0;   // --tolerance T; 0: features only
  std::string transitions = "polygons";  // --transitions polygons|triangles
  bool given() const { return levels >= 0; }
};

void add_adaptive_options(CLI::App* cmd, AdaptiveArgs& args);
// After parsing: `--adaptive` without L takes -l's level (`--adaptive -l 3`, as `--adaptive 3`);
// both given must agree. `levels`: -l's value (its default when not given).
void resolve_adaptive_level(const CLI::App& cmd, AdaptiveArgs& args, int levels, bool levels_given);
// --tolerance T alone, for commands with an --adaptive of their own (subdiv evaluate).
void add_tolerance_option(CLI::App* cmd, double& tolerance);

// --transitions polygons|triangles, for both commands' --adaptive.
void add_transitions_option(CLI::App* cmd, std::string& transitions);

// Runs the adaptive refinement of `request`'s mesh and scheme, writes `output` (a mesh file)
// and prints a summary unless quiet.
void run_adaptive_refine(RefineRequest request, const AdaptiveArgs& args, bool limit, bool in_pieces,
                         const std::string& output, bool quiet, Progress& progress,
                         std::chrono::steady_clock::time_point t0);

}  // namespace subdiv::cli
