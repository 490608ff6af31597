#include "interpolate_common.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "framework/util/error.h"

namespace subdiv::cli {
namespace {

namespace fs = std::filesystem;

// Theorem 2 (Lin et al. 2015) for any limit operator: where the fixed vertices' limit points end.
std::string theorem_two_note(const StencilTable& limit, const std::vector<double>& targets,
                             const std::vector<std::uint8_t>& moving, const ProgressiveResult& r) {
  double offset = 0, gap = 0;
  try {
    const std::vector<double> predicted = predicted_fixed_offsets(limit, targets, moving);
    for (size_t v = 0; v < moving.size(); ++v) {
      if (moving[v]) continue;
      double d2 = 0, e2 = 0;
      for (int c = 0; c < 3; ++c) {
        const double d = targets[3 * v + c] - r.limit[3 * v + c];
        d2 += d * d, e2 += (d - predicted[3 * v + c]) * (d - predicted[3 * v + c]);
      }
      offset = std::max(offset, std::sqrt(d2)), gap = std::max(gap, std::sqrt(e2));
    }
  } catch (const Error& e) {
    return fmt::format("fixed vertices: stay in place; theorem 2 not evaluated: {}", e.what());
  }
  return fmt::format("fixed vertices: stay in place; their limit points end up to {:.6g} from them "
                     "(theorem 2, D_Q = D_Q^0 - E M^-1 D_P^0, agrees to {:.1e})", offset, gap);
}

}  // namespace

std::string read_text(const fs::path& file, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(fmt::format("{}: cannot read '{}'", what, file.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::uint8_t> read_selection(const std::string& select, Index vertex_count) {
  const bool inline_list = select == "all" || select.find_first_not_of("0123456789, ") == std::string::npos;
  if (inline_list) return parse_vertex_selection(select, vertex_count, "--select");
  std::error_code ec;
  if (!fs::is_regular_file(select, ec))
    throw Error(fmt::format("--select '{}': no such file, and not 'all' or a comma list of 0-based vertex ids", select));
  return parse_vertex_selection(read_text(select, "--select"), vertex_count, select);
}

IterationRun run_iterations(const StencilTable& limit, const std::vector<double>& targets,
                            const std::vector<std::uint8_t>& moving, const IterationSettings& settings,
                            Progress& progress) {
  IterationRun run;
  run.vertices = Index(moving.size());
  run.moving = Index(std::count(moving.begin(), moving.end(), std::uint8_t(1)));
  ProgressiveOptions po;
  po.tolerance = settings.tolerance >= 0 ? settings.tolerance
                                         : default_interpolation_tolerance(targets);
  po.max_iterations = settings.max_iterations;
  po.observer = [&](const IterationState& s) {
    progress.say(fmt::format("iteration {}: max residual {:.3e}, rms {:.3e}", s.record.iteration,
                             s.record.max_residual, s.record.rms_residual));
    if (settings.verbose)
      run.log.push_back(fmt::format("{:>9} {:>14.6e} {:>14.6e}", s.record.iteration, s.record.max_residual,
                                    s.record.rms_residual));
  };
  run.tolerance = po.tolerance;
  run.result = progressive_interpolation(limit, targets, moving, po);
  if (run.moving < run.vertices) run.fixed_note = theorem_two_note(limit, targets, moving, run.result);
  return run;
}

void warn_if_stopped(const IterationRun& run, const std::string& written) {
  if (run.result.converged) return;
  fmt::print(stderr, "subdiv: warning: the residual {:.3e} is above the tolerance {:.3e} after {} iterations "
             "(--max-iter); {} the last iterate\n", run.result.history.back().max_residual, run.tolerance,
             run.result.iterations, written);
}

void print_iterations(const IterationRun& run, const std::string& what, bool verbose) {
  const IterationRecord& first = run.result.history.front();
  const IterationRecord& last = run.result.history.back();
  fmt::print("moving: {} of {} {} ({}); tolerance {:.3e}\n", run.moving, run.vertices, what,
             run.moving == run.vertices ? "global" : "local", run.tolerance);
  if (verbose) {
    fmt::print("{:>9} {:>14} {:>14}\n", "iteration", "max residual", "rms residual");
    for (const auto& line : run.log) fmt::print("{}\n", line);
  }
  fmt::print("{} in {} iterations: max residual {:.3e}, rms {:.3e} (initially {:.3e}, {:.3e})\n",
             run.result.converged ? "converged" : "stopped", run.result.iterations, last.max_residual,
             last.rms_residual, first.max_residual, first.rms_residual);
  if (!run.fixed_note.empty()) fmt::print("{}\n", run.fixed_note);
}

}  // namespace subdiv::cli
