#include "interpolate_common.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"
#include "safe_print.h"

namespace subdiv::cli {
namespace fs = std::filesystem;

std::string read_text(const fs::path& file, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(fmt::format("{}: cannot read {}", what, subdiv::quoted(file.string())));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::uint8_t> read_selection(const std::string& select, Index vertex_count) {
  const bool inline_list = select == "all" || select.find_first_not_of("0123456789, ") == std::string::npos;
  if (inline_list) return parse_vertex_selection(select, vertex_count, "--select");
  std::error_code ec;
  if (!fs::is_regular_file(select, ec))
    throw Error(fmt::format("--select {}: no such file, and not 'all' or a comma list of 0-based vertex ids", subdiv::quoted(select)));
  return parse_vertex_selection(read_text(select, "--select"), vertex_count, select);
}

void show_iterations(InterpolateRequest& request, Progress& progress, bool verbose, std::vector<std::string>& log) {
  request.progress = [&progress](const std::string& phase) { progress.say(phase); };
  request.iteration = [&progress, &log, verbose](const IterationRecord& r) {
    progress.say(fmt::format("iteration {}: max residual {:.3e}, rms {:.3e}", r.iteration, r.max_residual,
                             r.rms_residual));
    if (verbose) log.push_back(fmt::format("{:>9} {:>14.6e} {:>14.6e}", r.iteration, r.max_residual, r.rms_residual));
  };
}

void warn_if_stopped(const InterpolateResult& run, const std::string& written) {
  if (run.iteration.converged) return;
  print_safe(stderr, "subdiv: warning: the residual {:.3e} is above the tolerance {:.3e} after {} iterations "
             "(--max-iter); {} the last iterate\n", run.iteration.history.back().max_residual, run.tolerance,
             run.iteration.iterations, written);
}

void print_iterations(const InterpolateResult& run, const std::vector<std::string>& log, const std::string& what,
                      bool verbose) {
  const IterationRecord& first = run.iteration.history.front();
  const IterationRecord& last = run.iteration.history.back();
  print_safe("moving: {} of {} {} ({}); tolerance {:.3e}\n", run.moving, run.vertices, what,
             run.moving == run.vertices ? "global" : "local", run.tolerance);
  if (verbose) {
    print_safe("{:>9} {:>14} {:>14}\n", "iteration", "max residual", "rms residual");
    for (const auto& line : log) print_safe("{}\n", line);
  }
  print_safe("{} in {} iterations: max residual {:.3e}, rms {:.3e} (initially {:.3e}, {:.3e})\n",
             run.iteration.converged ? "converged" : "stopped", run.iteration.iterations, last.max_residual,
             last.rms_residual, first.max_residual, first.rms_residual);
  if (!run.fixed_note.empty()) print_safe("{}\n", run.fixed_note);
}

}  // namespace subdiv::cli
